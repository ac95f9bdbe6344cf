#pragma once
// The truth-model wrappers the paper scenarios integrate (header-only, so the Cortex-M7 replay
// recorder, tests/target/record_inputs.cpp, closes exactly the same loops without linking the
// scenario library). Each is a Plant for src/sim's integrators: kStateSize, kInputSize, State,
// Input, derivative(); Se3PairPlant also normalize().
#include <cmath>
#include <limits>

#include "adcs/math/quaternion.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"

namespace adcs::sim {

// ------------------------------------------------------------------ seed 001
//! TP-FULL plus the reference MRP σ_d (spec §A.2.4: integrated with the plant, same step).
struct HybridSimPlant {
  using FullPlant = VscmgFullPlant<4, 3>;
  static constexpr int kStateSize = FullPlant::kStateSize + 3;
  static constexpr int kInputSize = FullPlant::kInputSize;
  using State = Vec<kStateSize>;
  using Input = Vec<kInputSize>;
  const FullPlant* plant;
  SinusoidalRateReference ref;
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    FullPlant::State xp = x.head<FullPlant::kStateSize>(), dp;
    plant->derivative(t, xp, u, dp);
    xdot.head<FullPlant::kStateSize>() = dp;
    xdot.tail<3>() = ref.sigma_dot(t, x.tail<3>());
  }
};

// ------------------------------------------------------------------ seed 002
//! Truth plant plus the disturbance d(t) of seed 002 §4 (B.4 #22) added to the control torque.
struct FlexibleSimPlant {
  using Plant = FlexibleSpacecraft<2, 4>;
  static constexpr int kStateSize = Plant::kStateSize;
  static constexpr int kInputSize = 3;
  using State = Plant::State;
  using Input = Vec3;
  const Plant* plant;
  double d_amp, n0;
  Vec3 disturbance(double t) const noexcept {  // d = a [cos n0t + 1, cos n0t + sin n0t, sin n0t + 1]
    const double c = std::cos(n0 * t), s = std::sin(n0 * t);
    return d_amp * Vec3(c + 1.0, c + s, s + 1.0);
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    plant->derivative(t, x, Vec3(u + disturbance(t)), xdot);
  }
};

// ------------------------------------------------------------------ seed 003 (26 states)
//! Chaser (states 0..12) and target (13..25), each [q (4), R_N (3), ω (3), v (3)].
struct Se3PairPlant {
  static constexpr int kBody = 13;
  static constexpr int kStateSize = 2 * kBody;
  static constexpr int kInputSize = 6;
  using State = Vec<kStateSize>;
  using Input = Vec6;

  const Se3Spacecraft* chaser;      //!< truth J, m
  const Se3Spacecraft* target;      //!< J_o, m_o
  const Se3ScenarioParams* scenario;  //!< disturbance

  //! The body at offset `off` (0 chaser, kBody target), C_NB from q/‖q‖.
  static Se3SpacecraftState body(const State& x, int off) noexcept {
    Se3SpacecraftState s;
    const Vec4 q = x.segment<4>(off);
    s.C_NB = quat_to_dcm(QuaternionSF::from_scalar_first(q / q.norm())).transpose();
    s.R_N = x.segment<3>(off + 4);
    s.omega_BN_B = x.segment<3>(off + 7);
    s.v_B = x.segment<3>(off + 10);
    return s;
  }
  static void put(State& x, int off, const Se3SpacecraftState& s) noexcept {
    x.segment<4>(off) = dcm_to_quat(s.C_NB.transpose()).scalar_first();
    x.segment<3>(off + 4) = s.R_N;
    x.segment<3>(off + 7) = s.omega_BN_B;
    x.segment<3>(off + 10) = s.v_B;
  }
  static void rates(const Se3Spacecraft& m, const State& x, int off, const Vec6& tau_c,
                    const Vec6& tau_d, State& xdot) noexcept {
    Se3SpacecraftRates r;
    if (m.derivative(body(x, off), tau_c, tau_d, r) != Status::ok) {
      xdot.segment<kBody>(off).setConstant(std::numeric_limits<double>::quiet_NaN());  // CVODE stops
      return;
    }
    const Vec4 q = x.segment<4>(off);
    const Vec3 w = x.segment<3>(off + 7);
    xdot(off) = -0.5 * q.tail<3>().dot(w);                            // q̇ = ½ q ⊗ (0, ω)
    xdot.segment<3>(off + 1) = 0.5 * (q(0) * w + q.tail<3>().cross(w));
    xdot.segment<3>(off + 4) = r.R_dot_N;
    xdot.segment<3>(off + 7) = r.omega_dot_B;
    xdot.segment<3>(off + 10) = r.v_dot_B;
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    rates(*chaser, x, 0, u, se3_disturbance(t, *scenario), xdot);
    rates(*target, x, kBody, Vec6::Zero(), Vec6::Zero(), xdot);
  }
  //! Re-normalises both quaternions; true if either changed.
  bool normalize(State& x) const noexcept {
    bool changed = false;
    for (int off : {0, kBody}) {
      const double n = x.segment<4>(off).norm();
      if (n != 1.0 && n > 0.0) {
        x.segment<4>(off) /= n;
        changed = true;
      }
    }
    return changed;
  }
};

}  // namespace adcs::sim
