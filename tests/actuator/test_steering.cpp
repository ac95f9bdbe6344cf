#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <Eigen/SVD>

#include "adcs/actuator/steering.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/plant/vscmg_configurations.hpp"

namespace ADCS_UNITY_ID {
using adcs::Status;
using X7 = adcs::Mat<3, 7>;

X7 hybrid_like() {  // a well-conditioned 3x7 (CMG-like columns + weak wheel columns)
  X7 X;
  X << 0.5, -0.1, 0.2, 0.3, 0.01, 0, 0,  //
      0.1, 0.6, -0.3, 0.2, 0, 0.01, 0,   //
      -0.2, 0.1, 0.4, -0.5, 0, 0, 0.01;
  return X;
}

TEST(Steering, ExactMinimumNormWhenWellConditioned) {
  const X7 X = hybrid_like();
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  ASSERT_EQ(adcs::steer<7>(X, v, adcs::SteeringParams{}, u, &info), Status::ok);
  EXPECT_EQ(info.mode, adcs::SteeringMode::pseudo_inverse);
  EXPECT_LT((X * u - v).norm(), 1e-15);
  // Minimum norm: u lies in the row space of X.
  const Eigen::Matrix<double, 7, 7> P_row =
      X.transpose() * (X * X.transpose()).inverse() * X;
  EXPECT_LT((P_row * u - u).norm(), 1e-15);
  EXPECT_GT(info.pinv.sigma_min, 0.0);
}

TEST(Steering, SingularGeometryFallsBackAndStaysBounded) {
  X7 X = hybrid_like();
  X.row(2) = 2.0 * X.row(0);  // rank 2: exactly singular
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  const adcs::SteeringParams p{1e-3, 1e-2};
  const Status s = adcs::steer<7>(X, v, p, u, &info);
  // v leaves the range of X: whatever the damped u delivers, the status matches its torque error.
  ASSERT_TRUE(adcs::written(s));
  EXPECT_EQ(s, info.torque_error <= p.max_torque_error ? Status::ill_conditioned : Status::request_not_met);
  EXPECT_NEAR(info.torque_error, (X * u - v).norm() / v.norm(), 1e-12);
  EXPECT_EQ(info.mode, adcs::SteeringMode::singularity_robust);
  EXPECT_TRUE(adcs::all_finite(u));
  EXPECT_LE(u.norm(), v.norm() / (2.0 * p.lambda_max) + 1e-12);
  EXPECT_GT(info.pinv.damping, 0.0);
}

TEST(Steering, NoJumpAtTheSwitch) {
  // Scale one direction down through the threshold: u changes continuously.
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  const adcs::SteeringParams p{1e-3, 1e-2};
  adcs::Vec<7> prev = adcs::Vec<7>::Zero();
  bool first = true;
  for (double eps = 2e-3; eps > 5e-4; eps *= 0.999) {
    X7 X = hybrid_like();
    X.row(2) = X.row(0) + eps * adcs::Mat<1, 7>::Ones();
    adcs::Vec<7> u;
    ASSERT_TRUE(adcs::written(adcs::steer<7>(X, v, p, u)));  // usable, or flagged request_not_met
    if (!first) {
      EXPECT_LT((u - prev).norm(), 0.05 * (1.0 + u.norm()));
    }
    prev = u;
    first = false;
  }
}

TEST(Steering, NonFiniteInputLeavesCommandUntouched) {
  X7 X = hybrid_like();
  adcs::Vec<7> u = adcs::Vec<7>::Constant(3.0);
  X(1, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(adcs::steer<7>(X, adcs::Vec3::Ones(), {}, u), Status::non_finite_input);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
  EXPECT_EQ(adcs::steer<7>(hybrid_like(), adcs::Vec3(0, std::numeric_limits<double>::infinity(), 0),
                           {}, u),
            Status::non_finite_input);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
}
// Failed actuators (FDIR mask): exactly zero command for them, the others solve X u = v alone,
// and the answer equals the pseudo-inverse of X without those columns.
TEST(Steering, UnavailableActuatorsGetExactlyZeroAndTheRestTakeOver) {
  const X7 X = hybrid_like();
  const adcs::Vec3 v(1e-3, -2e-3, 5e-4);
  const adcs::ActuatorMask mask = adcs::all_actuators<7>() & ~(1u << 1) & ~(1u << 5);  // gimbal 2, wheel 2
  adcs::Vec<7> u;
  adcs::SteeringInfo info;
  ASSERT_EQ(adcs::steer_available<7>(X, v, adcs::SteeringParams{}, mask, u, &info), Status::ok);
  EXPECT_EQ(u(1), 0.0);
  EXPECT_EQ(u(5), 0.0);
  EXPECT_LT((X * u - v).norm(), 1e-15);  // still exact on the remaining five
  Eigen::Matrix<double, 3, 5> Xr;
  Xr << X.col(0), X.col(2), X.col(3), X.col(4), X.col(6);
  const Eigen::Matrix<double, 5, 1> ur = Xr.transpose() * (Xr * Xr.transpose()).ldlt().solve(v);
  EXPECT_LT((adcs::Vec<5>(u(0), u(2), u(3), u(4), u(6)) - ur).norm(), 1e-12 * ur.norm());
  // All available: identical to steer().
  adcs::Vec<7> u_all, u_ref;
  ASSERT_EQ(adcs::steer_available<7>(X, v, {}, adcs::all_actuators<7>(), u_all), Status::ok);
  ASSERT_EQ(adcs::steer<7>(X, v, {}, u_ref), Status::ok);
  EXPECT_EQ(u_all, u_ref);
}

TEST(Steering, MaskThatCannotSpanThreeAxesIsBoundedAndFlagged) {
  const X7 X = hybrid_like();
  adcs::Vec<7> u = adcs::Vec<7>::Constant(7.0);
  adcs::SteeringInfo info;
  // Only wheel 1 (x axis) left: rank 1, the singularity-robust inverse answers, but two thirds
  // of v cannot be delivered: written, bounded, and not usable.
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3(1e-3, 1e-3, 1e-3), {}, 1u << 4, u, &info),
            Status::request_not_met);
  EXPECT_GT(info.torque_error, 0.8);
  EXPECT_EQ(info.mode, adcs::SteeringMode::singularity_robust);
  for (int k = 0; k < 7; ++k) {
    if (k != 4) {
      EXPECT_EQ(u(k), 0.0) << k;
    }
  }
  EXPECT_TRUE(adcs::all_finite(u));
  // Nothing available: zero command, bounded, and flagged as delivering nothing.
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3(1e-3, 0, 0), {}, 0u, u, &info), Status::request_not_met);
  EXPECT_DOUBLE_EQ(info.torque_error, 1.0);
  EXPECT_EQ(u, adcs::Vec<7>::Zero());
  // A mask naming an 8th actuator is refused, u untouched.
  u.setConstant(3.0);
  EXPECT_EQ(adcs::steer_available<7>(X, adcs::Vec3::Ones(), {}, 1u << 7, u), Status::out_of_range);
  EXPECT_EQ(u, adcs::Vec<7>::Constant(3.0));
}

// ---- CMG clusters of a user's own size: measure, torque error, singularity escape (issue 15) --

constexpr double kDeg = adcs::kPiRad / 180.0;
using Cluster = adcs::VscmgGeometry<4, 0>;  // a pure CMG cluster: no wheels

Cluster small_pyramid(double skew_deg = 60.0, double h = 0.03) {
  Cluster g;
  EXPECT_EQ(adcs::set_cmg_pyramid(skew_deg * kDeg, h, g), Status::ok);
  return g;
}
adcs::Mat<3, 4> jacobian(const Cluster& g, const adcs::Vec<4>& gamma_rad) {
  return g.A_ct(gamma_rad) * g.h_cw.asDiagonal();  // torque = −X γ̇ (seed 001 eq. (11))
}
const adcs::Vec<4> kElliptic(90 * kDeg, 0.0, -90 * kDeg, 0.0);  // internal singularity, x lost

TEST(CmgPyramid, BuilderReproducesTheNominalPyramidAndRefusesBadGeometry) {
  adcs::VscmgGeometry<4, 3> g = adcs::pyramid_4cmg_3rw_nominal();
  const adcs::VscmgGeometry<4, 3> ref = g;
  ASSERT_EQ(adcs::set_cmg_pyramid(std::acos(1.0 / std::sqrt(3.0)), 10.0, g), Status::ok);
  EXPECT_LT((g.A_cg - ref.A_cg).norm(), 1e-15);
  EXPECT_LT((g.A_cs0 - ref.A_cs0).norm(), 1e-15);
  EXPECT_LT((g.A_ct0 - ref.A_ct0).norm(), 1e-15);
  EXPECT_EQ(g.h_cw, ref.h_cw);
  const adcs::VscmgGeometry<4, 3> before = g;
  for (double skew : {0.0, 90 * kDeg, -0.1, std::nan("")})
    EXPECT_EQ(adcs::set_cmg_pyramid(skew, 1.0, g), Status::invalid_parameter) << skew;
  for (double h : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")})
    EXPECT_EQ(adcs::set_cmg_pyramid(1.0, h, g), Status::invalid_parameter) << h;
  EXPECT_EQ(g.A_cg, before.A_cg);  // untouched on refusal
  // Six CMGs: zero momentum at γ = 0, unit orthogonal axes.
  adcs::VscmgGeometry<6, 0> g6;
  ASSERT_EQ(adcs::set_cmg_pyramid(50 * kDeg, 0.1, g6), Status::ok);
  EXPECT_LT((g6.A_cs0 * g6.h_cw).norm(), 1e-15);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(g6.A_cg.col(i).norm(), 1.0, 1e-15);
    EXPECT_NEAR(g6.A_cg.col(i).dot(g6.A_cs0.col(i)), 0.0, 1e-15);
  }
}

TEST(WheelPyramid, AxesAtTheElevationAndRefusals) {
  adcs::Mat<3, 4> A;
  ASSERT_EQ(adcs::wheel_pyramid_axes<4>(30 * kDeg, A), Status::ok);
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(A.col(j).norm(), 1.0, 1e-15);
    EXPECT_NEAR(A(2, j), 0.5, 1e-15);  // sin 30°
  }
  const Eigen::JacobiSVD<adcs::Mat<3, 4>> svd(A);
  EXPECT_GT(svd.singularValues()(2), 0.5);  // spans 3 axes
  const adcs::Mat<3, 4> before = A;
  for (double e : {0.0, 90 * kDeg, -0.2, std::nan("")})
    EXPECT_EQ(adcs::wheel_pyramid_axes<4>(e, A), Status::invalid_parameter) << e;
  EXPECT_EQ(A, before);
}

TEST(SingularityEscape, MatchesThePseudoInverseAwayFromSingularities) {
  const Cluster g = small_pyramid();
  const adcs::Mat<3, 4> X = jacobian(g, adcs::Vec<4>(0.1, -0.2, 0.3, 0.05));
  const adcs::Vec3 v(-2e-3, 1e-3, 5e-4);
  adcs::Vec<4> u_exact = adcs::Vec<4>::Zero(), u = adcs::Vec<4>::Zero();
  ASSERT_EQ((adcs::right_pinv_solve<3, 4>(X, v, u_exact)), Status::ok);
  adcs::SteeringInfo info;
  for (double t : {0.0, 0.37, 12.5}) {
    ASSERT_EQ(adcs::steer_escape<4>(X, v, {}, t, u, &info), Status::ok) << t;
    EXPECT_EQ(info.mode, adcs::SteeringMode::singularity_escape);
    EXPECT_LT((u - u_exact).norm(), 1e-4 * u_exact.norm()) << t;
    EXPECT_LE(info.torque_error, adcs::kSteeringOkTorqueError);
    EXPECT_GT(info.singularity_measure, 0.5);
  }
}

TEST(SingularityEscape, ThresholdsAreRelativeToTheClusterScale) {
  // The same geometry with rotors 1e-4 and 1e+4 times as large: u scales as 1/h, the status,
  // torque error and measure do not change (the damped fallback's absolute thresholds would).
  const adcs::Vec<4> gamma(88 * kDeg, 0.0, -88 * kDeg, 0.0);
  const adcs::Vec3 v(1e-3, 2e-4, 0.0);
  adcs::Vec<4> u_ref;
  adcs::SteeringInfo ref;
  const Status s_ref = adcs::steer_escape<4>(jacobian(small_pyramid(60, 1.0), gamma), v, {}, 1.0, u_ref, &ref);
  for (double h : {1e-4, 1e4}) {
    adcs::Vec<4> u;
    adcs::SteeringInfo info;
    EXPECT_EQ(adcs::steer_escape<4>(jacobian(small_pyramid(60, h), gamma), v, {}, 1.0, u, &info), s_ref);
    EXPECT_LT((h * u - u_ref).norm(), 1e-9 * u_ref.norm()) << h;
    EXPECT_NEAR(info.torque_error, ref.torque_error, 1e-9);
    EXPECT_NEAR(info.singularity_measure, ref.singularity_measure, 1e-12);
  }
}

TEST(SingularityEscape, AtTheEllipticSingularityTheDampedFallbackSaysItDeliversNothing) {
  // The defect of issue 15: ill_conditioned (usable) with |u| ~ 1e-17 and 100 % torque error.
  const adcs::Mat<3, 4> X = jacobian(small_pyramid(), kElliptic);
  const adcs::Vec3 v(-2e-3, 0.0, 0.0);  // along the lost direction
  adcs::Vec<4> u = adcs::Vec<4>::Constant(9.0);
  adcs::SteeringInfo info;
  EXPECT_EQ(adcs::steer<4>(X, v, {}, u, &info), Status::request_not_met);
  EXPECT_GT(info.torque_error, 0.99);
  EXPECT_LT(info.singularity_measure, 1e-6);
  EXPECT_TRUE(adcs::all_finite(u));
  // The escape law's command is not usable as that torque either, but it moves the gimbals.
  adcs::Vec<4> ue;
  ASSERT_EQ(adcs::steer_escape<4>(X, v, {}, 0.5, ue, &info), Status::request_not_met);
  EXPECT_TRUE(adcs::all_finite(ue));
  EXPECT_GT(ue.norm(), 1e-4);          // ~ε0 |v| / h: small, but it moves the gimbals
  EXPECT_GT(ue.norm(), 1e10 * u.norm());  // where the damped command is ~1e-17
}

// Gimbal kinematics γ̇ = u (exact under a zero-order hold) from the elliptic singularity.
double measure_after(const Cluster& g, double seconds, bool escape) {
  adcs::EscapeSteeringParams ep;
  ep.epsilon0 = 0.3;  // the scenario's value (cmg-singularity-escape)
  adcs::Vec<4> gamma = kElliptic;
  const adcs::Vec3 v(-2e-3, 0.0, 0.0);
  const double T = 0.1;
  for (int k = 0; k < static_cast<int>(seconds / T); ++k) {
    const adcs::Mat<3, 4> X = jacobian(g, gamma);
    adcs::Vec<4> u = adcs::Vec<4>::Zero();
    const Status s = escape ? adcs::steer_escape<4>(X, v, ep, k * T, u) : adcs::steer<4>(X, v, {}, u);
    if (!adcs::written(s)) u.setZero();
    gamma += T * u.cwiseMax(-1.0).cwiseMin(1.0);  // 1 rad/s gimbal motors
  }
  adcs::SteeringInfo info;
  adcs::Vec<4> u;
  (void)adcs::steer<4>(jacobian(g, gamma), v, {}, u, &info);
  return info.singularity_measure;
}

TEST(SingularityEscape, LeavesTheEllipticSingularityWhereTheDampedInverseStays) {
  const Cluster g = small_pyramid();
  // Started exactly on the surface with the request along the lost axis the whole time (the
  // hardest case: the scenario approaches it instead), the escape law is off it by ~20 s.
  EXPECT_GT(measure_after(g, 25.0, true), 0.05);
  EXPECT_LT(measure_after(g, 25.0, false), 1e-3);
}

TEST(SingularityEscape, RefusesBadParametersAndInputsWithoutWriting) {
  const adcs::Mat<3, 4> X = jacobian(small_pyramid(), adcs::Vec<4>::Zero());
  const adcs::Vec3 v(1e-3, 0, 0);
  adcs::Vec<4> u = adcs::Vec<4>::Constant(5.0);
  const adcs::Vec<4> u0 = u;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<adcs::EscapeSteeringParams> bad(8);
  bad[0].lambda0 = 0.5 * adcs::kEscapeLambda0Min;  // X̄X̄ᵀ + λE would be rounding noise
  bad[1].lambda0 = nan;
  bad[2].mu = -1.0;
  bad[3].epsilon0 = 0.5;  // E could lose definiteness
  bad[4].omega_rad_s = std::numeric_limits<double>::infinity();
  bad[5].phase_rad(1) = nan;
  bad[6].max_torque_error = 0.0;
  bad[7].max_torque_error = 1.5;
  for (const auto& p : bad) {
    EXPECT_FALSE(adcs::valid(p));
    EXPECT_EQ(adcs::steer_escape<4>(X, v, p, 0.0, u), Status::invalid_parameter);
  }
  adcs::Mat<3, 4> Xn = X;
  Xn(1, 2) = nan;
  EXPECT_EQ(adcs::steer_escape<4>(Xn, v, {}, 0.0, u), Status::non_finite_input);
  EXPECT_EQ(adcs::steer_escape<4>(X, adcs::Vec3(0, nan, 0), {}, 0.0, u), Status::non_finite_input);
  EXPECT_EQ(adcs::steer_escape<4>(X, v, {}, nan, u), Status::non_finite_input);
  EXPECT_EQ(u, u0);
  adcs::SteeringParams sp;
  sp.max_torque_error = -0.1;
  EXPECT_EQ(adcs::steer<4>(X, v, sp, u), Status::invalid_parameter);
  sp = {};
  sp.sigma_threshold = nan;
  EXPECT_EQ(adcs::steer<4>(X, v, sp, u), Status::invalid_parameter);
  EXPECT_EQ(u, u0);
}

TEST(SingularityEscape, NoAuthorityAndNoRequest) {
  adcs::Vec<4> u = adcs::Vec<4>::Constant(5.0);
  adcs::SteeringInfo info;
  // X = 0: nothing can be delivered, u = 0 is written and flagged.
  EXPECT_EQ(adcs::steer_escape<4>(adcs::Mat<3, 4>::Zero(), adcs::Vec3(1e-3, 0, 0), {}, 0.0, u, &info),
            Status::request_not_met);
  EXPECT_EQ(u, adcs::Vec<4>::Zero());
  EXPECT_DOUBLE_EQ(info.torque_error, 1.0);
  // v = 0: u = 0, ok, whatever the geometry.
  u.setConstant(5.0);
  EXPECT_EQ(adcs::steer_escape<4>(jacobian(small_pyramid(), kElliptic), adcs::Vec3::Zero(), {}, 0.0, u, &info),
            Status::ok);
  EXPECT_EQ(u, adcs::Vec<4>::Zero());
  EXPECT_EQ(info.torque_error, 0.0);
}

TEST(SingularityEscape, BoundedNearEverySingularityAndDeterministic) {
  // Random gimbal angles, some on singular surfaces: u finite and within
  // ‖u‖ ≤ ‖v‖ / (s √(λ (1 − 2ε0))); the same inputs give the same bits.
  const Cluster g = small_pyramid();
  const adcs::EscapeSteeringParams p;
  std::srand(7);
  for (int n = 0; n < 500; ++n) {
    adcs::Vec<4> gamma = adcs::Vec<4>::Random() * adcs::kPiRad;
    if (n % 5 == 0) gamma = kElliptic + 1e-9 * adcs::Vec<4>::Random();
    const adcs::Mat<3, 4> X = jacobian(g, gamma);
    const adcs::Vec3 v = 1e-3 * adcs::Vec3::Random();
    adcs::Vec<4> u, u2;
    adcs::SteeringInfo info;
    const Status s = adcs::steer_escape<4>(X, v, p, 0.1 * n, u, &info);
    ASSERT_TRUE(adcs::written(s)) << n;
    ASSERT_TRUE(adcs::all_finite(u));
    const double bound = v.norm() / (g.h_cw(0) * std::sqrt(info.regularization * (1.0 - 2.0 * p.epsilon0)));
    EXPECT_LE(u.norm(), bound * (1.0 + 1e-9)) << n;
    EXPECT_EQ(s == Status::request_not_met, info.torque_error > p.max_torque_error) << n;
    ASSERT_EQ(adcs::steer_escape<4>(X, v, p, 0.1 * n, u2), s);
    EXPECT_EQ(u2, u);
  }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
