#pragma once
// Se3Spacecraft as a plant of the one plant shape (core/plant.hpp): the structured state
// (C_NB, R_N, ω, v) as 13 numbers [q (4, scalar first, the quaternion of C_BN = C_NBᵀ); R_N (3)
// [m]; ω_BN_B (3) [rad/s]; v_B (3) [m/s]], the control wrench [M_c; F_c] (6) held over a period, and
// a constant disturbance wrench the caller may set. The attitude is integrated as a quaternion,
// q̇ = ½ q ⊗ (0, ω), re-normalised at each sample (normalize()); seed 003 eqs. (1)-(5) for the rest.
// Ground code stacks two of them (chaser and target, src/scenarios/truth_plants.hpp) with a
// time-varying disturbance through the static helpers.
#include <limits>

#include "adcs/core/plant.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/plant/se3_spacecraft.hpp"

namespace adcs {

class Se3SpacecraftPlant {
 public:
  static constexpr int kStateSize = 13;
  static constexpr int kInputSize = 6;
  using State = Vec<kStateSize>;
  using Input = Vec6;

  //! `model` (not owned) must outlive the plant.
  explicit Se3SpacecraftPlant(const Se3Spacecraft& model, const Vec6& disturbance_B = Vec6::Zero()) noexcept
      : model_(&model), tau_d_(disturbance_B) {}
  Status status() const noexcept { return all_finite(tau_d_) ? model_->status() : Status::invalid_parameter; }

  //! The body at offset `off` of a stacked state, C_NB from q/‖q‖.
  template <int S>
  static Se3SpacecraftState body(const Vec<S>& x, int off) noexcept {
    Se3SpacecraftState s;
    const Vec4 q = x.template segment<4>(off);
    s.C_NB = quat_to_dcm(QuaternionSF::from_scalar_first(q / q.norm())).transpose();
    s.R_N = x.template segment<3>(off + 4);
    s.omega_BN_B = x.template segment<3>(off + 7);
    s.v_B = x.template segment<3>(off + 10);
    return s;
  }
  template <int S>
  static void put(Vec<S>& x, int off, const Se3SpacecraftState& s) noexcept {
    x.template segment<4>(off) = dcm_to_quat(s.C_NB.transpose()).scalar_first();
    x.template segment<3>(off + 4) = s.R_N;
    x.template segment<3>(off + 7) = s.omega_BN_B;
    x.template segment<3>(off + 10) = s.v_B;
  }
  //! ẋ of the body at offset `off` under the wrenches tau_c, tau_d [N m; N]; NaN (integrator
  //! stops) when the model refuses the state (Se3Spacecraft::derivative).
  template <int S>
  static void rates(const Se3Spacecraft& m, const Vec<S>& x, int off, const Vec6& tau_c, const Vec6& tau_d,
                    Vec<S>& xdot) noexcept {
    Se3SpacecraftRates r;
    if (m.derivative(body(x, off), tau_c, tau_d, r) != Status::ok) {
      xdot.template segment<kStateSize>(off).setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    const Vec4 q = x.template segment<4>(off);
    const Vec3 w = x.template segment<3>(off + 7);
    xdot(off) = -0.5 * q.template tail<3>().dot(w);  // q̇ = ½ q ⊗ (0, ω)
    xdot.template segment<3>(off + 1) = 0.5 * (q(0) * w + q.template tail<3>().cross(w));
    xdot.template segment<3>(off + 4) = r.R_dot_N;
    xdot.template segment<3>(off + 7) = r.omega_dot_B;
    xdot.template segment<3>(off + 10) = r.v_dot_B;
  }
  //! Re-normalises the quaternion at `off`; true if it changed.
  template <int S>
  static bool normalize_at(Vec<S>& x, int off) noexcept {
    const double n = x.template segment<4>(off).norm();
    if (n != 1.0 && n > 0.0) {
      x.template segment<4>(off) /= n;
      return true;
    }
    return false;
  }

  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    rates(*model_, x, 0, u, tau_d_, xdot);
  }
  bool normalize(State& x) const noexcept { return normalize_at(x, 0); }

 private:
  const Se3Spacecraft* model_;
  Vec6 tau_d_;
};

ADCS_ASSERT_PLANT(Se3SpacecraftPlant);

}  // namespace adcs
