#pragma once
// CMG / VSCMG steering as a component: a body torque request → gimbal rates and wheel
// accelerations, so any torque law (MrpPd, the PPC law, ...) drives a CMG cluster. The cluster
// exchanges momentum with the body: with the rotor momentum h_i s_i(γ_i) and ∂s_i/∂γ_i = t_i
// (seed 001 eq. (3)), and wheel momentum I_ws,j Ω_j s_wj, the torque the cluster applies to the
// body is
//   L = −Σ_i h_cw,i t_i(γ_i) γ̇_i − Σ_j I_ws,j s_wj Ω̇_j = X(γ) u,   u = [γ̇; Ω̇_w]
// (gimbal and wheel inertia terms neglected, as steering laws do), so steering solves X u = L_r
// with the steering laws of actuator/steering.hpp: the singularity-robust pseudo-inverse, or Wie's
// escape law (generalized singularity-robust inverse with dither).
#include <cstdint>

#include "adcs/actuator/steering.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/plant/vscmg_cluster.hpp"

namespace adcs {

enum class SteeringLaw : std::uint8_t {
  robust = 0,  //!< steer(): pseudo-inverse, damped near singularities (stalls at one)
  escape = 1,  //!< steer_escape(): Wie's GSR inverse, leaves singularities (default)
};

//! The geometry is the steering's knowledge of the cluster (no default: refused until set). Only
//! what X(γ) uses is read and checked: the spin and transverse axes at γ = 0 (unit), the rotor
//! momenta and the wheel axes and inertias; the body inertia J_s may stay unset.
template <int M, int N>
struct VscmgSteeringParams {
  VscmgGeometry<M, N> geometry{};      //!< gimbal/spin/transverse axes, rotor momenta, wheel inertias
  SteeringLaw law = SteeringLaw::escape;
  SteeringParams robust{};             //!< thresholds of steer()
  EscapeSteeringParams escape{};       //!< Wie 2005's λ0, μ, ε0, ω, phases
};

template <int M, int N>
struct VscmgSteeringInput {
  double t_s = 0.0;                 //!< [s] sample time (the escape law's dither phase)
  BodyTorque request{};             //!< L_r, the torque the law asks of the cluster
  VscmgState<M, N> actuators{};     //!< measured gimbal angles (and wheel speeds)
};

template <int M, int N>
class VscmgSteering {
 public:
  static constexpr int L = M + N;
  using Params = VscmgSteeringParams<M, N>;
  using Input = VscmgSteeringInput<M, N>;
  using Output = VscmgRates<M, N>;
  using Diagnostics = SteeringInfo;

  explicit VscmgSteering(const Params& p) noexcept : p_(p) {
    const VscmgGeometry<M, N>& g = p_.geometry;
    bool ok = unit_columns<3, M>(g.A_cs0) && unit_columns<3, M>(g.A_ct0) && finite_positive(g.h_cw) &&
              valid(p_.robust) && valid(p_.escape);
    if constexpr (N > 0) ok = ok && unit_columns<3, N>(g.A_ws) && finite_positive(g.I_wws);
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  //! ok, or invalid_parameter: an axis not unit (NaN: unset), a rotor momentum or wheel inertia
  //! not finite > 0, or a law's parameters (valid(SteeringParams), valid(EscapeSteeringParams)).
  Status status() const noexcept { return status_; }
  double period_s() const noexcept { return 0.0; }  //!< runs whenever its law runs (core/component.hpp)
  void reset() noexcept {}

  //! X(γ) of the header comment [N m per rad/s | N m per rad/s²].
  Mat<3, L> torque_matrix(const Vec<M>& gamma_rad) const noexcept {
    Mat<3, L> X;
    X.template leftCols<M>() = -p_.geometry.A_ct(gamma_rad) * p_.geometry.h_cw.asDiagonal();
    if constexpr (N > 0) X.template rightCols<N>() = -p_.geometry.A_ws * p_.geometry.I_wws.asDiagonal();
    return X;
  }

  //! u with X(γ) u ≈ L_r. ok / ill_conditioned (usable); request_not_met: the escape law's
  //! command while it leaves a singularity, or at the momentum envelope — written, finite and
  //! bounded, and meant to be applied (it is how the escape law escapes), so the output is that
  //! command; every other failure (non_finite_input, out_of_range, invalid_parameter) outputs
  //! zero rates (the gimbals hold, the wheels coast).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) const noexcept {
    out = Output{};
    if (status_ != Status::ok) return status_;
    if (!all_finite(in.actuators.gamma_rad) || !std::isfinite(in.t_s)) return Status::non_finite_input;
    const Mat<3, L> X = torque_matrix(in.actuators.gamma_rad);
    Vec<L> u;
    const Status s = p_.law == SteeringLaw::escape
                         ? steer_escape<L>(X, in.request.torque_B_Nm, p_.escape, in.t_s, u, diag)
                         : steer<L>(X, in.request.torque_B_Nm, p_.robust, u, diag);
    if (written(s)) out = Output::from_stacked(u);
    return s;
  }

 private:
  Params p_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_COMPONENT(VscmgSteering<4, 0>);

}  // namespace adcs
