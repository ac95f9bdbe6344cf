#pragma once
// The row of the Euler-angle tracking Systems (seed 002's PPATC, its ATC baseline, the ESO-based
// ADRC on its vehicle; replay_ppc.hpp, replay_euler_f.hpp): t, ϑ (3), ω (3), ϑ_d (3), ϑ̇_d (3),
// ϑ̈_d (3), as record_ppc writes it, into the laws' common Input in their scalar S (for float, 16
// double-to-float conversions: library calls on the Cortex-M4F, the driver's cost, not the law's).
#include "adcs/control/euler_tracking_common.hpp"

namespace replay {

inline constexpr int kEulerRowWidth = 16;

template <class S>
void fill_euler_row(const double* row, adcs::EulerTrackingInputT<S>& in) noexcept {
  in.t_s = static_cast<S>(row[0]);
  in.state.theta_BN_rad = adcs::Vec3::Map(row + 1).cast<S>();
  in.state.omega_BN_B = adcs::Vec3::Map(row + 4).cast<S>();
  in.reference.angles = adcs::Vec3::Map(row + 7).cast<S>();
  in.reference.angles_dot = adcs::Vec3::Map(row + 10).cast<S>();
  in.reference.angles_ddot = adcs::Vec3::Map(row + 13).cast<S>();
}

}  // namespace replay
