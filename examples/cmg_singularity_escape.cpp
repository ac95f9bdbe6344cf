// Steering a pure four-CMG pyramid of your own (docs/USER-GUIDE.md, "CMG steering"): 60° skew,
// 0.03 N m s rotors, no wheels (VscmgGeometry<4, 0>). At the internal singular configuration
// γ = (90°, 0, −90°, 0) a torque along the lost direction cannot be delivered by any gimbal rate:
//   steer()        (pseudo-inverse with a damped fallback) says so — request_not_met, torque
//                  error ≈ 100 % — and would stay there;
//   steer_escape() (Wie's generalized singularity-robust inverse with a deterministic dither)
//                  writes a bounded command that moves the gimbals off the singular surface,
//                  after which it delivers the request.
// Exit status 0 only if both behave so (ctest runs this program: label "examples").
#include <adcs/actuator/steering.hpp>
#include <adcs/plant/vscmg_configurations.hpp>  // set_cmg_pyramid(), VscmgGeometry

#include <Eigen/SVD>  // only to find the lost direction for the demonstration

#include <cmath>
#include <cstdio>

namespace {
constexpr double kDeg = adcs::kPiRad / 180.0;
using Cluster = adcs::VscmgGeometry<4, 0>;

// Torque Jacobian of the CMGs at gimbal angles gamma: X = A_t(γ) diag(h), τ_cmg = −X γ̇.
adcs::Mat<3, 4> jacobian(const Cluster& g, const adcs::Vec<4>& gamma) {
  return g.A_ct(gamma) * g.h_cw.asDiagonal();
}

int fail(const char* what) {
  std::fprintf(stderr, "cmg_singularity_escape: FAILED: %s\n", what);
  return 1;
}
}  // namespace

int main() {
  Cluster cluster;
  if (adcs::set_cmg_pyramid(60.0 * kDeg, 0.03, cluster) != adcs::Status::ok) return fail("pyramid refused");

  const adcs::Vec<4> gamma_singular(90.0 * kDeg, 0.0, -90.0 * kDeg, 0.0);
  const adcs::Mat<3, 4> X0 = jacobian(cluster, gamma_singular);
  // The lost direction: the left singular vector of the smallest singular value.
  const Eigen::JacobiSVD<adcs::Mat<3, 4>> svd(X0, Eigen::ComputeFullU);
  const adcs::Vec3 v = 2e-3 * svd.matrixU().col(2);  // [N m] X γ̇ = v, a 2 mN m request

  // 1. steer(): the damped fallback, graded by the torque error it delivers.
  adcs::SteeringParams damped;  // library defaults: 10 % torque-error bound
  adcs::Vec<4> u;
  adcs::SteeringInfo info;
  const adcs::Status s_damped = adcs::steer<4>(X0, v, damped, u, &info);
  std::printf("steer() at the singularity: %s, torque error %.3f, singularity measure %.2e\n",
              adcs::to_string(s_damped), info.torque_error, info.singularity_measure);
  if (s_damped != adcs::Status::request_not_met || info.torque_error < 0.9)
    return fail("steer() should report request_not_met with ~100 % torque error here");

  // 2. steer_escape() at 10 Hz, gimbal rates limited to 1 rad/s; the dither's phase is the
  //    sample time, so the same inputs give the same command.
  adcs::EscapeSteeringParams escape;  // Wie 2005's lambda0, mu, omega, phases
  escape.epsilon0 = 0.3;              // a stronger dither escapes faster (see cmg-singularity-escape)
  const double T = 0.1, rate_limit = 1.0, m_off = 0.05;  // [s], [rad/s], singular-surface threshold
  adcs::Vec<4> gamma = gamma_singular;
  double t_left = -1.0, err_after = 0.0;
  int after = 0;
  for (int k = 0; k < 400; ++k) {
    const double t = k * T;
    const adcs::Mat<3, 4> X = jacobian(cluster, gamma);
    const adcs::Status s = adcs::steer_escape<4>(X, v, escape, t, u, &info);
    if (!adcs::written(s)) return fail("steer_escape wrote no command");  // then: zero gimbal rate
    u = u.cwiseMax(-rate_limit).cwiseMin(rate_limit);
    if (t_left < 0.0 && info.singularity_measure > m_off) t_left = t;
    if (t_left >= 0.0 && t >= t_left + 5.0) {  // 5 s after leaving: the request is delivered
      err_after = std::fmax(err_after, (X * u - v).norm() / v.norm());
      ++after;
    }
    gamma += T * u;  // the gimbal motors follow the commanded rate over the period
  }
  std::printf("steer_escape(): left the singular surface (measure > %.2f) at %.1f s; max torque error "
              "from 5 s later: %.3g\n",
              m_off, t_left, err_after);
  if (t_left < 0.0 || t_left > 20.0) return fail("did not leave the singular surface within 20 s");
  if (after == 0 || err_after > 0.1) return fail("torque error above 10 % after the escape");
  return 0;
}
