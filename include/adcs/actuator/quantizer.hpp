#pragma once
// Composite logarithmic/uniform input quantizer with transmission counting: seed 003 §1.3
// seed 003 eqs. (12)-(16), spec §A.3 (structure [P]; forms [R] Fu & Xie 2005, Zhou, Wen & Yang 2014).
// Per channel (parameters ρ ∈ (0,1), u_min > 0, u_s ≥ u_min, σ > 0):
//
//   u_j = ρ^{1−j} u_min  (j = 1..n),   δ = (1−ρ)/(1+ρ)
//   Q_log(u) = sign(u) u_j   if u_j/(1+δ) < |u| ≤ u_j/(1−δ)        (hysteresis-free)
//            = 0             if |u| ≤ u_min/(1+δ)                   (dead zone)
//   Q_uni(u) = σ floor(u/σ + 1e-12)                        (floor type [A], error ∈ (−σ, 0])
//   Q(u)     = Q_log(u) if |u| ≤ u_s, else Q_uni(u)
//   |Q(u) − u| ≤ ϖ = max{σ, δ u_s + u_min}                          for every finite u [P]
//
// Interval boundaries are evaluated in one canonical floating-point form, b_j = u_j/(1+δ) (the
// upper end of level j is b_{j+1}, equal to u_j/(1−δ) in exact arithmetic), so the levels tile
// (0, ∞) in floating point too: no input falls in a gap or in two intervals. The spec's index
// formula gives the level in O(1); a bounded snap against the b_j then makes the answer agree
// with the interval definition even where ln() rounds across an integer.
//
// Per control tick (spec §A.3 [A]): u → sat → Q → clip → actuator, see saturate_then_quantize.
// A channel transmits when its quantized value changes; the first tick transmits every channel:
// N_tx = M + Σ_k Σ_i 1[u_c,i(k) ≠ u_c,i(k−1)].
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "adcs/actuator/saturation.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Largest number n of logarithmic levels per channel. [A] not in the paper: 32 magnitudes
//! (5 bits + sign) covers u_s/u_min up to 2^31 at ρ = 0.5 and ≈1000 at ρ = 0.8; seed 003 needs
//! n = 5 (torque) and 12 (force). Bounds the level table and every search loop.
inline constexpr int kMaxQuantizerLevels = 32;

//! One quantizer channel, in the channel's unit (N m for torques, N for forces). The defaults
//! are the seed 003 torque row of spec §A.8 "Proposed Table 1" [A]. Scalar S (issue 19): every
//! quantizer type takes it last, double by default (`QuantizerChannelParams` is the double one).
template <class S = double>
struct QuantizerChannelParamsT {
  S rho = S(0.3);     //!< [-] log density ρ ∈ (0,1); smaller = coarser, fewer transmissions
  S u_min = S(1e-3);  //!< [N m | N] smallest level u_1 (> 0); |u| ≤ u_min/(1+δ) maps to 0
  S u_s = S(0.2);     //!< [N m | N] log/uniform switch (≥ u_min): log for |u| ≤ u_s
  S sigma = S(0.1);   //!< [N m | N] uniform step σ (> 0) above u_s
  //! The same channel in another scalar (each value rounded once; validated by the channel).
  template <class T>
  QuantizerChannelParamsT<T> cast() const noexcept {
    return QuantizerChannelParamsT<T>{narrow_scalar<T>(rho), narrow_scalar<T>(u_min), narrow_scalar<T>(u_s),
                                      narrow_scalar<T>(sigma)};
  }
};
using QuantizerChannelParams = QuantizerChannelParamsT<double>;

//! Sector bound δ = (1−ρ)/(1+ρ) of the log quantizer (spec §A.3).
template <class S>
inline S quantizer_delta(const QuantizerChannelParamsT<S>& p) noexcept {
  return (S(1) - p.rho) / (S(1) + p.rho);
}

//! Level u_j = ρ^{1−j} u_min, j ≥ 1 (spec §A.3). The one formula every level comes from.
template <class S>
inline S quantizer_level(const QuantizerChannelParamsT<S>& p, int j) noexcept {
  return p.u_min * std::pow(p.rho, static_cast<S>(1 - j));
}

//! Quantization-error bound ϖ = max{σ, δ u_s + u_min} (seed 003 [P], spec §A.3). The compensation
//! amplitude of the controller must satisfy ζ ≥ ϖ (spec §A.5).   seed 003 eq. (16)
template <class S>
inline S quantizer_error_bound(const QuantizerChannelParamsT<S>& p) noexcept {
  return std::max(p.sigma, quantizer_delta(p) * p.u_s + p.u_min);
}

//! Number of levels n = ceil(ln(u_s(1+δ)/u_min)/ln(1/ρ)) (spec §A.3): the smallest n ≥ 1 with
//! u_s ≤ u_{n+1}/(1+δ), i.e. just enough levels to cover |u| ≤ u_s. Returns
//! kMaxQuantizerLevels + 1 when more are needed. Requires ρ ∈ (0,1), 0 < u_min ≤ u_s (finite).
template <class S>
inline int quantizer_level_count(const QuantizerChannelParamsT<S>& p) noexcept {
  const S one_plus_delta = S(1) + quantizer_delta(p);
  const S nd = std::ceil(std::log(p.u_s * one_plus_delta / p.u_min) / -std::log(p.rho));
  if (!(nd <= S(kMaxQuantizerLevels))) return kMaxQuantizerLevels + 1;  // before the int cast
  int n = std::max(1, static_cast<int>(nd));
  // ln() may round across an integer when u_s sits on a boundary: snap to the b_j definition.
  // Each loop moves n at most kMaxQuantizerLevels times (in practice at most once).
  while (n > 1 && p.u_s <= quantizer_level(p, n) / one_plus_delta) --n;
  while (n <= kMaxQuantizerLevels && p.u_s > quantizer_level(p, n + 1) / one_plus_delta) ++n;
  return n;
}

//! True when the channel defines a quantizer: finite, ρ ∈ (0,1), 0 < u_min ≤ u_s, σ > 0 and
//! n ≤ kMaxQuantizerLevels.
template <class S>
inline bool valid(const QuantizerChannelParamsT<S>& p) noexcept {
  const bool finite = std::isfinite(p.rho) && std::isfinite(p.u_min) && std::isfinite(p.u_s) &&
                      std::isfinite(p.sigma);
  return finite && p.rho > S(0) && p.rho < S(1) && p.u_min > S(0) && p.u_s >= p.u_min &&
         p.sigma > S(0) && quantizer_level_count(p) <= kMaxQuantizerLevels;
}

namespace detail {
//! Q_uni's floor offset (a few rounding units of u/σ, so that an exact multiple of σ stays on its
//! own level) and the |u/σ| beyond which the grid is at most 4 ulp(u) wide (u itself is then the
//! best level). Double: 1e-12 and 2^50 (as before issue 19). Float: 1e-4 (ε_f|u/σ| ≈ 6e-5 at
//! |u/σ| = 1e3) and 2^21 (2^(p−3), p = 24 bits, as 2^50 is for p = 53).
template <class S>
inline constexpr S kUniformFloorOffset = std::is_same_v<S, float> ? S(1e-4) : S(1e-12);
template <class S>
inline constexpr S kUniformGridLimit = std::is_same_v<S, float> ? S(0x1p21) : S(0x1p50);
}  // namespace detail

//! One channel with its derived constants (δ, n, the level table, ln terms) computed once.
//! Invariant when status() == ok: |quantize(u) − u| ≤ error_bound() for every finite u, and
//! quantize() is odd for |u| ≤ u_s. Non-finite u passes through unchanged (callers check
//! first); so does every u when status() != ok (n = 0), so a rejected channel never invents a
//! command.
template <class S = double>
class QuantizerChannelT {
 public:
  using Params = QuantizerChannelParamsT<S>;
  //! The seed 003 torque channel (QuantizerChannelParams defaults).
  QuantizerChannelT() noexcept : QuantizerChannelT(Params{}) {}
  explicit QuantizerChannelT(const Params& p) noexcept : p_(p) {
    if (!ADCS_CHECK(valid(p_), "QuantizerChannel: need rho in (0,1), 0 < u_min <= u_s, sigma > 0, "
                               "n <= kMaxQuantizerLevels")) {
      status_ = Status::invalid_parameter;
      return;
    }
    delta_ = quantizer_delta(p_);
    one_plus_delta_ = S(1) + delta_;
    n_ = quantizer_level_count(p_);
    for (int j = 1; j <= n_; ++j) levels_[static_cast<std::size_t>(j - 1)] = quantizer_level(p_, j);
    log_offset_ = std::log(one_plus_delta_ / p_.u_min);  // j = ceil((ln|u| + this) / ln(1/ρ))
    inv_log_inv_rho_ = S(-1) / std::log(p_.rho);
    bound_ = quantizer_error_bound(p_);
  }

  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  S delta() const noexcept { return delta_; }        //!< [-] δ
  int level_count() const noexcept { return n_; }    //!< [-] n
  S error_bound() const noexcept { return bound_; }  //!< [N m | N] ϖ
  //! u_j for j = 1..n (the table the quantizer uses); 0 outside that range.
  S level(int j) const noexcept {
    return (j >= 1 && j <= n_) ? levels_[static_cast<std::size_t>(j - 1)] : S(0);
  }
  //! Canonical boundary b_j = u_j/(1+δ) for j = 1..n: level j is (b_j, b_{j+1}], 0 is [0, b_1].
  S lower_boundary(int j) const noexcept { return level(j) / one_plus_delta_; }

  //! Q_log(u) for |u| ≤ u_s (above u_s it stays on the top level u_n; the composite switches
  //! to Q_uni there). Exactly odd: works on |u| and restores the sign.   seed 003 eq. (13)
  S quantize_log(S u) const noexcept {
    if (n_ == 0 || std::isnan(u)) return u;
    const S a = std::fabs(u);
    if (a <= lower_boundary(1)) return S(0);  // dead zone |u| ≤ u_min/(1+δ)
    // spec §A.3 index formula, clamped in floating point before the cast (no overflow UB)
    const S jd = std::ceil((std::log(a) + log_offset_) * inv_log_inv_rho_);
    int j = jd <= S(1) ? 1 : (jd >= S(n_) ? n_ : static_cast<int>(jd));
    // Snap to (b_j, b_{j+1}]: fixes ln() rounding across an integer at a boundary. Bounded by n.
    while (j < n_ && a > lower_boundary(j + 1)) ++j;
    while (j > 1 && !(a > lower_boundary(j))) --j;
    return std::copysign(levels_[static_cast<std::size_t>(j - 1)], u);
  }

  //! Q_uni(u) = σ floor(u/σ + c) (spec §A.3 [A], c = 1e-12 in double,
  //! detail::kUniformFloorOffset); c keeps exact multiples of σ on their own level. Error ∈
  //! (−σ, cσ].   seed 003 eq. (14)
  S quantize_uniform(S u) const noexcept {
    if (n_ == 0) return u;
    const S x = u / p_.sigma;
    // For |x| ≥ 2^50 (float: 2^21) the grid is at most 4 ulp(u) wide: u itself is the best
    // representable level (error 0 ≤ σ). ±inf and NaN also pass through here.
    if (!(std::fabs(x) < detail::kUniformGridLimit<S>)) return u;
    const S m = std::floor(x + detail::kUniformFloorOffset<S>);
    S q = p_.sigma * m;
    // Rounding of u/σ and σ·m can leave u − q a few ulp(u) above σ when |u| ≫ σ (never within
    // the saturated range); step one level up so that the bound σ holds as computed.
    if (u - q > p_.sigma) q = p_.sigma * (m + S(1));
    return q;
  }

  //! Q_i(u) (spec §A.3): log for |u| ≤ u_s, uniform above.   seed 003 eq. (12)
  S quantize(S u) const noexcept {
    return std::fabs(u) <= p_.u_s ? quantize_log(u) : quantize_uniform(u);
  }

 private:
  Params p_;
  std::array<S, kMaxQuantizerLevels> levels_{};
  S delta_ = S(0);
  S one_plus_delta_ = S(1);
  S log_offset_ = S(0);
  S inv_log_inv_rho_ = S(0);
  S bound_ = S(0);
  int n_ = 0;
  Status status_ = Status::ok;
};
using QuantizerChannel = QuantizerChannelT<double>;

//! Parameters of an M-channel quantizer, channel i in the unit of input i. Default: every
//! channel the seed 003 torque row (QuantizerChannelParams); seed003_quantizer_params()
//! (src/scenarios/seed003_data.hpp) gives the paper's torque and force channels.
template <int M, class S = double>
struct CompositeQuantizerParams {
  std::array<QuantizerChannelParamsT<S>, M> channel{};
  //! The same channels in another scalar.
  template <class T>
  CompositeQuantizerParams<M, T> cast() const noexcept {
    CompositeQuantizerParams<M, T> q;
    for (std::size_t i = 0; i < static_cast<std::size_t>(M); ++i) q.channel[i] = channel[i].template cast<T>();
    return q;
  }
};

//! M channels quantized independently, with the transmission count of spec §A.3. A
//! transmission is a change of a channel's quantized value from the previous apply(); the first
//! apply() after construction or reset() transmits every channel. reset() clears the counters
//! and the remembered output.
template <int M, class S = double>
class CompositeQuantizer {
  static_assert(M >= 1 && M <= 32, "one bit per channel in the transmission mask");

 public:
  using Params = CompositeQuantizerParams<M, S>;

  explicit CompositeQuantizer(const Params& p) noexcept {
    bool ok = true;
    for (std::size_t i = 0; i < static_cast<std::size_t>(M); ++i) {
      channels_[i] = QuantizerChannelT<S>(p.channel[i]);
      ok = ok && channels_[i].status() == Status::ok;
    }
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }

  Status status() const noexcept { return status_; }
  const QuantizerChannelT<S>& channel(int i) const noexcept {
    return channels_[static_cast<std::size_t>(i)];
  }

  void reset() noexcept {
    last_.setZero();
    have_last_ = false;
    tx_total_ = 0;
    tx_channel_.fill(0);
  }

  //! u_q = Q(u) per channel; counts transmissions. `tx_mask` (optional) gets bit i set when
  //! channel i transmits this tick. non_finite_input / invalid_parameter: u_q, tx_mask and all
  //! counters untouched.
  [[nodiscard]] Status apply(const Vec<M, S>& u, Vec<M, S>& u_q,
                             std::uint32_t* tx_mask = nullptr) noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(u)) return Status::non_finite_input;
    std::uint32_t mask = 0;
    for (int i = 0; i < M; ++i) {
      const std::size_t ii = static_cast<std::size_t>(i);
      const S q = channels_[ii].quantize(u(i));
      // Exact comparison on purpose: equal levels are bit-identical (one table, one formula).
      if (!have_last_ || q != last_(i)) {
        mask |= std::uint32_t{1} << i;
        ++tx_channel_[ii];
        ++tx_total_;
      }
      last_(i) = q;
    }
    have_last_ = true;
    u_q = last_;
    if (tx_mask) *tx_mask = mask;
    return Status::ok;
  }

  //! Total transmissions N_tx since construction or reset() (64 bit: 8 Hz × 6 channels would
  //! wrap 32 bits in under 3 years).
  std::uint64_t transmissions() const noexcept { return tx_total_; }
  //! Transmissions per channel.
  const std::array<std::uint64_t, M>& channel_transmissions() const noexcept { return tx_channel_; }
  //! The output of the last successful apply() (zero before the first).
  const Vec<M, S>& last_output() const noexcept { return last_; }

 private:
  std::array<QuantizerChannelT<S>, M> channels_;
  Vec<M, S> last_ = Vec<M, S>::Zero();
  std::array<std::uint64_t, M> tx_channel_{};
  std::uint64_t tx_total_ = 0;
  bool have_last_ = false;
  Status status_ = Status::ok;
};

//! One control tick of spec §A.3 [A]: u_c = clip(Q(sat(u))) with per-channel limits (the
//! saturate_each encoding: a limit that is not > 0 means none). Saturating BEFORE quantizing
//! keeps a saturated command on one level, so it is not re-transmitted (−31% transmissions in
//! the spec's prototype, §C.3). The final clip is a no-op when every limit is an exact level
//! (seed 003: 0.5 = 5σ, 5 = 5σ); otherwise it maps the one level beyond −limit back onto
//! −limit, a one-to-one change, so counting Q's changes counts u_c's. Returns saturated when
//! sat clipped a channel, non_finite_input / invalid_parameter with u_c and counters untouched.
template <int M, class S = double>
[[nodiscard]] Status saturate_then_quantize(const Vec<M, S>& u, const identity_t<Vec<M, S>>& limit,
                                            CompositeQuantizer<M, S>& q, Vec<M, S>& u_c,
                                            std::uint32_t* tx_mask = nullptr) noexcept {
  if (!all_finite(u)) return Status::non_finite_input;
  Vec<M, S> v = u;
  const int clipped = saturate_each<M, S>(v, limit);
  Vec<M, S> w;
  const Status s = q.apply(v, w, tx_mask);
  if (s != Status::ok) return s;
  saturate_each<M, S>(w, limit);
  u_c = w;
  return clipped > 0 ? Status::saturated : Status::ok;
}

template <int M, class S = double>
struct SaturatedQuantizerParams {
  CompositeQuantizerParams<M, S> quantizer{};        //!< the channels' levels
  Vec<M, S> limit = Vec<M, S>::Constant(unset_v<S>);  //!< [channel units] actuator limits, > 0 (+inf: none); no default
  //! The same parameters in another scalar (each value rounded once; validated by the stage).
  template <class T>
  SaturatedQuantizerParams<M, T> cast() const noexcept {
    return SaturatedQuantizerParams<M, T>{quantizer.template cast<T>(), scalar_cast<T>(limit)};
  }
};

struct SaturatedQuantizerDiagnostics {
  std::uint32_t tx_mask = 0;  //!< bit i: channel i transmitted this tick
};

//! saturate_then_quantize as a component: u → sat → Q → clip, with its transmission counters.
template <int M, class S = double>
class SaturatedQuantizer {
 public:
  using Params = SaturatedQuantizerParams<M, S>;
  using Input = Vec<M, S>;
  using Output = Vec<M, S>;
  using Diagnostics = SaturatedQuantizerDiagnostics;

  explicit SaturatedQuantizer(const Params& p) noexcept : p_(p), q_(p.quantizer) {
    const bool ok = q_.status() == Status::ok && !p_.limit.hasNaN() && (p_.limit.array() > S(0)).all();
    status_ = ok ? Status::ok : Status::invalid_parameter;
    reset();
  }
  //! ok, or invalid_parameter: a channel refused (QuantizerChannel) or a limit NaN or not > 0.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return S(0); }  //!< runs whenever its law runs (core/component.hpp)
  void reset() noexcept { q_.reset(); }
  const CompositeQuantizer<M, S>& quantizer() const noexcept { return q_; }

  //! ok or saturated (sat clipped a channel); non_finite_input / invalid_parameter: out = 0 (the
  //! actuators idle), counters untouched.
  [[nodiscard]] Status step(const Input& u, Output& out, Diagnostics* diag = nullptr) noexcept {
    if (status_ != Status::ok) {
      out.setZero();
      return status_;
    }
    std::uint32_t mask = 0;
    const Status s = saturate_then_quantize<M, S>(u, p_.limit, q_, out, &mask);
    if (!usable(s)) {
      out.setZero();
      return s;
    }
    if (diag) diag->tx_mask = mask;
    return s;
  }

 private:
  Params p_;
  CompositeQuantizer<M, S> q_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(SaturatedQuantizer<6>);
ADCS_ASSERT_COMPONENT(SaturatedQuantizer<6, float>);

}  // namespace adcs
