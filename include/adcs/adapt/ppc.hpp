#pragma once
// Prescribed-performance control (PPC) machinery for K independent channels, seed 002 eqs.
// (5)-(11), spec §B.3 steps 2-7 (repaired readings B.4 #5-#8):
//
//   ρ(t) = (ρ0 − ρ∞) e^{−kt} + ρ∞                         performance function        eq. (5)
//   z = e/ρ must stay in (−δ, 1) if e(0) ≥ 0 (branch +), in (−1, δ) if e(0) < 0 (branch −)  eq. (6)
//   e = ρ S(ε):  S₊(ε) = (e^ε − δ e^−ε)/(e^ε + e^−ε),  S₋(ε) = (δ e^ε − e^−ε)/(e^ε + e^−ε)   eq. (7)
//   ε = S⁻¹(z):  ε₊ = ½ ln((z + δ)/(1 − z)),  ε₋ = ½ ln((z + 1)/(δ − z))                 eq. (9)
//   r = ε_z/ρ,  q = ė − e ρ̇/ρ,  ε̇ = r q,  ṙ = ε_zz ż/ρ − ε_z ρ̇/ρ²,  ż = (ė − z ρ̇)/ρ
//
// A controller that wants ṡ for s = λε + ε̇ also needs q̇ = ë + q_dot_offset with
// q_dot_offset = −(ė ρ̇ ρ + e ρ̈ ρ − e ρ̇²)/ρ² (= −d/dt(e ρ̇/ρ)), returned here (eq. (11)).
//
// At a funnel edge ε is ±∞. transform() never takes the logarithm there: it returns
// out_of_range with the output untouched, or — in the optional robust mode — clamps z into the
// interval with a 1e-12 margin, computes a finite result and returns constraint_violated.
#include <array>
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! ρ(t) = (ρ0 − ρ∞) e^{−kt} + ρ∞ with ρ0 > ρ∞ > 0, k > 0 (units of the error; k in 1/s).
struct PerformanceFunction {
  double rho0 = 1.0;     //!< [error units] ρ(0)
  double rho_inf = 0.1;  //!< [error units] lim ρ(t)
  double k = 1.0;        //!< [1/s] decay rate
};

struct PerformanceSample {
  double rho = 0.0, rho_dot = 0.0, rho_ddot = 0.0;  //!< ρ, ρ̇, ρ̈ at one time
};

inline bool valid(const PerformanceFunction& f) noexcept {
  return std::isfinite(f.rho0) && std::isfinite(f.rho_inf) && std::isfinite(f.k) &&
         f.rho_inf > 0.0 && f.rho0 > f.rho_inf && f.k > 0.0;
}

//! ρ, ρ̇ = −k(ρ0 − ρ∞)e^{−kt}, ρ̈ = k²(ρ0 − ρ∞)e^{−kt}.   seed 002 eq. (5), spec §B.3 step 2
inline PerformanceSample evaluate(const PerformanceFunction& f, double t) noexcept {
  const double a = (f.rho0 - f.rho_inf) * std::exp(-f.k * t);
  return PerformanceSample{a + f.rho_inf, -f.k * a, f.k * f.k * a};
}

//! Which side of zero the error starts (and, with δ = 0, stays) on.   seed 002 eq. (6)
enum class PpcBranch : signed char { positive = 1, negative = -1 };

//! Forward map z = S(ε) of eq. (7) (for tests and plots).
inline double ppc_S(double eps, PpcBranch b, double delta) noexcept {
  const double ep = std::exp(eps), em = std::exp(-eps);
  return b == PpcBranch::positive ? (ep - delta * em) / (ep + em) : (delta * ep - em) / (ep + em);
}

//! Signed distance of z to the nearer edge of the open interval of eq. (6): > 0 inside.
inline double ppc_margin(double z, PpcBranch b, double delta) noexcept {
  return b == PpcBranch::positive ? std::fmin(z + delta, 1.0 - z) : std::fmin(z + 1.0, delta - z);
}

struct PpcInverse {
  double eps = 0.0;     //!< [-] ε = S⁻¹(z)                    eq. (9)
  double eps_z = 0.0;   //!< [-] ∂ε/∂z (> 0)                   spec §B.3 step 5
  double eps_zz = 0.0;  //!< [-] ∂²ε/∂z²
};

//! ε, ε_z, ε_zz for z strictly inside the interval. out_of_range (out untouched) otherwise,
//! non_finite_input for NaN z.   seed 002 eq. (9), spec §B.3 steps 4-5
inline Status ppc_S_inverse(double z, PpcBranch b, double delta, PpcInverse& out) noexcept {
  if (!std::isfinite(z)) return Status::non_finite_input;
  if (!(ppc_margin(z, b, delta) > 0.0)) return Status::out_of_range;
  // a = distance to the lower edge, c = distance to the upper edge (both > 0 here).
  const double a = b == PpcBranch::positive ? z + delta : z + 1.0;
  const double c = b == PpcBranch::positive ? 1.0 - z : delta - z;
  const double eps = 0.5 * std::log(a / c);
  const double eps_z = 0.5 * (1.0 / a + 1.0 / c);
  const double eps_zz = 0.5 * (1.0 / (c * c) - 1.0 / (a * a));
  // Within ~1e-154 of an edge the squares overflow: that is the edge, numerically.
  if (!std::isfinite(eps) || !std::isfinite(eps_z) || !std::isfinite(eps_zz)) return Status::out_of_range;
  out.eps = eps;
  out.eps_z = eps_z;
  out.eps_zz = eps_zz;
  return Status::ok;
}

template <int K>
struct PpcParams {
  std::array<PerformanceFunction, K> rho{};  //!< one performance function per channel
  Vec<K> delta = Vec<K>::Zero();             //!< [-] overshoot parameters δ_i ∈ [0, 1]
  bool robust_clamp = false;  //!< clamp z at a funnel edge (flagged) instead of refusing
};

//! Everything a PPC law needs from one error sample (spec §B.3 steps 2-7), per channel.
template <int K>
struct PpcSample {
  Vec<K> rho = Vec<K>::Zero(), rho_dot = Vec<K>::Zero(), rho_ddot = Vec<K>::Zero();
  Vec<K> z = Vec<K>::Zero();             //!< [-] e/ρ
  Vec<K> eps = Vec<K>::Zero();           //!< [-] transformed error ε
  Vec<K> eps_dot = Vec<K>::Zero();       //!< [1/s] ε̇ = r q
  Vec<K> r = Vec<K>::Zero();             //!< [1/error] ε_z/ρ
  Vec<K> r_dot = Vec<K>::Zero();         //!< [1/(error s)] ṙ
  Vec<K> q = Vec<K>::Zero();             //!< [error/s] ė − e ρ̇/ρ
  Vec<K> q_dot_offset = Vec<K>::Zero();  //!< [error/s²] q̇ − ë = −(ėρ̇ρ + eρ̈ρ − eρ̇²)/ρ²
  double margin_min = 0.0;               //!< [-] min over channels of ppc_margin(z) (before any clamp)
};

//! Error transform with the branches fixed from e(0) (spec §B.3 "fixed at t = 0").
template <int K>
class PrescribedPerformance {
 public:
  using Params = PpcParams<K>;
  using Sample = PpcSample<K>;

  explicit PrescribedPerformance(const Params& p) noexcept : p_(p) {
    bool ok = true;
    for (int i = 0; i < K; ++i)
      ok = ok && valid(p_.rho[i]) && std::isfinite(p_.delta(i)) && p_.delta(i) >= 0.0 && p_.delta(i) <= 1.0;
    status_ = ok ? Status::ok : Status::invalid_parameter;
    branch_.fill(PpcBranch::positive);
  }

  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  PpcBranch branch(int i) const noexcept { return branch_[i]; }

  //! Fixes b_i = + if e_i(0) ≥ 0, else − (spec §B.3), and checks that e(0) is inside the
  //! funnel: out_of_range (branches still set) if some |z_i(0)| is on or beyond its edge.
  [[nodiscard]] Status init(const Vec<K>& e0) noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(e0)) return Status::non_finite_input;
    bool inside = true;
    for (int i = 0; i < K; ++i) {
      branch_[i] = e0(i) >= 0.0 ? PpcBranch::positive : PpcBranch::negative;
      inside = inside && ppc_margin(e0(i) / p_.rho[i].rho0, branch_[i], p_.delta(i)) > 0.0;
    }
    return inside ? Status::ok : Status::out_of_range;
  }

  //! Steps 2-7 at time t [s] for error e and its rate ė. ok; constraint_violated (robust mode:
  //! some z clamped, result finite); out_of_range (some z outside, `out` untouched);
  //! non_finite_input (`out` untouched).
  [[nodiscard]] Status transform(double t, const Vec<K>& e, const Vec<K>& e_dot, Sample& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(t) || !all_finite(e) || !all_finite(e_dot)) return Status::non_finite_input;
    Sample s;
    bool clamped = false;
    s.margin_min = INFINITY;
    for (int i = 0; i < K; ++i) {
      const PerformanceSample f = evaluate(p_.rho[i], t);                     // step 2
      const double rho = f.rho, rd = f.rho_dot, rdd = f.rho_ddot;
      double z = e(i) / rho;                                                   // step 3
      const double margin = ppc_margin(z, branch_[i], p_.delta(i));
      s.margin_min = std::fmin(s.margin_min, margin);
      if (!(margin > 0.0)) {
        if (!p_.robust_clamp) return Status::out_of_range;
        const double lo = branch_[i] == PpcBranch::positive ? -p_.delta(i) : -1.0;
        const double hi = branch_[i] == PpcBranch::positive ? 1.0 : p_.delta(i);
        z = std::fmin(std::fmax(z, lo + kClampMargin), hi - kClampMargin);
        clamped = true;
      }
      PpcInverse inv;
      if (ppc_S_inverse(z, branch_[i], p_.delta(i), inv) != Status::ok) return Status::out_of_range;
      const double z_dot = (e_dot(i) - z * rd) / rho;                           // step 6
      s.rho(i) = rho;
      s.rho_dot(i) = rd;
      s.rho_ddot(i) = rdd;
      s.z(i) = z;
      s.eps(i) = inv.eps;                                                       // step 4
      s.r(i) = inv.eps_z / rho;
      s.r_dot(i) = inv.eps_zz * z_dot / rho - inv.eps_z * rd / (rho * rho);
      s.q(i) = e_dot(i) - e(i) * rd / rho;                                      // step 7
      s.eps_dot(i) = s.r(i) * s.q(i);
      s.q_dot_offset(i) = -(e_dot(i) * rd * rho + e(i) * rdd * rho - e(i) * rd * rd) / (rho * rho);  // eq. (11)
    }
    // Absurd errors (|e| ~ 1e300) can still overflow the products above: refuse, never emit Inf.
    if (!all_finite(s.eps_dot) || !all_finite(s.r_dot) || !all_finite(s.q_dot_offset) || !all_finite(s.q))
      return Status::out_of_range;
    out = s;
    return clamped ? Status::constraint_violated : Status::ok;
  }

  //! Distance kept from a funnel edge by the robust clamp (spec §B.3 step 3).
  static constexpr double kClampMargin = 1e-12;

 private:
  Params p_;
  std::array<PpcBranch, K> branch_{};
  Status status_ = Status::ok;
};

}  // namespace adcs
