// A complete closed loop for your own spacecraft (docs/USER-GUIDE.md walks through it): the 12U
// cubesat of issue 15 — J = diag(0.20, 0.25, 0.15) kg m², four reaction wheels in a 30° pyramid,
// 3 mN m each — slews 30° about (1, 2, 3)/√14 and holds for 300 s, with
//   MrpPd<4>             the attitude law, run at 10 Hz            (adcs/control/mrp_pd.hpp)
//   RwTorqueAllocator<4> body torque -> wheel motor torques        (adcs/actuator/rw_allocation.hpp)
//   RigidBodyRw<4>       the spacecraft, integrated by a 10 ms RK4 (adcs/plant/rigid_body_rw.hpp)
// The plant and its integrator stand in for the real spacecraft; in flight the loop body is the
// same three calls on sensor data. Exit status 0 only if the slew settles within the wheel limit
// and every step was ok (ctest runs this program: label "examples").
#include <adcs/actuator/rw_allocation.hpp>
#include <adcs/control/mrp_pd.hpp>
#include <adcs/plant/rigid_body_rw.hpp>
#include <adcs/plant/vscmg_configurations.hpp>  // wheel_pyramid_axes()

#include <cmath>
#include <cstdio>

namespace {
constexpr int kWheels = 4;
using Plant = adcs::RigidBodyRw<kWheels>;
constexpr double kDeg = adcs::kPiRad / 180.0;

// Classical RK4 over one step h with the input held (zero-order hold), then the MRP shadow switch.
void rk4_step(const Plant& plant, double h, const Plant::Input& u, Plant::State& x) {
  Plant::State k1, k2, k3, k4;
  plant.derivative(0.0, x, u, k1);
  plant.derivative(0.0, Plant::State(x + 0.5 * h * k1), u, k2);
  plant.derivative(0.0, Plant::State(x + 0.5 * h * k2), u, k3);
  plant.derivative(0.0, Plant::State(x + h * k3), u, k4);
  x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  plant.normalize(x);
}

int fail(const char* what) {
  std::fprintf(stderr, "cubesat_mrp_pd: FAILED: %s\n", what);
  return 1;
}
}  // namespace

int main() {
  // 1. The vehicle. Every parameter is set: the library has no made-up defaults.
  Plant::Params vehicle;
  vehicle.J_B = adcs::Vec3(0.20, 0.25, 0.15).asDiagonal();            // [kg m^2] incl. wheels
  if (adcs::wheel_pyramid_axes<kWheels>(30.0 * kDeg, vehicle.G_s_B) != adcs::Status::ok)
    return fail("wheel_pyramid_axes refused 30 deg");
  vehicle.J_s = adcs::Vec<kWheels>::Constant(2e-5);                    // [kg m^2] per wheel
  const Plant plant(vehicle);
  if (plant.status() != adcs::Status::ok) return fail("plant parameters refused");

  // 2. The law at 10 Hz. Critically damped axes: near the target sigma ~ phi/4, so
  //    K = 4 J_max w_n^2 and P_i = 2 J_i w_n, with w_n = 0.1 rad/s: a bandwidth well below the
  //    10 Hz sample rate (w_n T = 0.01) and a 30 deg step asking ~0.7 mN m, inside one wheel's 3.
  const double w_n = 0.1, T = 0.1;  // [rad/s], [s]
  adcs::MrpPdParams<kWheels> law;
  law.K = 4.0 * 0.25 * w_n * w_n;
  law.P = (2.0 * w_n * vehicle.J_B.diagonal()).asDiagonal();
  law.J_rw_B = plant.J_rw();
  law.G_s_B = vehicle.G_s_B;
  law.J_s = vehicle.J_s;
  law.period_s = T;                                    // [s] required: the rate the law runs at
  law.on_failure = adcs::FailurePolicy::safe_command;  // the default: zero torque after a failed step
  adcs::MrpPd<kWheels> controller(law);
  if (controller.status() != adcs::Status::ok) return fail("MRP PD parameters refused");

  // 3. Allocation: minimum-norm wheel torques, each clipped at 3 mN m.
  adcs::RwAllocationParams<kWheels> alloc;
  alloc.G_s_B = vehicle.G_s_B;
  alloc.torque_limit = 3e-3;  // [N m]
  const adcs::RwTorqueAllocator<kWheels> allocator(alloc);
  if (allocator.status() != adcs::Status::ok) return fail("allocation parameters refused");

  // 4. The target: 30 deg about e = (1, 2, 3)/sqrt(14), sigma = tan(phi/4) e; inertial (rates 0).
  adcs::MrpPd<kWheels>::Input in;
  in.reference.sigma_RN = std::tan(30.0 * kDeg / 4.0) * adcs::Vec3(1.0, 2.0, 3.0).normalized();

  // 5. The loop: measure, control, allocate, hold for one period.
  Plant::State x = Plant::State::Zero();  // at rest, sigma_BN = 0, wheels stopped
  Plant::Input u = Plant::Input::Zero();  // [wheel motor torques; external torque = 0]
  const int steps = static_cast<int>(std::lround(420.0 / T)), substeps = 10;
  double err_rad = 0.0, settle_s = 0.0, torque_max = 0.0;
  long not_ok = 0;
  for (int k = 0; k <= steps; ++k) {
    in.state.sigma_BN = Plant::sigma_BN(x);  // perfect sensors here; yours go in these fields
    in.state.omega_BN_B = Plant::omega_BN_B(x);
    in.Omega_rad_s = Plant::Omega(x);
    err_rad = adcs::mrp_principal_angle(adcs::mrp_subtract(in.state.sigma_BN, in.reference.sigma_RN));
    if (err_rad > 1e-3) settle_s = (k + 1) * T;
    if (k == steps) break;
    adcs::BodyTorque cmd;
    if (controller.step(in, cmd) != adcs::Status::ok) ++not_ok;  // cmd is safe either way
    adcs::WheelTorques<kWheels> wheels;
    const adcs::Status a = allocator.step(cmd, wheels);  // ok or saturated (scaled); else zero torques
    if (!adcs::usable(a)) ++not_ok;
    u.head<kWheels>() = wheels.u_s_Nm;
    torque_max = std::fmax(torque_max, wheels.u_s_Nm.cwiseAbs().maxCoeff());
    for (int j = 0; j < substeps; ++j) rk4_step(plant, T / substeps, u, x);
  }

  std::printf("cubesat_mrp_pd: final error %.3g deg, settled (1e-3 rad) at %.1f s, max wheel torque %.3g mN m, "
              "%ld steps not ok\n",
              err_rad / kDeg, settle_s, 1e3 * torque_max, not_ok);
  if (!(err_rad < 1e-4)) return fail("did not converge to 1e-4 rad");
  if (!(settle_s < 120.0)) return fail("did not settle within 120 s");
  if (!(torque_max <= 3e-3)) return fail("wheel torque above the limit");
  if (not_ok != 0) return fail("a step was not ok");
  return 0;
}
