// The ground models of a vehicle file: the sensor model (noise levels, bias walk, dropouts, the
// gyro-propagated attitude, one noise stream per sensor), the disturbance torques, and the truth
// plants' friction and external torque.
#include <gtest/gtest.h>

#include <cmath>

#include "adcs/math/mrp.hpp"
#include "adcs/math/so3.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "vehicle/disturbances.hpp"
#include "vehicle/plants.hpp"
#include "vehicle/sensors.hpp"

namespace ADCS_UNITY_ID {
using namespace adcs;
using namespace adcs::sim::vehicle;

constexpr double kT = 0.1;  // [s] control period

TEST(VehicleSensors, AbsentSensorsArePerfect) {
  SensorModel s(std::nullopt, std::nullopt, kT, 7);
  const AttitudeState truth{Vec3(0.1, -0.2, 0.3), Vec3(1e-3, 2e-3, -3e-3)};
  for (int k = 0; k < 5; ++k) {
    const AttitudeState m = s.measure(truth);
    EXPECT_EQ(m.sigma_BN, truth.sigma_BN);
    EXPECT_EQ(m.omega_BN_B, truth.omega_BN_B);
  }
  EXPECT_EQ(s.star_tracker_samples(), 0);
}

TEST(VehicleSensors, GyroNoiseHasTheSpectralDensityOfItsArw) {
  GyroConfig g;
  g.arw_rad_sqrt_s = 1e-4;
  SensorModel s(g, std::nullopt, kT, 3);
  const int n = 20000;
  double sum2 = 0.0;
  for (int k = 0; k < n; ++k) sum2 += s.measure(AttitudeState{}).omega_BN_B.squaredNorm();
  // White noise of density arw² averaged over T: variance arw²/T per axis.
  EXPECT_NEAR(std::sqrt(sum2 / (3.0 * n)), 1e-4 / std::sqrt(kT), 0.02 * 1e-4 / std::sqrt(kT));
}

TEST(VehicleSensors, GyroBiasStartsAtItsValueAndWalks) {
  GyroConfig g;
  g.bias_rad_s = Vec3(1e-5, -2e-5, 3e-5);
  SensorModel fixed(g, std::nullopt, kT, 1);
  EXPECT_EQ(fixed.measure(AttitudeState{}).omega_BN_B, g.bias_rad_s);  // no noise, no walk: the bias
  EXPECT_EQ(fixed.measure(AttitudeState{}).omega_BN_B, g.bias_rad_s);
  // Random walk: after n periods the bias has moved by ~ rrw sqrt(n T) per axis.
  g.rrw_rad_s_sqrt_s = 1e-6;
  double sum2 = 0.0;
  const int runs = 400, n = 100;
  for (int r = 0; r < runs; ++r) {
    SensorModel s(g, std::nullopt, kT, 100 + r);
    for (int k = 0; k < n; ++k) s.measure(AttitudeState{});
    sum2 += (s.gyro_bias() - g.bias_rad_s).squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum2 / (3.0 * runs)), 1e-6 * std::sqrt(n * kT), 0.1 * 1e-6 * std::sqrt(n * kT));
}

TEST(VehicleSensors, StarTrackerSamplesAtItsRateWithDropoutsAndNoise) {
  StarTrackerConfig st;
  st.noise_rad = 1e-4;
  st.rate_hz = 5.0;
  st.every_samples = 2;
  st.dropout_probability = 0.1;
  SensorModel s(std::nullopt, st, kT, 11);
  const AttitudeState truth{Vec3(0.05, 0.02, -0.01), Vec3::Zero()};
  const int n = 20000;
  double sum2 = 0.0;
  long valid = 0;
  for (int k = 0; k < n; ++k) {
    const AttitudeState m = s.measure(truth);
    if (k % 2 == 1) {
      EXPECT_FALSE(s.star_tracker_valid());  // between star-tracker samples
      continue;
    }
    if (!s.star_tracker_valid()) continue;
    ++valid;
    // The error rotation C_m C^T = exp(-[theta]x): theta from its skew part.
    const Vec3 theta = -vee(mrp_to_dcm(m.sigma_BN) * mrp_to_dcm(truth.sigma_BN).transpose());
    sum2 += theta.squaredNorm();
  }
  EXPECT_EQ(s.star_tracker_samples(), n / 2);
  EXPECT_NEAR(double(s.star_tracker_dropouts()) / (n / 2), 0.1, 0.01);
  EXPECT_EQ(valid + s.star_tracker_dropouts(), n / 2);
  EXPECT_NEAR(std::sqrt(sum2 / (3.0 * valid)), 1e-4, 3e-6);
}

TEST(VehicleSensors, BetweenStarTrackerSamplesTheAttitudeIsPropagatedWithTheGyro) {
  // A body turning at a constant rate, a perfect gyro, a star tracker every 10th sample that always
  // drops out: the attitude given is propagated from the true initial attitude, exactly for a
  // constant rate (the rotation over T is exp(-[omega T]x)).
  StarTrackerConfig st;
  st.rate_hz = 1.0;
  st.every_samples = 10;
  st.dropout_probability = 1.0;
  GyroConfig perfect;
  SensorModel s(perfect, st, kT, 5);
  const Vec3 w(0.01, -0.02, 0.015);
  Mat3 C = mrp_to_dcm(Vec3(0.1, 0.0, -0.05));
  for (int k = 0; k < 200; ++k) {
    const AttitudeState m = s.measure(AttitudeState{dcm_to_mrp(C), w});
    EXPECT_LT((mrp_to_dcm(m.sigma_BN) - C).norm(), 1e-12) << k;
    C = so3_exp(-kT * w) * C;
  }
  EXPECT_EQ(s.star_tracker_dropouts(), 20);
}

TEST(VehicleSensors, EachSensorHasItsOwnNoiseStream) {
  GyroConfig g;
  g.arw_rad_sqrt_s = 1e-4;
  g.rrw_rad_s_sqrt_s = 1e-6;
  StarTrackerConfig st;
  st.noise_rad = 1e-4;
  st.rate_hz = 10.0;
  st.dropout_probability = 0.05;
  SensorModel gyro_only(g, std::nullopt, kT, 42), both(g, st, kT, 42), other_seed(g, st, kT, 43);
  for (int k = 0; k < 100; ++k) {
    const Vec3 a = gyro_only.measure(AttitudeState{}).omega_BN_B;
    const Vec3 b = both.measure(AttitudeState{}).omega_BN_B;
    const Vec3 c = other_seed.measure(AttitudeState{}).omega_BN_B;
    EXPECT_EQ(a, b) << k;  // adding a star tracker does not change the gyro's noise
    EXPECT_NE(a, c) << k;  // another seed, other noise
  }
}

TEST(VehicleDisturbances, ConstantHarmonicAndGravityGradient) {
  DisturbanceConfig d;
  d.constant_B_Nm = Vec3(1e-6, 0.0, -2e-6);
  d.harmonic = true;
  d.amplitude_B_Nm = Vec3(1e-5, 2e-5, 0.0);
  d.frequency_rad_s = 0.3;
  d.phase_rad = Vec3(0.0, 0.5, 0.0);
  const Mat3 J = Vec3(2.0, 3.0, 4.0).asDiagonal();
  const DisturbanceModel m(d, J);
  const Vec3 L = m.torque_B_Nm(2.0, Vec3::Zero());
  EXPECT_DOUBLE_EQ(L(0), 1e-6 + 1e-5 * std::sin(0.6));
  EXPECT_DOUBLE_EQ(L(1), 2e-5 * std::sin(0.6 + 0.5));
  EXPECT_DOUBLE_EQ(L(2), -2e-6);

  DisturbanceConfig gg;
  gg.gravity_gradient = true;
  gg.altitude_m = 500e3;
  const DisturbanceModel g(gg, J);
  const double n = std::sqrt(3.986004418e14 / std::pow(6378137.0 + 500e3, 3));
  EXPECT_DOUBLE_EQ(g.mean_motion_rad_s(), n);
  EXPECT_NEAR(n, 1.1068e-3, 1e-6);  // a 94.6 min orbit
  // At t = 0 the nadir direction is x_N. Body turned by 30 deg about z: r_B = (cos 30, -sin 30, 0),
  // L = 3 n^2 r x (J r): only z, 3 n^2 r_x r_y (J_y - J_x).
  const Vec3 sigma(0.0, 0.0, std::tan(30.0 * kPiRad / 180.0 / 4.0));
  const Vec3 Lg = g.torque_B_Nm(0.0, sigma);
  const double rx = std::cos(kPiRad / 6.0), ry = -std::sin(kPiRad / 6.0);
  EXPECT_NEAR(Lg(2), 3.0 * n * n * rx * ry * (3.0 - 2.0), 1e-18);
  EXPECT_NEAR(Lg(0), 0.0, 1e-20);
  EXPECT_NEAR(Lg(1), 0.0, 1e-20);
  // A quarter orbit later the nadir is y_N: r_B = C_BN y_N.
  const double t = 0.5 * kPiRad / n;
  const Vec3 r = mrp_to_dcm(sigma) * Vec3(0.0, 1.0, 0.0);
  EXPECT_LT((g.torque_B_Nm(t, sigma) - 3.0 * n * n * r.cross(J * r)).norm(), 1e-18);
}

TEST(VehiclePlants, WheelFrictionOpposesTheWheelSpeed) {
  RigidBodyRw<3>::Params p;
  p.J_B = Vec3(1.0, 1.2, 0.8).asDiagonal();
  p.G_s_B = Mat3::Identity();
  p.J_s = Vec3::Constant(1e-3);
  const RigidBodyRw<3> body(p);
  const DisturbanceModel none(DisturbanceConfig{}, p.J_B);
  const RwVehiclePlant<3> plant{&body, &none, Vec3(1e-5, 2e-5, 3e-5)};
  RigidBodyRw<3>::State x = RigidBodyRw<3>::State::Zero();
  x.tail<3>() = Vec3(100.0, -50.0, 20.0);
  const RigidBodyRw<3>::Input u = RigidBodyRw<3>::Input::Zero();
  RigidBodyRw<3>::State a, b;
  plant.derivative(0.0, x, u, a);
  RigidBodyRw<3>::Input v = u;
  v.head<3>() = -Vec3(1e-5 * 100.0, 2e-5 * -50.0, 3e-5 * 20.0);  // the friction torque as a motor torque
  body.derivative(0.0, x, v, b);
  EXPECT_EQ(a, b);
  EXPECT_LT(a(6), 0.0);  // wheel 1 at +100 rad/s slows down
  EXPECT_GT(a(7), 0.0);  // wheel 2 at -50 rad/s too
}

TEST(VehiclePlants, CmgPlantAddsTheExternalTorqueToTheMomentumRate) {
  VscmgParams<4, 3> p;
  VscmgGeometry<4, 3>& g = p.truth;
  ASSERT_EQ((set_cmg_pyramid<4, 3>(std::acos(1.0 / std::sqrt(3.0)), 0.4, g)), Status::ok);
  g.A_ws = Mat3::Identity();
  g.I_wws = Vec3::Constant(1e-3);
  g.J_s = Vec3(6.0, 7.0, 5.0).asDiagonal();
  p.nominal = g;
  const VscmgFullPlant<4, 3> cluster(p);
  DisturbanceConfig d;
  d.constant_B_Nm = Vec3(1e-3, -2e-3, 3e-3);
  const DisturbanceModel m(d, g.J_s);
  const CmgVehiclePlant<4, 3> plant{&cluster, &m};
  VscmgFullPlant<4, 3>::State x = cluster.initial_state(Vec3(0.1, 0.0, 0.0), Vec3(0.01, 0.0, 0.0), Vec<4>::Zero(),
                                                        Vec3(10.0, 0.0, -5.0));
  VscmgFullPlant<4, 3>::Input u;
  u << 0.1, 0.0, -0.1, 0.0, 1.0, 0.0, 0.0;
  VscmgFullPlant<4, 3>::State a, b;
  plant.derivative(0.0, x, u, a);
  cluster.derivative(0.0, x, u, b);
  EXPECT_LT((a.segment<3>(3) - b.segment<3>(3) - d.constant_B_Nm).norm(), 1e-15);
  EXPECT_EQ(a.head<3>(), b.head<3>());
  EXPECT_EQ(a.tail<7>(), b.tail<7>());
  // The shadow switch keeps |sigma| <= 1.
  x.head<3>() = Vec3(1.2, 0.0, 0.0);
  EXPECT_TRUE(plant.normalize(x));
  EXPECT_LE(x.head<3>().norm(), 1.0);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
