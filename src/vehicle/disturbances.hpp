#pragma once
// The external torques of a vehicle file (issue 18), evaluated inside the continuous dynamics
// (the truth plants of vehicle/plants.hpp call torque_B_Nm at every right-hand-side evaluation,
// so nothing is held over a control period):
//   constant   L = constant_torque_B_Nm
//   harmonic   L_i = a_i sin(ω t + φ_i)
//   gravity    L = 3 n² r̂ × (J r̂)   (Schaub & Junkins §4.6; Wie, Space Vehicle Dynamics §6.5)
//   gradient   with r̂ the unit nadir (or zenith: the torque is even in r̂) direction in B and n the
//              mean motion of a circular orbit of radius R = R_E + altitude_m, n = √(μ/R³). The
//              orbit lies in the x-y plane of N, the spacecraft on +x_N at t = 0:
//              r̂_N(t) = (cos n t, sin n t, 0), r̂_B = C_BN(σ) r̂_N.
// μ = 3.986004418e14 m³/s² and R_E = 6378137 m (WGS 84). J is the truth's total inertia.
#include "adcs/core/types.hpp"
#include "vehicle/config.hpp"

namespace adcs::sim::vehicle {

class DisturbanceModel {
 public:
  DisturbanceModel(const DisturbanceConfig& config, const Mat3& J_truth_kgm2) noexcept;

  //! [N m] the external torque at t [s] with the attitude sigma_BN, B components.
  Vec3 torque_B_Nm(double t_s, const Vec3& sigma_BN) const noexcept;
  //! [rad/s] the orbit's mean motion (0 without gravity gradient).
  double mean_motion_rad_s() const noexcept { return n_; }

 private:
  DisturbanceConfig c_;
  Mat3 J_;
  double n_ = 0.0;
};

}  // namespace adcs::sim::vehicle
