#pragma once
// Extended-state filter with a saturation-constrained scalar measurement, seed 004 Algorithm 2
// (spec §B.5, seed 004 eqs. (15)-(34)): one instance per accelerometer axis, state X = [r; ṙ; f],
//
//   X_{k+1} = A_d X_k + B_d (u_k + w_k) + B_e G_k,   y_k = C X_k + D (u_k + w_k) + d_k,
//   y_c,k = sat(y_k, y̲, ȳ)                                                            seed 004 eqs. (13)-(14)
//
// The time update is Algorithm 1's with l = 1 (seed 004 eqs. (18)-(19)). The measurement update is the
// Kalman one while y_c is inside the range (31)-(32); when it sits on a bound the reading only
// says y ≥ ȳ (or ≤ y̲), and the update uses the moments of the predicted y truncated to that
// half-line (33)-(34), evaluated stably far in the tail (math/truncated_normal.hpp).
// A "skip" mode (L3 of spec §B.9-1) ignores saturated samples instead.
#include <cmath>
#include <limits>

#include "adcs/core/component.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"
#include "adcs/math/truncated_normal.hpp"

namespace adcs {

//! What a saturated reading does to the estimate.
enum class SaturationUpdate {
  truncated,  //!< set-valued update with truncated-normal moments (Algorithm 2, L1)
  skip,       //!< no measurement update when saturated (L3 of spec §B.9-1)
};

//! The axis model (A_d, B_d, C, D) and R_a have no default: NaN until set (drag_free_axis_model()
//! gives seed 004's), so a forgotten one is refused. B_e = [0; 0; 1] is the structure of the
//! state [r; ṙ; f] (seed 004 eq. (12)); q = 0, S = 0 (no increment bound, no input noise) and the
//! unbounded range are real choices; X̂_0, P_0 are spec §B.5's. Sc is the filter's scalar (issue
//! 19; named Sc because the input-noise variance is S).
template <class Sc = double>
struct SaturatedEsfParamsT {
  Mat<3, 3, Sc> A_d = Mat<3, 3, Sc>::Constant(unset_v<Sc>);  //!< discrete state matrix (ZOH), no default
  Vec<3, Sc> B_d = Vec<3, Sc>::Constant(unset_v<Sc>);        //!< discrete input column, no default
  Vec<3, Sc> B_e = Vec<3, Sc>(Sc(0), Sc(0), Sc(1));           //!< disturbance-increment selector (seed 004 eq. (12))
  Mat<1, 3, Sc> C = Mat<1, 3, Sc>::Constant(unset_v<Sc>);    //!< measurement row (11), no default
  Sc D = unset_v<Sc>;                                          //!< direct input feedthrough (11), no default
  Sc q = Sc(0);                                                //!< bound on E[G²] (>= 0)
  Sc S = Sc(0);                                                //!< input-noise variance (>= 0)
  Sc R_a = unset_v<Sc>;                                        //!< accelerometer noise variance (> 0), no default
  Sc y_min = -std::numeric_limits<Sc>::infinity();             //!< range y̲ (< y_max; −inf: no lower bound)
  Sc y_max = std::numeric_limits<Sc>::infinity();              //!< range ȳ
  Vec<3, Sc> x0 = Vec<3, Sc>::Zero();                          //!< X̂_0 (spec §B.5: 0)
  Mat<3, 3, Sc> P0 = Sc(0.01) * Mat<3, 3, Sc>::Identity();     //!< P_0 (spec §B.5: 0.01 I), symmetric PSD, tr > 0
  ThetaPolicy theta_policy = ThetaPolicy::trace_optimal;
  SaturationUpdate saturation = SaturationUpdate::truncated;
  Sc period_s = unset_v<Sc>;                                   //!< [s] h, the period A_d was discretised at, no default

  //! The same parameters in the scalar T, each value rounded once (narrow_scalar: beyond T's
  //! range ±Inf, which the filter then refuses).
  template <class T>
  SaturatedEsfParamsT<T> cast() const noexcept {
    SaturatedEsfParamsT<T> out;
    out.A_d = scalar_cast<T>(A_d);
    out.B_d = scalar_cast<T>(B_d);
    out.B_e = scalar_cast<T>(B_e);
    out.C = scalar_cast<T>(C);
    out.D = narrow_scalar<T>(D);
    out.q = narrow_scalar<T>(q);
    out.S = narrow_scalar<T>(S);
    out.R_a = narrow_scalar<T>(R_a);
    out.y_min = narrow_scalar<T>(y_min);
    out.y_max = narrow_scalar<T>(y_max);
    out.x0 = scalar_cast<T>(x0);
    out.P0 = scalar_cast<T>(P0);
    out.theta_policy = theta_policy;
    out.saturation = saturation;
    out.period_s = narrow_scalar<T>(period_s);
    return out;
  }
};
using SaturatedEsfParams = SaturatedEsfParamsT<double>;

//! One filter sample of one axis.
template <class S = double>
struct SaturatedEsfInputT {
  S u_prev = S(0);           //!< [N] u_{k−1}, the axis's control force over the last period
  S delta_f_nominal = S(0);  //!< [N] Δf̄ (0: nominal model f̄ = 0)
  S y_c_m_s2 = S(0);         //!< [m/s²] the reading, possibly at the range limit
  S u = S(0);                //!< [N] u_k, through the feedthrough D
};
using SaturatedEsfInput = SaturatedEsfInputT<double>;

template <class S = double>
struct SaturatedEsfOutputT {
  Vec<3, S> x_hat = Vec<3, S>::Zero();  //!< [m, m/s, N] X̂_k = [r; ṙ; f]
};
using SaturatedEsfOutput = SaturatedEsfOutputT<double>;

struct SaturatedEsfDiagnostics {
  Status predict = Status::ok;  //!< the time update's status
  Status update = Status::ok;   //!< the measurement update's (saturated: set-valued or skipped)
};

//! Algorithm 2 in the scalar S (SaturatedEsf: double). In float (issue 19) the truncated-normal
//! moments use float's limits (math/truncated_normal.hpp, TruncNormalLimits<float>) and the
//! covariance flush float's floor (covariance_flush_v<float>).
template <class S = double>
class SaturatedEsfT {
 public:
  using Scalar = S;
  using Params = SaturatedEsfParamsT<S>;
  using Input = SaturatedEsfInputT<S>;
  using Output = SaturatedEsfOutputT<S>;
  using Diagnostics = SaturatedEsfDiagnostics;
  using Vec3s = Vec<3, S>;
  using Mat3s = Mat<3, 3, S>;

  explicit SaturatedEsfT(const Params& p) noexcept : p_(p) {
    Q1_ = S(4) * p_.q * p_.B_e * p_.B_e.transpose();  // seed 004 eq. (18), l = 1
    Q2_ = p_.S * p_.B_d * p_.B_d.transpose();         // seed 004 eq. (19)
    const bool ok = all_finite(p_.A_d) && all_finite(p_.B_d) && all_finite(p_.B_e) && all_finite(p_.C) &&
                    std::isfinite(p_.D) && finite_nonnegative(p_.q) && finite_nonnegative(p_.S) &&
                    finite_positive(p_.R_a) && p_.y_min < p_.y_max && all_finite(p_.x0) &&
                    symmetric_positive_semidefinite<3, S>(p_.P0) && p_.P0.trace() > S(0) &&
                    finite_positive(p_.period_s);
    status_ = ok ? Status::ok : Status::invalid_parameter;
    theta_fixed_ = std::sqrt(Q1_.trace() / p_.P0.trace());
    reset();
  }
  //! ok, or invalid_parameter: A_d, B_d, B_e, C, D or X̂_0 not finite (unset); q or S not finite
  //! or < 0; R_a not finite > 0; not y_min < y_max (NaN fails; ±inf: no bound); P_0 not
  //! symmetric PSD or tr P_0 = 0; period_s not finite > 0. A refused filter answers invalid_parameter from predict()
  //! and update() with its estimate untouched; fuse_axis() refuses it too.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  S period_s() const noexcept { return p_.period_s; }

  //! One sample: predict(in.u_prev, in.delta_f_nominal), then update(in.y_c_m_s2, in.u). A
  //! rejected measurement leaves the prediction (the filter coasts); a rejected time update
  //! leaves everything. seed 004's closed loop interleaves the two halves with the control law
  //! (predict, control from the prediction, update with the new u), so they stay public.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    const Status sp = predict(in.u_prev, in.delta_f_nominal);
    const Status su = usable(sp) ? update(in.y_c_m_s2, in.u) : sp;
    out.x_hat = x_;
    if (diag) {
      diag->predict = sp;
      diag->update = su;
    }
    return usable(sp) ? su : sp;
  }

  void reset() noexcept {
    x_ = p_.x0;
    P_ = p_.P0;
    saturated_updates_ = 0;
  }

  //! Time update with the applied input u_{k−1} (Algorithm 1's with l = 1; Ĝ from seed 004 eq. (9)).
  [[nodiscard]] Status predict(S u, S delta_f_nominal = S(0)) noexcept {
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(u) || !std::isfinite(delta_f_nominal)) return Status::non_finite_input;
    const S sq = std::sqrt(p_.q);
    const S G_hat = std::fmin(std::fmax(delta_f_nominal, -sq), sq);
    const Vec3s x_pred = p_.A_d * x_ + p_.B_d * u + p_.B_e * G_hat;
    const Mat3s APA = p_.A_d * P_ * p_.A_d.transpose();
    const S theta = young_weight<3, S>(p_.theta_policy, theta_fixed_, APA, Q1_);
    Mat3s P_pred = bounded_increment_prediction<3, S>(APA, Q1_, Q2_, theta);
    if (!all_finite(x_pred) || !all_finite(P_pred)) return Status::out_of_range;
    keep_psd<3, S>(P_pred);
    // Symmetrising ((P + Pᵀ)/2) or projecting a finite P near the largest value can overflow: check again.
    if (!all_finite(P_pred)) return Status::out_of_range;
    x_ = x_pred;
    P_ = P_pred;
    return Status::ok;
  }

  //! Measurement update with the (possibly saturated) reading y_c and the applied input u_k.
  //! ok (in range), saturated (set-valued or skipped update used), non_finite_input /
  //! singular (innovation variance not > 0 or not finite) / out_of_range (state untouched).
  //! seed 004 eqs. (21)-(34)
  [[nodiscard]] Status update(S y_c, S u) noexcept {
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(y_c) || !std::isfinite(u)) return Status::non_finite_input;
    const bool upper = y_c >= p_.y_max, lower = y_c <= p_.y_min;
    if ((upper || lower) && p_.saturation == SaturationUpdate::skip) {
      ++saturated_updates_;
      return Status::saturated;
    }
    const S y_pred = p_.C.dot(x_) + p_.D * u;                        // ŷ⁻
    const S R_eff = p_.R_a + p_.D * p_.D * p_.S;                     // R_a + D² S
    const S CPC = std::fmax((p_.C * P_ * p_.C.transpose())(0, 0), S(0));  // [D] clamp at >= 0
    const S S_y = CPC + R_eff;                                       // seed 004 eq. (27)
    if (!(S_y > S(0)) || !std::isfinite(S_y)) return Status::singular;  // nothing applied: not usable()
    const Vec3s K = P_ * p_.C.transpose() / S_y;                     // seed 004 eq. (22)
    const Mat3s IKC = Mat3s::Identity() - K * p_.C;
    Mat3s P_new = IKC * P_ * IKC.transpose() + R_eff * K * K.transpose();  // seed 004 eq. (21) P*
    Vec3s x_new;
    if (!upper && !lower) {
      x_new = x_ + K * (y_c - y_pred);                               // seed 004 eqs. (20), (31), (32)
    } else {
      const S sd = std::sqrt(S_y);
      // Standardised distance of the bound from the prediction, towards the admissible side.   seed 004 eq. (23)
      const S t = upper ? (p_.y_max - y_pred) / sd : (y_pred - p_.y_min) / sd;
      const TruncatedMomentsT<S> m = upper_truncated_std_normal(t);
      const S mean = upper ? y_pred + sd * m.mean : y_pred - sd * m.mean;  // E[y | Y^k]
      x_new = x_ + K * (mean - y_pred);                              // seed 004 eq. (33)
      P_new += (S_y * m.variance) * K * K.transpose();               // seed 004 eq. (34)
    }
    if (!all_finite(x_new) || !all_finite(P_new)) return Status::out_of_range;
    keep_psd<3, S>(P_new);
    if (!all_finite(P_new)) return Status::out_of_range;  // as in predict()
    x_ = x_new;
    P_ = P_new;
    if (upper || lower) {
      ++saturated_updates_;
      return Status::saturated;
    }
    return Status::ok;
  }

  const Vec3s& state() const noexcept { return x_; }
  const Mat3s& covariance() const noexcept { return P_; }
  long saturated_updates() const noexcept { return saturated_updates_; }

  //! Overwrites the estimate (fusion, Algorithm 3). Rejects non-finite values.
  [[nodiscard]] Status set_estimate(const Vec3s& x, const Mat3s& P) noexcept {
    if (!all_finite(x) || !all_finite(P)) return Status::non_finite_input;
    x_ = x;
    P_ = P;
    return Status::ok;
  }

 private:
  Params p_;
  Mat3s Q1_ = Mat3s::Zero(), Q2_ = Mat3s::Zero();
  S theta_fixed_ = S(0);
  Status status_ = Status::ok;
  Vec3s x_ = Vec3s::Zero();
  Mat3s P_ = Mat3s::Identity();
  long saturated_updates_ = 0;
};
using SaturatedEsf = SaturatedEsfT<double>;

ADCS_ASSERT_COMPONENT(SaturatedEsf);
ADCS_ASSERT_COMPONENT(SaturatedEsfT<float>);

}  // namespace adcs
