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

//! What the Euler-angle Systems share around their law (PpcSystem, EulerFloatSystem): the law,
//! its Input, Output and status as members, and the two cost stages of one step, the row into
//! the Input, then the law's step(). The Input is a member, so that neither stage alone is dead
//! code. Each System adds its name, columns, stage names and outputs.
template <class Law>
class EulerRowSystem {
 public:
  using Controller = Law;
  adcs::Status init_status() const noexcept { return ctrl_.status(); }
  void step(const double* row) noexcept { step_stages(2, row); }
  //! The first n stages of step() (cost mode).
  void step_stages(int n, const double* row) noexcept {
    fill_euler_row(row, in_);
    if (n < 2) return;
    status_ = ctrl_.step(in_, cmd_);
  }
  void step_part(int, const double* row) noexcept { step(row); }
  void command(double* u) const noexcept {
    for (int i = 0; i < 3; ++i) u[i] = static_cast<double>(cmd_.torque_B_Nm(i));
  }

 protected:
  explicit EulerRowSystem(const typename Law::Params& params) noexcept : ctrl_(params) {}
  Law ctrl_;
  typename Law::Input in_{};
  typename Law::Output cmd_{};
  adcs::Status status_ = adcs::Status::ok;
};

}  // namespace replay
