// The one plant shape (core/plant.hpp): every plant meets it (compile time), and the two adapters
// are the models they adapt: Se3SpacecraftPlant's derivative is Se3Spacecraft's (attitude as a
// quaternion), DragFreePlant integrated over one period with u held is drag_free_discretize()'s
// A_d X + B_d u.
#include <gtest/gtest.h>

#include <cmath>

#include "adcs/adcs.hpp"

namespace ADCS_UNITY_ID {
using adcs::Status;
using adcs::Vec3;
using adcs::Vec6;

static_assert(adcs::is_plant_v<adcs::RigidBodyRw<4>>);
static_assert(adcs::is_plant_v<adcs::VscmgFullPlant<4, 3>>);
static_assert(adcs::is_plant_v<adcs::VscmgCtrlPlant<4, 3>>);
static_assert(adcs::is_plant_v<adcs::FlexibleSpacecraft<2, 4>>);
static_assert(adcs::is_plant_v<adcs::Se3SpacecraftPlant>);
static_assert(adcs::is_plant_v<adcs::DragFreePlant>);
// A structured-state model is not a plant until adapted, and a component is not a plant.
static_assert(!adcs::is_plant_v<adcs::Se3Spacecraft>);
static_assert(!adcs::is_plant_v<adcs::MrpPd<4>>);

TEST(PlantConcept, Se3AdapterIsTheSe3Model) {
  adcs::Se3SpacecraftParams p;
  p.J_B << 25, 1, 0.5, 1, 22, 1.2, 0.5, 1.2, 23;
  p.m = 105.0;
  const adcs::Se3Spacecraft model(p);
  const Vec6 tau_d(1e-4, -2e-4, 3e-4, 1e-3, 0.0, -1e-3);
  const adcs::Se3SpacecraftPlant plant(model, tau_d);
  ASSERT_EQ(plant.status(), Status::ok);
  adcs::Se3SpacecraftState s;
  s.C_NB = Eigen::AngleAxisd(0.4, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  s.R_N = Vec3(7.0e6, 1.0e5, -3.0e4);
  s.omega_BN_B = Vec3(1e-3, -2e-3, 5e-4);
  s.v_B = Vec3(10.0, 7.5e3, -3.0);
  adcs::Se3SpacecraftPlant::State x;
  adcs::Se3SpacecraftPlant::put(x, 0, s);
  const adcs::Se3SpacecraftState back = adcs::Se3SpacecraftPlant::body(x, 0);
  EXPECT_LT((back.C_NB - s.C_NB).norm(), 1e-15);
  const Vec6 u(0.01, -0.02, 0.03, 0.5, -0.5, 1.0);
  adcs::Se3SpacecraftPlant::State xdot;
  plant.derivative(0.0, x, u, xdot);
  adcs::Se3SpacecraftRates r;
  ASSERT_EQ(model.derivative(back, u, tau_d, r), Status::ok);
  EXPECT_EQ(xdot.segment<3>(4), r.R_dot_N);
  EXPECT_EQ(xdot.segment<3>(7), r.omega_dot_B);
  EXPECT_EQ(xdot.segment<3>(10), r.v_dot_B);
  // q̇ = ½ q ⊗ (0, ω) keeps |q| (its derivative is orthogonal to q).
  EXPECT_NEAR(x.head<4>().dot(xdot.head<4>()), 0.0, 1e-18);
  // A refused model makes a refused plant, and a NaN disturbance is refused.
  EXPECT_EQ(adcs::Se3SpacecraftPlant(adcs::Se3Spacecraft(adcs::Se3SpacecraftParams{})).status(),
            Status::invalid_parameter);
  EXPECT_EQ(adcs::Se3SpacecraftPlant(model, Vec6::Constant(NAN)).status(), Status::invalid_parameter);
}

TEST(PlantConcept, DragFreeAdapterOverOnePeriodIsTheZohModel) {
  const adcs::DragFreeParams p;  // seed 004's satellite
  const adcs::DragFreePlant plant(p);
  ASSERT_EQ(plant.status(), Status::ok);
  adcs::DragFreeDiscrete d;
  ASSERT_EQ(adcs::drag_free_discretize(p, d), Status::ok);
  adcs::DragFreePlant::State x0;
  for (int i = 0; i < 27; ++i) x0(i) = 1e-6 * std::cos(0.7 * i);
  adcs::DragFreePlant::Input u;
  for (int i = 0; i < 9; ++i) u(i) = 1e-3 * std::sin(0.3 * i + 0.2);
  // Classical RK4 with 1000 steps over h: error ~ (h/1000)^4 ‖A‖^5, far below the tolerance.
  const int n = 1000;
  const double dt = p.period_s / n;
  adcs::DragFreePlant::State x = x0, k1, k2, k3, k4;
  for (int i = 0; i < n; ++i) {
    plant.derivative(0.0, x, u, k1);
    plant.derivative(0.0, adcs::DragFreePlant::State(x + 0.5 * dt * k1), u, k2);
    plant.derivative(0.0, adcs::DragFreePlant::State(x + 0.5 * dt * k2), u, k3);
    plant.derivative(0.0, adcs::DragFreePlant::State(x + dt * k3), u, k4);
    x += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  const adcs::DragFreePlant::State zoh = d.A_d * x0 + d.B_d * u;
  EXPECT_LT((x - zoh).cwiseAbs().maxCoeff(), 1e-12 * (zoh.cwiseAbs().maxCoeff() + 1e-6));
  // A refused set gives a refused plant with a zero (finite) derivative.
  adcs::DragFreeParams bad = p;
  bad.m_sc = -1.0;
  const adcs::DragFreePlant refused(bad);
  EXPECT_EQ(refused.status(), Status::invalid_parameter);
  adcs::DragFreePlant::State xd;
  refused.derivative(0.0, x0, u, xd);
  EXPECT_EQ(xd, adcs::DragFreePlant::State::Zero());
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
