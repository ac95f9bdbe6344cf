#pragma once
// ATC: the adaptive RBF tracking law seed 002 compares PPATC with (spec §B.3, repaired B.4 #21):
// the same gains, NN input, centres and adaptive laws, but no error transformation:
//
//   s_e = λ e + ė
//   u = B⁻¹ ( −A + ϑ̈_d − λ ė − D̂ − μ̂² s_e/(μ̂‖s_e‖ + σ) − K s_e ),  B⁻¹ = J G
//   Ŵ̇_i = τ_wi (s_e,i h − β Ŵ_i),  μ̂̇ = τ_μ (‖s_e‖ − γ μ̂)
//
// giving ṡ_e = D̄ − D̂ − μ̂² s_e/(μ̂‖s_e‖ + σ) − K s_e. Discrete-time at period_s like PPATC.
#include "adcs/control/euler_tracking_common.hpp"
#include "adcs/core/component.hpp"

namespace adcs {

template <class S = double>
struct AdaptiveTrackingParamsT {
  EulerTrackingGainsT<S> gains{};  //!< J, λ, K, RBF compensator, units, period (seed 002 Table 2)
  template <class T>
  AdaptiveTrackingParamsT<T> cast() const noexcept {
    return {gains.template cast<T>()};
  }
};
using AdaptiveTrackingParams = AdaptiveTrackingParamsT<double>;

template <class S = double>
struct AdaptiveTrackingDiagnosticsT {
  Vec<3, S> s = Vec<3, S>::Zero();       //!< [law units/s] s_e = λe + ė
  Vec<3, S> D_hat = Vec<3, S>::Zero();   //!< [law units/s²] Ŵᵀh
  Vec<3, S> robust = Vec<3, S>::Zero();  //!< [law units/s²] μ̂²s/(μ̂‖s‖ + σ)
  Vec<3, S> e = Vec<3, S>::Zero();       //!< [rad] ϑ − ϑ_d
};
using AdaptiveTrackingDiagnostics = AdaptiveTrackingDiagnosticsT<double>;

//! S: the scalar the law computes in (issue 19); `AdaptiveTracking` is the double instance.
template <class S = double>
class AdaptiveTrackingT {
 public:
  using Params = AdaptiveTrackingParamsT<S>;
  using Input = EulerTrackingInputT<S>;
  using Output = BodyTorqueT<S>;
  using Diagnostics = AdaptiveTrackingDiagnosticsT<S>;
  using Core = EulerTrackingCoreT<S>;

  explicit AdaptiveTrackingT(const Params& p) noexcept : p_(p), core_(p.gains) { reset(); }
  Status status() const noexcept { return core_.status(); }
  S period_s() const noexcept { return core_.period_s(); }
  const Params& params() const noexcept { return p_; }
  void reset() noexcept { core_.reset(); }

  //! One control sample. ok; non_finite_input; singular (gimbal lock); out_of_range (a
  //! non-finite result). Except for ok, `out` is the failure command (zero torque, or the last good
  //! command under gains.on_failure = hold_last), estimates untouched.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    out = core_.failure_command();
    if (core_.status() != Status::ok) return core_.status();
    typename Core::Kinematics k;
    const Status ks = core_.kinematics(in, k);
    if (ks != Status::ok) return ks;
    const S c = core_.angle_scale();
    const Vec<3, S>& lambda = p_.gains.lambda;
    const Vec<3, S> s = c * (lambda.cwiseProduct(k.e) + k.e_dot);
    const Vec<3, S> law = c * (-k.affine.A + in.reference.angles_ddot - lambda.cwiseProduct(k.e_dot));
    typename Core::Compensation comp;
    const Status cs = core_.compensate_and_adapt(k, s, law, out, comp);
    if (diag) {
      diag->s = s;
      diag->D_hat = comp.D_hat;
      diag->robust = comp.robust;
      diag->e = k.e;
    }
    return cs;
  }

  const Mat<7, 3, S>& weights() const noexcept { return core_.compensator().weights(); }
  S mu() const noexcept { return core_.compensator().mu(); }
  RbfCompensator<6, 7, 3, S>& compensator() noexcept { return core_.compensator(); }

 private:
  Params p_;
  Core core_;
};

using AdaptiveTracking = AdaptiveTrackingT<double>;
ADCS_ASSERT_COMPONENT(AdaptiveTracking);
ADCS_ASSERT_COMPONENT(AdaptiveTrackingT<float>);

}  // namespace adcs
