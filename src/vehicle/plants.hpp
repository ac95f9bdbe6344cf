#pragma once
// The truth plants a vehicle file flies (plants for sim/closed_loop.hpp): the flight plant models
// with what happens between two control samples added inside the dynamics, not held:
//   RwVehiclePlant<N>       RigidBodyRw<N> + the external torques (vehicle/disturbances.hpp) in
//                           its external-torque input and each wheel's viscous friction −b_j Ω_j
//                           added to its motor torque (an internal torque: the body gets the
//                           reaction through the plant's −G_s u_s).
//   CmgVehiclePlant<M, N>   VscmgFullPlant<M, N> (momentum form: ḣ = −ω × h + τ) + the external
//                           torques added to ḣ, and the MRP shadow switch at samples (|σ| <= 1;
//                           the flight plant leaves it out for seed 001's reference branch).
#include "adcs/core/plant.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "vehicle/disturbances.hpp"

namespace adcs::sim::vehicle {

template <int N>
struct RwVehiclePlant {
  using Base = RigidBodyRw<N>;
  static constexpr int kStateSize = Base::kStateSize;
  static constexpr int kInputSize = Base::kInputSize;
  using State = typename Base::State;
  using Input = typename Base::Input;

  const Base* base;
  const DisturbanceModel* disturbances;
  Vec<N> friction_Nm_s;  //!< [N m s] viscous coefficient per wheel

  Status status() const noexcept { return base != nullptr && disturbances != nullptr ? base->status() : Status::invalid_parameter; }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    Input v = u;
    v.template head<N>() -= friction_Nm_s.cwiseProduct(Base::Omega(x));
    v.template tail<3>() += disturbances->torque_B_Nm(t, Base::sigma_BN(x));
    base->derivative(t, x, v, xdot);
  }
  bool normalize(State& x) const noexcept { return base->normalize(x); }
};

template <int M, int N>
struct CmgVehiclePlant {
  using Base = VscmgFullPlant<M, N>;
  static constexpr int kStateSize = Base::kStateSize;
  static constexpr int kInputSize = Base::kInputSize;
  using State = typename Base::State;
  using Input = typename Base::Input;

  const Base* base;
  const DisturbanceModel* disturbances;

  Status status() const noexcept { return base != nullptr && disturbances != nullptr ? base->status() : Status::invalid_parameter; }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    base->derivative(t, x, u, xdot);
    xdot.template segment<3>(3) += disturbances->torque_B_Nm(t, Base::sigma_BN(x));
  }
  //! σ → its shadow when |σ| > 1; h_B, γ and Ω_w are B-frame and actuator quantities, unchanged.
  bool normalize(State& x) const noexcept {
    Vec3 s = Base::sigma_BN(x);
    if (!mrp_shadow_switch(s)) return false;
    x.template head<3>() = s;
    return true;
  }
};

}  // namespace adcs::sim::vehicle
