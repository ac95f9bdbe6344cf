// RigidBodyRw: conservation laws and power balance checked on the right-hand side itself
// (directional derivatives along xdot), independent of any integrator.
#include <gtest/gtest.h>

#include <random>

#include "adcs/plant/rigid_body_rw.hpp"
#include "directional_derivative.hpp"

namespace ADCS_UNITY_ID {
using Plant = adcs::RigidBodyRw<4>;

Plant::Params params() {
  Plant::Params p;
  p.J_B << 900, 12, -8, 12, 800, 5, -8, 5, 600;
  const double s = 1.0 / std::sqrt(3.0);
  p.G_s_B << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  p.J_s << 0.1, 0.12, 0.08, 0.1;
  return p;
}

Plant::State random_state(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Plant::State x;
  for (int i = 0; i < 3; ++i) x(i) = 0.5 * u(rng);
  for (int i = 3; i < 6; ++i) x(i) = 0.05 * u(rng);
  for (int i = 6; i < 10; ++i) x(i) = 200.0 * u(rng);
  return x;
}


TEST(RigidBodyRw, ValidParameters) {
  const Plant plant(params());
  EXPECT_EQ(plant.status(), adcs::Status::ok);
  Plant::Params bad = params();
  bad.J_s(0) = 1e4;  // J - J_s g g^T no longer positive definite
  EXPECT_EQ(Plant(bad).status(), adcs::Status::invalid_parameter);
}

TEST(RigidBodyRw, TorqueFreeConservesInertialMomentumAndEnergy) {
  const Plant plant(params());
  std::mt19937_64 rng(7);
  const Plant::Input u = Plant::Input::Zero();
  for (int k = 0; k < 50; ++k) {
    const Plant::State x = random_state(rng);
    Plant::State xdot;
    plant.derivative(0.0, x, u, xdot);
    const adcs::Vec3 dH = directional([&](const Plant::State& y) { return plant.momentum_N(y); },
                                      x, xdot, 1e-4);
    const double dT = directional([&](const Plant::State& y) { return plant.kinetic_energy(y); },
                                  x, xdot, 1e-4);
    EXPECT_LT(dH.norm(), 1e-7 * (1.0 + plant.momentum_N(x).norm()));
    EXPECT_LT(std::abs(dT), 1e-7 * (1.0 + plant.kinetic_energy(x)));
  }
}

TEST(RigidBodyRw, PowerBalanceAndMomentumExchange) {
  // dT/dt = sum_i u_s,i Omega_i + omega^T L ; dH_N/dt = C^T L (motor torques are internal).
  const Plant plant(params());
  std::mt19937_64 rng(11);
  for (int k = 0; k < 50; ++k) {
    const Plant::State x = random_state(rng);
    Plant::Input u;
    u << 0.1, -0.2, 0.05, 0.15, 0.01, -0.02, 0.03;
    Plant::State xdot;
    plant.derivative(0.0, x, u, xdot);
    const double dT = directional([&](const Plant::State& y) { return plant.kinetic_energy(y); },
                                  x, xdot, 1e-5);
    const double power = u.head<4>().dot(Plant::Omega(x)) + Plant::omega_BN_B(x).dot(u.tail<3>());
    EXPECT_NEAR(dT, power, 1e-6 * (1.0 + std::abs(power)));
    const adcs::Vec3 dH = directional([&](const Plant::State& y) { return plant.momentum_N(y); },
                                      x, xdot, 1e-5);
    const adcs::Vec3 expected =
        adcs::mrp_to_dcm(Plant::sigma_BN(x)).transpose() * adcs::Vec3(u.tail<3>());
    EXPECT_LT((dH - expected).norm(), 1e-7);
  }
}

TEST(RigidBodyRw, WheelTorqueSpinsWheelAgainstBody) {
  // At rest, a positive motor torque on wheel 1 (axis b1) accelerates the body about -b1 and
  // the wheel relative to the body by u/J_s + u/J_rw,11-ish: check the exact split.
  const Plant plant(params());
  Plant::State x = Plant::State::Zero();
  Plant::Input u = Plant::Input::Zero();
  u(0) = 0.2;
  Plant::State xdot;
  plant.derivative(0.0, x, u, xdot);
  const adcs::Vec3 wdot = xdot.segment<3>(3);
  const adcs::Vec3 expected = plant.J_rw().ldlt().solve(adcs::Vec3(-0.2, 0, 0));
  EXPECT_LT((wdot - expected).norm(), 1e-15);
  EXPECT_NEAR(xdot(6), 0.2 / 0.1 - wdot(0), 1e-12);
  EXPECT_LT(xdot.head<3>().norm(), 1e-15);  // sigma_dot = G(0) * 0
}

TEST(RigidBodyRw, NormalizeKeepsShortSetAndAttitude) {
  const Plant plant(params());
  Plant::State x = Plant::State::Zero();
  x.head<3>() << 0.9, -0.8, 0.3;  // |sigma| > 1
  const adcs::Mat3 C = adcs::mrp_to_dcm(Plant::sigma_BN(x));
  EXPECT_TRUE(plant.normalize(x));
  EXPECT_LE(Plant::sigma_BN(x).norm(), 1.0);
  EXPECT_LT((adcs::mrp_to_dcm(Plant::sigma_BN(x)) - C).norm(), 1e-14);
  EXPECT_FALSE(plant.normalize(x));
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
