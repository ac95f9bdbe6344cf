#include "vehicle/disturbances.hpp"

#include <cmath>

#include "adcs/math/mrp.hpp"

namespace adcs::sim::vehicle {
namespace ADCS_UNITY_ID {
constexpr double kMuEarth_m3_s2 = 3.986004418e14;  // WGS 84 (incl. the atmosphere)
constexpr double kEarthRadius_m = 6378137.0;       // WGS 84 semi-major axis
}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

DisturbanceModel::DisturbanceModel(const DisturbanceConfig& config, const Mat3& J_truth_kgm2) noexcept
    : c_(config), J_(J_truth_kgm2) {
  if (c_.gravity_gradient) {
    const double R = kEarthRadius_m + c_.altitude_m;
    n_ = std::sqrt(kMuEarth_m3_s2 / (R * R * R));
  }
}

Vec3 DisturbanceModel::torque_B_Nm(double t_s, const Vec3& sigma_BN) const noexcept {
  Vec3 L = c_.constant_B_Nm;
  if (c_.harmonic)
    for (int i = 0; i < 3; ++i) L(i) += c_.amplitude_B_Nm(i) * std::sin(c_.frequency_rad_s * t_s + c_.phase_rad(i));
  if (c_.gravity_gradient) {
    const Vec3 r_N(std::cos(n_ * t_s), std::sin(n_ * t_s), 0.0);
    const Vec3 r_B = mrp_to_dcm(sigma_BN) * r_N;
    L += 3.0 * n_ * n_ * r_B.cross(J_ * r_B);
  }
  return L;
}

}  // namespace adcs::sim::vehicle
