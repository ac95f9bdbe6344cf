#pragma once
// Seed 001's replay law: the A-REF parameters of src/scenarios/hybrid_adaptive.cpp (nominal 4-CMG
// pyramid + 3 wheels, the paper's gains, T_c = 1 ms, explicit-Euler adaptation, H_I^n = 0 because
// Ω_w(0) = 0), in double. Shared by the replay System (replay_hybrid.hpp) and the ground design
// of its gains (design_gains.cpp), so both read one parameter set.
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/plant/vscmg_configurations.hpp"

namespace replay {

inline constexpr double kHybridPeriod = 1.0e-3;  // [s] T_c, HybridAdaptiveParams default (spec A.5)

inline adcs::HybridAdaptiveParams<4, 3> hybrid_params() noexcept {
  adcs::HybridAdaptiveParams<4, 3> p;
  p.nominal = adcs::pyramid_4cmg_3rw_nominal();  // spec A.5 A-REF; the remaining fields are seed 001 §4
  p.period_s = kHybridPeriod;
  return p;
}

}  // namespace replay
