#pragma once
// The truth-model wrappers the paper scenarios integrate (header-only, so the Cortex-M7 replay
// recorder, tests/target/record_inputs.cpp, closes exactly the same loops without linking the
// scenario library). Each is a Plant for src/sim's integrators: kStateSize, kInputSize, State,
// Input, derivative(); Se3PairPlant also normalize().
#include <cmath>
#include <limits>

#include "adcs/core/plant.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "adcs/plant/se3_spacecraft_plant.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

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
  Status status() const noexcept {
    return plant != nullptr && ref.status() == Status::ok ? plant->status() : Status::invalid_parameter;
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    FullPlant::State xp = x.head<FullPlant::kStateSize>(), dp;
    plant->derivative(t, xp, u, dp);
    xdot.head<FullPlant::kStateSize>() = dp;
    xdot.tail<3>() = ref.sigma_dot(t, x.tail<3>());
  }
};
ADCS_ASSERT_PLANT(HybridSimPlant);

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
  Status status() const noexcept {
    return plant != nullptr && std::isfinite(d_amp) && std::isfinite(n0) ? plant->status() : Status::invalid_parameter;
  }
  Vec3 disturbance(double t) const noexcept {  // d = a [cos n0t + 1, cos n0t + sin n0t, sin n0t + 1]
    const double c = std::cos(n0 * t), s = std::sin(n0 * t);
    return d_amp * Vec3(c + 1.0, c + s, s + 1.0);
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    plant->derivative(t, x, Vec3(u + disturbance(t)), xdot);
  }
};
ADCS_ASSERT_PLANT(FlexibleSimPlant);

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
  Status status() const noexcept {
    if (chaser == nullptr || target == nullptr || scenario == nullptr) return Status::invalid_parameter;
    return chaser->status() != Status::ok ? chaser->status() : target->status();
  }

  //! The body at offset `off` (0 chaser, kBody target): the flight adapter's layout and
  //! arithmetic (plant/se3_spacecraft_plant.hpp), twice.
  static Se3SpacecraftState body(const State& x, int off) noexcept { return Se3SpacecraftPlant::body(x, off); }
  static void put(State& x, int off, const Se3SpacecraftState& s) noexcept { Se3SpacecraftPlant::put(x, off, s); }
  static void rates(const Se3Spacecraft& m, const State& x, int off, const Vec6& tau_c, const Vec6& tau_d,
                    State& xdot) noexcept {
    Se3SpacecraftPlant::rates(m, x, off, tau_c, tau_d, xdot);
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    rates(*chaser, x, 0, u, se3_disturbance(t, *scenario), xdot);
    rates(*target, x, kBody, Vec6::Zero(), Vec6::Zero(), xdot);
  }
  //! Re-normalises both quaternions; true if either changed.
  bool normalize(State& x) const noexcept {
    const bool chaser_changed = Se3SpacecraftPlant::normalize_at(x, 0);
    return Se3SpacecraftPlant::normalize_at(x, kBody) || chaser_changed;
  }
};
ADCS_ASSERT_PLANT(Se3PairPlant);

}  // namespace adcs::sim
