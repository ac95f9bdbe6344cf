#include "scenarios/rigid_rw_common.hpp"

#include <cmath>

#include "adcs/math/mrp.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "sim/random.hpp"

namespace adcs::sim {

CubesatManoeuvre cubesat_12u_manoeuvre() {
  CubesatManoeuvre c;
  c.source = "issue 15: 12U cubesat, J diag(0.20, 0.25, 0.15), 4 wheels at 30 deg, 3 mN m, 30 deg slew + 300 s hold";
  RigidRwDefaults& d = c.defaults;
  d.sigma0_BN = {0.0, 0.0, 0.0};
  d.omega0_BN_B = {0.0, 0.0, 0.0};
  d.Omega0_rad_s = {0.0, 0.0, 0.0, 0.0};
  d.J_kgm2 = {{0.20, 0.0, 0.0}, {0.0, 0.25, 0.0}, {0.0, 0.0, 0.15}};
  d.wheel_Js_kgm2 = {2e-5, 2e-5, 2e-5, 2e-5};  // ours: a small cubesat wheel (~2e-5 kg m^2)
  d.duration_s = 420.0;  // slew (~100 s) + the 300 s hold
  d.control_period_s = 0.1;
  d.source = c.source;
  Mat<3, kRigidRwWheels> A;
  (void)wheel_pyramid_axes<kRigidRwWheels>(30.0 * kPiRad / 180.0, A);  // 30 deg is in range: cannot fail
  for (int j = 0; j < kRigidRwWheels; ++j) d.wheel_axes_B.push_back({A(0, j), A(1, j), A(2, j)});
  d.wheel_axes_source = "issue 15: four wheels in a pyramid at 30 deg elevation (azimuths 0, 90, 180, 270 deg)";
  // 30 deg about e = (1, 2, 3)/sqrt(14): sigma = tan(30 deg / 4) e.
  const double t4 = std::tan(30.0 * kPiRad / 180.0 / 4.0), n = std::sqrt(14.0);
  c.sigma_RN = {t4 / n, 2.0 * t4 / n, 3.0 * t4 / n};
  c.torque_limit_Nm = 3e-3;
  return c;
}

void declare_rigid_rw(ParamSet& p, const RigidRwDefaults& d) {
  p.number("duration_s", d.duration_s, "s", d.source);
  p.number("control_period_s", d.control_period_s, "s", d.source);
  p.matrix("J_kgm2", d.J_kgm2, "kg m^2",
           "total inertia incl. wheels, B components; " + d.source);
  const double s = 1.0 / std::sqrt(3.0);
  if (d.wheel_axes_B.empty())
    p.matrix("wheel_axes_B", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {s, s, s}}, "-",
             "one row per wheel spin axis, B components (normalised on use); 3 orthogonal + 1 "
             "skewed, as in the issue");
  else
    p.matrix("wheel_axes_B", d.wheel_axes_B, "-",
             "one row per wheel spin axis, B components (normalised on use); " + d.wheel_axes_source);
  p.vector("wheel_Js_kgm2", d.wheel_Js_kgm2, "kg m^2", "wheel spin-axis inertia; " + d.source);
  p.vector("sigma0_BN", d.sigma0_BN, "-", "initial MRP; " + d.source);
  p.vector("omega0_BN_B", d.omega0_BN_B, "rad/s", "initial body rate; " + d.source);
  p.vector("Omega0_rad_s", d.Omega0_rad_s, "rad/s", "initial wheel speeds; " + d.source);
  p.number("omega0_dispersion_rad_s", 0.005, "rad/s",
           "assumed: with --seed > 0, omega0 is drawn uniformly in +-this per axis");
  p.name("integrator", "adams", {"adams", "bdf", "rk4"},
         "adams = CVODE Adams + fixed point; bdf = CVODE BDF + dense; rk4 = fixed-step check");
  p.number("rtol", 1e-12, "-", "CVODE relative tolerance (assumed: tight, for conservation)");
  p.number("atol", 1e-14, "state units",
           "CVODE absolute tolerance (assumed: 1e-14 keeps the 1000 s momentum drift ~1e-10)");
  p.number("rk4_step_s", 0.01, "s", "RK4 maximum sub-step (integrator=rk4 only)");
  p.number("record_every", 1, "samples", "CSV decimation: one row every N samples (>= 1)");
}

void declare_wheel_limits(ParamSet& p, double torque_limit_Nm, const std::string& torque_source) {
  p.number("torque_limit_Nm", torque_limit_Nm, "N m", torque_source);
  p.number("wheel_speed_limit_rad_s", 628.3, "rad/s",
           "ours: 6000 rpm, a typical small-satellite wheel; at the limit a wheel is not spun up further");
}

ActuatorLimits<0, kRigidRwWheels> wheel_limits(const ParamSet& p) {
  ActuatorLimits<0, kRigidRwWheels> l;
  l.wheel_torque_max_Nm.setConstant(p.get_number("torque_limit_Nm"));
  l.wheel_speed_max_rad_s.setConstant(p.get_number("wheel_speed_limit_rad_s"));
  if (!valid(l)) throw ParamError("torque_limit_Nm and wheel_speed_limit_rad_s must be > 0");
  return l;
}

void set_wheel_input(const ActuatorLimits<0, kRigidRwWheels>& limits, const RigidRwPlant::State& x,
                     const WheelTorques<kRigidRwWheels>& w, RigidRwPlant::Input& u, long& speed_held) {
  Vec<kRigidRwWheels> u_s = w.u_s_Nm;  // zero when the allocator refused (the wheels coast)
  LimitReport lr;
  if (limit_wheel_torques<kRigidRwWheels>(limits, RigidRwPlant::Omega(x), u_s, &lr) == Status::saturated)
    speed_held += lr.wheel_speed_held;
  u.head<kRigidRwWheels>() = u_s;
}

RigidRwPlant::Params rigid_rw_plant_params(const ParamSet& p) {
  RigidRwPlant::Params pp;
  pp.J_B = p.get_mat<3, 3>("J_kgm2");
  const Mat<kRigidRwWheels, 3> axes = p.get_mat<kRigidRwWheels, 3>("wheel_axes_B");
  for (int i = 0; i < kRigidRwWheels; ++i) {
    const double n = axes.row(i).norm();
    if (!(n > 0.0)) throw ParamError("wheel_axes_B: row " + std::to_string(i + 1) + " is zero");
    pp.G_s_B.col(i) = axes.row(i).transpose() / n;
  }
  pp.J_s = p.get_vec<kRigidRwWheels>("wheel_Js_kgm2");
  if ((pp.J_B - pp.J_B.transpose()).cwiseAbs().maxCoeff() > 1e-9 * pp.J_B.norm())
    throw ParamError("J_kgm2 must be symmetric");
  if (RigidRwPlant(pp).status() != Status::ok)
    throw ParamError("J_kgm2 - sum J_s g g^T must be positive definite and wheel_Js_kgm2 > 0");
  const double period = p.get_number("control_period_s");
  if (!(period > 0.0)) throw ParamError("control_period_s must be > 0");
  if (!(p.get_number("duration_s") >= 0.0)) throw ParamError("duration_s must be >= 0");
  if (!(p.get_number("record_every") >= 1.0)) throw ParamError("record_every must be >= 1");
  return pp;
}

IntegratorChoice integrator_choice(const ParamSet& p) {
  const std::string method = p.get_name("integrator");
  IntegratorChoice c;
  c.kind = method == "rk4" ? IntegratorChoice::Kind::rk4
                           : (method == "bdf" ? IntegratorChoice::Kind::bdf : IntegratorChoice::Kind::adams);
  c.rtol = p.get_number("rtol");
  c.atol = p.get_number("atol");
  c.rk4_step_s = p.get_number("rk4_step_s");
  return c;
}

RigidRwPlant::State rigid_rw_initial_state(const ParamSet& p, std::uint64_t seed,
                                           std::vector<UsedValue>* used) {
  RigidRwPlant::State x;
  Vec3 sigma = p.get_vec<3>("sigma0_BN");
  Vec3 omega = p.get_vec<3>("omega0_BN_B");
  if (seed != 0) {
    Rng rng(seed);
    // Uniform rotation: a unit quaternion uniform on S^3 (4 normals, normalised).
    Vec4 q;
    for (int i = 0; i < 4; ++i) q(i) = rng.normal();
    q.normalize();
    sigma = quat_to_mrp(QuaternionSF::from_scalar_first(q).canonical());
    const double d = p.get_number("omega0_dispersion_rad_s");
    for (int i = 0; i < 3; ++i) omega(i) = rng.uniform(-d, d);
    if (used) {
      const std::string from = "drawn from --seed " + std::to_string(seed) + ": ";
      used->push_back(UsedValue::vector("sigma0_BN", {sigma(0), sigma(1), sigma(2)}, "-",
                                        from + "uniform over SO(3), short MRP set"));
      used->push_back(UsedValue::vector(
          "omega0_BN_B", {omega(0), omega(1), omega(2)}, "rad/s",
          from + "uniform in +-omega0_dispersion_rad_s per axis"));
    }
  }
  x.head<3>() = sigma;
  x.segment<3>(3) = omega;
  x.tail<kRigidRwWheels>() = p.get_vec<kRigidRwWheels>("Omega0_rad_s");
  return x;
}

std::vector<Column> rigid_rw_columns(const std::vector<Column>& extra) {
  std::vector<Column> c{{"t", "s"},
                        {"sigma_BN_1", "-"},
                        {"sigma_BN_2", "-"},
                        {"sigma_BN_3", "-"},
                        {"omega_BN_B_1", "rad/s"},
                        {"omega_BN_B_2", "rad/s"},
                        {"omega_BN_B_3", "rad/s"}};
  for (int i = 1; i <= kRigidRwWheels; ++i) c.push_back({"Omega_" + std::to_string(i), "rad/s"});
  c.insert(c.end(), extra.begin(), extra.end());
  return c;
}

void rigid_rw_row(double t, const RigidRwPlant::State& x, std::vector<double>& row) {
  row.clear();
  row.push_back(t);
  for (int i = 0; i < RigidRwPlant::kStateSize; ++i) row.push_back(x(i));
}

}  // namespace adcs::sim
