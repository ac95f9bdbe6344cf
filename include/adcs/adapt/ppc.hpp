#pragma once
// Prescribed-performance control (PPC) machinery for K independent channels, seed 002
// eqs. (5)-(11), spec §B.3 steps 2-7 (repaired readings B.4 #5-#8):
//
//   ρ(t) = (ρ0 − ρ∞) e^{−kt} + ρ∞                         performance function        seed 002 eq. (5)
//   z = e/ρ must stay in (−δ, 1) if e(0) ≥ 0 (branch +), in (−1, δ) if e(0) < 0 (branch −)  seed 002 eq. (6)
//   e = ρ S(ε):  S₊(ε) = (e^ε − δ e^−ε)/(e^ε + e^−ε),  S₋(ε) = (δ e^ε − e^−ε)/(e^ε + e^−ε)   seed 002 eq. (7)
//   ε = S⁻¹(z):  ε₊ = ½ ln((z + δ)/(1 − z)),  ε₋ = ½ ln((z + 1)/(δ − z))                 seed 002 eq. (9)
//   r = ε_z/ρ,  q = ė − e ρ̇/ρ,  ε̇ = r q,  ṙ = ε_zz ż/ρ − ε_z ρ̇/ρ²,  ż = (ė − z ρ̇)/ρ
//
// A controller that wants ṡ for s = λε + ε̇ also needs q̇ = ë + q_dot_offset with
// q_dot_offset = −(ė ρ̇ ρ + e ρ̈ ρ − e ρ̇²)/ρ² (= −d/dt(e ρ̇/ρ)), returned here (seed 002 eq. (11)).
//
// At a funnel edge ε is ±∞. transform() never takes the logarithm there: it returns
// out_of_range with the output untouched, or — in the optional robust mode — clamps z into the
// interval with a 1e-12 margin, computes a finite result and returns constraint_violated.
//
// Funnel recovery (ours, issue 15; the paper's law has none): once the error has left its funnel
// the paper's law is undefined for good, since ρ(t) only shrinks. reopen() gives each violated
// channel a new performance function starting at the current time and error (see there), so a
// law can continue after a disturbance it was not designed for; the law counts and reports it.
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! ρ(t) = (ρ0 − ρ∞) e^{−kt} + ρ∞ with ρ0 > ρ∞ > 0, k > 0 (units of the error; k in 1/s).
template <class S = double>
struct PerformanceFunctionT {
  S rho0 = S(1.0);     //!< [error units] ρ(0)
  S rho_inf = S(0.1);  //!< [error units] lim ρ(t)
  S k = S(1.0);        //!< [1/s] decay rate
  template <class T>
  PerformanceFunctionT<T> cast() const noexcept {
    return {narrow_scalar<T>(rho0), narrow_scalar<T>(rho_inf), narrow_scalar<T>(k)};
  }
};
using PerformanceFunction = PerformanceFunctionT<double>;

template <class S = double>
struct PerformanceSampleT {
  S rho = S(0), rho_dot = S(0), rho_ddot = S(0);  //!< ρ, ρ̇, ρ̈ at one time
};
using PerformanceSample = PerformanceSampleT<double>;

template <class S>
inline bool valid(const PerformanceFunctionT<S>& f) noexcept {
  return std::isfinite(f.rho0) && std::isfinite(f.rho_inf) && std::isfinite(f.k) &&
         f.rho_inf > S(0) && f.rho0 > f.rho_inf && f.k > S(0);
}

//! ρ, ρ̇ = −k(ρ0 − ρ∞)e^{−kt}, ρ̈ = k²(ρ0 − ρ∞)e^{−kt}.   seed 002 eq. (5), spec §B.3 step 2
template <class S>
inline PerformanceSampleT<S> evaluate(const PerformanceFunctionT<S>& f, identity_t<S> t) noexcept {
  const S a = (f.rho0 - f.rho_inf) * std::exp(-f.k * t);
  return PerformanceSampleT<S>{a + f.rho_inf, -f.k * a, f.k * f.k * a};
}

//! Which side of zero the error starts (and, with δ = 0, stays) on.   seed 002 eq. (6)
enum class PpcBranch : signed char { positive = 1, negative = -1 };

//! Forward map z = S(ε) of seed 002 eq. (7) (for tests and plots).
template <class S>
inline S ppc_S(S eps, PpcBranch b, identity_t<S> delta) noexcept {
  const S ep = std::exp(eps), em = std::exp(-eps);
  return b == PpcBranch::positive ? (ep - delta * em) / (ep + em) : (delta * ep - em) / (ep + em);
}

//! Signed distance of z to the nearer edge of the open interval of seed 002 eq. (6): > 0 inside.
template <class S>
inline S ppc_margin(S z, PpcBranch b, identity_t<S> delta) noexcept {
  return b == PpcBranch::positive ? std::fmin(z + delta, S(1) - z) : std::fmin(z + S(1), delta - z);
}

template <class S = double>
struct PpcInverseT {
  S eps = S(0);     //!< [-] ε = S⁻¹(z)                    seed 002 eq. (9)
  S eps_z = S(0);   //!< [-] ∂ε/∂z (> 0)                   spec §B.3 step 5
  S eps_zz = S(0);  //!< [-] ∂²ε/∂z²
};
using PpcInverse = PpcInverseT<double>;

//! ε, ε_z, ε_zz for z strictly inside the interval. out_of_range (out untouched) otherwise,
//! non_finite_input for NaN z.   seed 002 eq. (9), spec §B.3 steps 4-5
template <class S>
inline Status ppc_S_inverse(S z, PpcBranch b, identity_t<S> delta, PpcInverseT<S>& out) noexcept {
  if (!std::isfinite(z)) return Status::non_finite_input;
  if (!(ppc_margin(z, b, delta) > S(0))) return Status::out_of_range;
  // a = distance to the lower edge, c = distance to the upper edge (both > 0 here).
  const S a = b == PpcBranch::positive ? z + delta : z + S(1);
  const S c = b == PpcBranch::positive ? S(1) - z : delta - z;
  const S eps = S(0.5) * std::log(a / c);
  const S eps_z = S(0.5) * (S(1) / a + S(1) / c);
  const S eps_zz = S(0.5) * (S(1) / (c * c) - S(1) / (a * a));
  // Within ~1e-154 (float: ~1e-19) of an edge the squares overflow: that is the edge, numerically.
  if (!std::isfinite(eps) || !std::isfinite(eps_z) || !std::isfinite(eps_zz)) return Status::out_of_range;
  out.eps = eps;
  out.eps_z = eps_z;
  out.eps_zz = eps_zz;
  return Status::ok;
}

//! What a PPC law does when the error has left its funnel (issue 15).
enum class FunnelRecovery : unsigned char {
  none,    //!< seed 002's law: out_of_range on every step until the error is back inside ρ(t)
  reopen,  //!< PrescribedPerformance::reopen() from the current error, counted (the default)
};

template <int K, class S = double>
struct PpcParams {
  std::array<PerformanceFunctionT<S>, K> rho{};  //!< one performance function per channel
  Vec<K, S> delta = Vec<K, S>::Zero();           //!< [-] overshoot parameters δ_i ∈ [0, 1]
  bool robust_clamp = false;  //!< clamp z at a funnel edge (flagged) instead of refusing
  FunnelRecovery recovery = FunnelRecovery::reopen;  //!< after a violation (ours, issue 15)
  //! The same parameters in another scalar (each value rounded once; validated by the user).
  template <class T>
  PpcParams<K, T> cast() const noexcept {
    PpcParams<K, T> q;
    for (int i = 0; i < K; ++i) q.rho[i] = rho[i].template cast<T>();
    q.delta = scalar_cast<T>(delta);
    q.robust_clamp = robust_clamp;
    q.recovery = recovery;
    return q;
  }
};

//! Everything a PPC law needs from one error sample (spec §B.3 steps 2-7), per channel.
template <int K, class S = double>
struct PpcSample {
  Vec<K, S> rho = Vec<K, S>::Zero(), rho_dot = Vec<K, S>::Zero(), rho_ddot = Vec<K, S>::Zero();
  Vec<K, S> z = Vec<K, S>::Zero();             //!< [-] e/ρ
  Vec<K, S> eps = Vec<K, S>::Zero();           //!< [-] transformed error ε
  Vec<K, S> eps_dot = Vec<K, S>::Zero();       //!< [1/s] ε̇ = r q
  Vec<K, S> r = Vec<K, S>::Zero();             //!< [1/error] ε_z/ρ
  Vec<K, S> r_dot = Vec<K, S>::Zero();         //!< [1/(error s)] ṙ
  Vec<K, S> q = Vec<K, S>::Zero();             //!< [error/s] ė − e ρ̇/ρ
  Vec<K, S> q_dot_offset = Vec<K, S>::Zero();  //!< [error/s²] q̇ − ë = −(ėρ̇ρ + eρ̈ρ − eρ̇²)/ρ²
  S margin_min = S(0);                         //!< [-] min over channels of ppc_margin(z) (before any clamp)
};

//! Error transform with the branches fixed from e(0) (spec §B.3 "fixed at t = 0").
template <int K, class S = double>
class PrescribedPerformance {
 public:
  using Params = PpcParams<K, S>;
  using Sample = PpcSample<K, S>;

  explicit PrescribedPerformance(const Params& p) noexcept : p_(p) {
    bool ok = true;
    for (int i = 0; i < K; ++i)
      ok = ok && valid(p_.rho[i]) && std::isfinite(p_.delta(i)) && p_.delta(i) >= S(0) && p_.delta(i) <= S(1);
    ok = ok && (p_.recovery == FunnelRecovery::none || p_.recovery == FunnelRecovery::reopen);
    status_ = ok ? Status::ok : Status::invalid_parameter;
    branch_.fill(PpcBranch::positive);
    restart();
  }

  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  PpcBranch branch(int i) const noexcept { return branch_[i]; }
  //! Channel i's performance function now in force and the time [s] it started (ρ0 and 0 until
  //! the channel is re-opened).
  const PerformanceFunctionT<S>& active(int i) const noexcept { return rho_[i]; }
  S start_time(int i) const noexcept { return t0_[i]; }
  //! ρ_i(t) of the funnel in force (what transform() divides by).
  S rho(int i, S t) const noexcept { return evaluate(rho_[i], t - t0_[i]).rho; }

  //! Fixes b_i = + if e_i(0) ≥ 0, else − (spec §B.3), and checks that e(0) is inside the
  //! funnel: out_of_range (branches still set) if some |z_i(0)| is on or beyond its edge.
  //! Restores the configured performance functions, started at t = 0.
  [[nodiscard]] Status init(const Vec<K, S>& e0) noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(e0)) return Status::non_finite_input;
    restart();
    bool inside = true;
    for (int i = 0; i < K; ++i) {
      branch_[i] = e0(i) >= S(0) ? PpcBranch::positive : PpcBranch::negative;
      inside = inside && ppc_margin(e0(i) / p_.rho[i].rho0, branch_[i], p_.delta(i)) > S(0);
    }
    return inside ? Status::ok : Status::out_of_range;
  }

  //! Steps 2-7 at time t [s] for error e and its rate ė. ok; constraint_violated (robust mode:
  //! some z clamped, result finite); out_of_range (some z outside, `out` untouched);
  //! non_finite_input (`out` untouched).
  [[nodiscard]] Status transform(S t, const Vec<K, S>& e, const Vec<K, S>& e_dot, Sample& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(t) || !all_finite(e) || !all_finite(e_dot)) return Status::non_finite_input;
    Sample s;
    bool clamped = false;
    s.margin_min = std::numeric_limits<S>::infinity();
    for (int i = 0; i < K; ++i) {
      const PerformanceSampleT<S> f = evaluate(rho_[i], t - t0_[i]);           // step 2
      const S rho = f.rho, rd = f.rho_dot, rdd = f.rho_ddot;
      S z = e(i) / rho;                                                         // step 3
      const S margin = ppc_margin(z, branch_[i], p_.delta(i));
      s.margin_min = std::fmin(s.margin_min, margin);
      if (!(margin > S(0))) {
        if (!p_.robust_clamp) return Status::out_of_range;
        const S lo = branch_[i] == PpcBranch::positive ? -p_.delta(i) : S(-1);
        const S hi = branch_[i] == PpcBranch::positive ? S(1) : p_.delta(i);
        z = std::fmin(std::fmax(z, lo + kClampMargin), hi - kClampMargin);
        clamped = true;
      }
      PpcInverseT<S> inv;
      if (ppc_S_inverse(z, branch_[i], p_.delta(i), inv) != Status::ok) return Status::out_of_range;
      const S z_dot = (e_dot(i) - z * rd) / rho;                                // step 6
      s.rho(i) = rho;
      s.rho_dot(i) = rd;
      s.rho_ddot(i) = rdd;
      s.z(i) = z;
      s.eps(i) = inv.eps;                                                       // step 4, seed 002 eq. (8)
      s.r(i) = inv.eps_z / rho;
      s.r_dot(i) = inv.eps_zz * z_dot / rho - inv.eps_z * rd / (rho * rho);
      s.q(i) = e_dot(i) - e(i) * rd / rho;                                      // step 7
      s.eps_dot(i) = s.r(i) * s.q(i);
      s.q_dot_offset(i) = -(e_dot(i) * rd * rho + e(i) * rdd * rho - e(i) * rd * rd) / (rho * rho);  // seed 002 eq. (11)
    }
    // Absurd errors (|e| ~ 1e300) can still overflow the products above: refuse, never emit Inf.
    if (!all_finite(s.eps_dot) || !all_finite(s.r_dot) || !all_finite(s.q_dot_offset) || !all_finite(s.q))
      return Status::out_of_range;
    out = s;
    return clamped ? Status::constraint_violated : Status::ok;
  }

  //! Funnel recovery (ours, issue 15). Every channel i whose z_i = e_i/ρ_i(t) is on or beyond
  //! its edge gets a new performance function starting at t,
  //!   ρ_i'(t') = (ρ0' − ρ∞) e^{−k (t' − t)} + ρ∞,   ρ0' = max(|e_i| / kReopenZ, ρ_i(t), 2 ρ∞),
  //! with ρ∞ and k unchanged, and its branch from the sign of e_i: the error restarts at half the
  //! new funnel's width (|z_i| ≤ kReopenZ, ε_i near 0), the funnel is never narrower than the one it
  //! replaces, and it again converges to ρ∞ at the configured rate. Channels still inside keep
  //! their funnel. `reopened` = number of channels re-opened (0: nothing was violated).
  //! ok; non_finite_input; out_of_range if a re-opened channel is still not strictly inside
  //! (e_i = 0 with δ_i = 0, on no branch's interval) or ρ0' overflows. Nothing changes unless ok.
  [[nodiscard]] Status reopen(S t, const Vec<K, S>& e, int& reopened) noexcept {
    reopened = 0;
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(t) || !all_finite(e)) return Status::non_finite_input;
    std::array<PerformanceFunctionT<S>, K> rho = rho_;
    std::array<S, K> t0 = t0_;
    std::array<PpcBranch, K> branch = branch_;
    int n = 0;
    for (int i = 0; i < K; ++i) {
      const S rho_now = this->rho(i, t);
      if (ppc_margin(e(i) / rho_now, branch[i], p_.delta(i)) > S(0)) continue;
      const PerformanceFunctionT<S>& f = rho_[i];
      const S rho0 = std::fmax(std::fmax(std::fabs(e(i)) / kReopenZ, rho_now), S(2) * f.rho_inf);
      const PerformanceFunctionT<S> g{rho0, f.rho_inf, f.k};
      branch[i] = e(i) >= S(0) ? PpcBranch::positive : PpcBranch::negative;
      if (!valid(g) || !(ppc_margin(e(i) / rho0, branch[i], p_.delta(i)) > S(0))) return Status::out_of_range;
      rho[i] = g;
      t0[i] = t;
      ++n;
    }
    rho_ = rho;
    t0_ = t0;
    branch_ = branch;
    reopened = n;
    return Status::ok;
  }

  //! Distance kept from a funnel edge by the robust clamp (spec §B.3 step 3): 1e-12 in double
  //! (~4500 rounding units of z ~ 1); in float 1e-12 is below the spacing of z near 1 (6e-8),
  //! so the clamp would land on the edge itself: 1e-6 (~8 units, ε = S⁻¹(z) ≈ ±7.3 there
  //! against ±14 in double). Ours (issue 19), not the paper's.
  static constexpr S kClampMargin = std::is_same_v<S, double> ? S(1e-12) : S(1e-6);
  //! |z| of a re-opened channel's error at the re-opening (ours): mid-way to the edge.
  static constexpr S kReopenZ = S(0.5);

 private:
  void restart() noexcept {
    rho_ = p_.rho;
    t0_.fill(S(0));
  }

  Params p_;
  std::array<PerformanceFunctionT<S>, K> rho_{};  //!< in force: p_.rho until a channel is re-opened
  std::array<S, K> t0_{};                         //!< [s] when each channel's function started
  std::array<PpcBranch, K> branch_{};
  Status status_ = Status::ok;
};

}  // namespace adcs
