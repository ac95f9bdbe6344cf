#include "vehicle/config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>

namespace adcs::sim::vehicle {
namespace ADCS_UNITY_ID {

constexpr double kDeg = kPiRad / 180.0;
constexpr double kUnitTol = 1e-6;  //!< axes must be unit within this (then normalised)

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

//! Reads typed values and reports a bad one where it came from.
class Checker {
 public:
  Checker(const VehicleFile& f, const ParamSet& ps) : f_(f), ps_(ps) {}

  [[noreturn]] void bad(const std::string& key, const std::string& why) const {
    if (ps_.has(key) && ps_.at(key).overridden) throw ParamError(key + " (--set): " + why);
    const auto it = f_.where.find(key);
    fail_at(it == f_.where.end() ? f_.path : it->second, key + ": " + why);
  }
  std::string where(const std::string& key) const {
    if (ps_.at(key).overridden) return "--set " + key;
    const auto it = f_.where.find(key);
    return it == f_.where.end() ? f_.path : it->second;
  }

  double number(const std::string& key) const { return ps_.get_number(key); }
  double positive(const std::string& key) const {
    const double x = number(key);
    if (!(x > 0.0)) bad(key, "must be > 0, got " + num(x));
    return x;
  }
  double nonnegative(const std::string& key) const {
    const double x = number(key);
    if (!(x >= 0.0)) bad(key, "must be >= 0, got " + num(x));
    return x;
  }
  Vec3 vec3(const std::string& key) const { return ps_.get_vec<3>(key); }
  Eigen::VectorXd vec(const std::string& key) const { return ps_.get_vec<Eigen::Dynamic>(key); }
  Eigen::VectorXd positive_vec(const std::string& key) const {
    const Eigen::VectorXd v = vec(key);
    for (Eigen::Index i = 0; i < v.size(); ++i)
      if (!(v(i) > 0.0)) bad(key, "element " + std::to_string(i + 1) + " must be > 0, got " + num(v(i)));
    return v;
  }
  Vec3 positive_vec3(const std::string& key) const { return Vec3(positive_vec(key)); }
  Mat3 mat3(const std::string& key) const { return ps_.get_mat<3, 3>(key); }
  std::string name(const std::string& key) const { return ps_.get_name(key); }

  //! An N x 3 matrix of unit rows (within 1e-6), returned as normalised 3 x N columns.
  Eigen::MatrixXd unit_rows(const std::string& key) const {
    const std::vector<std::vector<double>> m = ps_.get_matrix(key);
    Eigen::MatrixXd A(3, static_cast<Eigen::Index>(m.size()));
    for (std::size_t i = 0; i < m.size(); ++i) {
      const Vec3 a(m[i][0], m[i][1], m[i][2]);
      const double n = a.norm();
      if (!(std::abs(n - 1.0) <= kUnitTol))
        bad(key, "row " + std::to_string(i + 1) + " must be a unit vector (within 1e-6), its norm is " + num(n));
      A.col(static_cast<Eigen::Index>(i)) = a / n;
    }
    return A;
  }

  //! A total inertia: symmetric, positive definite, principal moments meeting J_i + J_j >= J_k.
  Mat3 inertia(const std::string& key) const {
    const Mat3 J = mat3(key);
    if (!((J - J.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * J.norm())) bad(key, "must be symmetric");
    const Eigen::SelfAdjointEigenSolver<Mat3> es(J);
    const Vec3 d = es.eigenvalues();  // ascending
    if (!(d(0) > 0.0)) bad(key, "must be positive definite (smallest principal moment " + num(d(0)) + " kg m^2)");
    if (!(d(0) + d(1) >= d(2) * (1.0 - 1e-12)))
      bad(key, "principal moments " + num(d(0)) + ", " + num(d(1)) + ", " + num(d(2)) +
                   " break the triangle inequality J1 + J2 >= J3 (no rigid body has them)");
    return J;
  }

  //! J - sum J_s a a^T positive definite (the body without the wheels' spin inertia).
  void body_without_wheels(const std::string& key, const Mat3& J, const Eigen::MatrixXd& axes,
                           const Eigen::VectorXd& J_s) const {
    Mat3 Jb = J;
    for (Eigen::Index j = 0; j < axes.cols(); ++j) Jb -= J_s(j) * Vec3(axes.col(j)) * Vec3(axes.col(j)).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat3> es(Jb);
    if (!(es.eigenvalues()(0) > 0.0))
      bad(key, "J - sum J_s a a^T (the body without the wheels' spin inertia) must be positive definite");
  }

 private:
  const VehicleFile& f_;
  const ParamSet& ps_;
};

RunSettings read_run(const Checker& c) {
  RunSettings r;
  r.duration_s = c.positive("duration_s");
  r.control_period_s = c.positive("control_period_s");
  const std::string method = c.name("integrator");
  r.integrator.kind = method == "rk4" ? IntegratorChoice::Kind::rk4
                                      : (method == "bdf" ? IntegratorChoice::Kind::bdf : IntegratorChoice::Kind::adams);
  r.integrator.rtol = c.positive("rtol");
  if (!(r.integrator.rtol < 1.0)) c.bad("rtol", "must be < 1");
  r.integrator.atol = c.positive("atol");
  r.integrator.rk4_step_s = c.positive("rk4_step_s");
  const double every = c.number("record_every");
  if (!(every >= 1.0 && every == std::floor(every) && every <= 1e9)) c.bad("record_every", "must be a whole number >= 1");
  r.record_every = static_cast<int>(every);
  const Eigen::VectorXd w = c.vec("steady_window_s");
  r.steady_t0_s = w(0);
  r.steady_t1_s = w(1);
  if (!(0.0 <= w(0) && w(0) <= w(1) && w(1) <= r.duration_s))
    c.bad("steady_window_s", "must be [t0, t1] with 0 <= t0 <= t1 <= duration_s (" + num(r.duration_s) + " s)");
  return r;
}

WheelConfig read_wheels(const Checker& c, int n, bool steering) {
  WheelConfig w;
  w.count = n;
  if (n == 0) return w;
  w.axes_B = c.unit_rows("wheels.axes_B");
  w.J_s_kgm2 = c.positive_vec("wheels.J_s_kgm2");
  w.torque_max_Nm = c.positive_vec("wheels.torque_max_Nm");
  w.speed_max_rad_s = c.positive_vec("wheels.speed_max_rad_s");
  w.friction_Nm_s = c.vec("wheels.friction_Nm_s");
  for (Eigen::Index j = 0; j < n; ++j)
    if (!(w.friction_Nm_s(j) >= 0.0)) c.bad("wheels.friction_Nm_s", "must be >= 0 (a viscous coefficient)");
  // With CMG steering the wheels are driven by acceleration commands (the VSCMG plant's input is
  // Ω̇): the wheel servo absorbs its own friction, so a coefficient would have no effect there.
  if (steering && w.friction_Nm_s.cwiseAbs().maxCoeff() > 0.0)
    c.bad("wheels.friction_Nm_s", "is modelled with actuation.type = rw_allocation only (vscmg_steering commands "
                                  "wheel accelerations, whose servo absorbs the friction): set it to 0");
  w.Omega0_rad_s = c.vec("wheels.Omega0_rad_s");
  return w;
}

CmgConfig read_cmgs(const Checker& c, int m) {
  CmgConfig g;
  g.count = m;
  if (m == 0) return g;
  g.gimbal_axes_B = c.unit_rows("cmgs.gimbal_axes_B");
  g.spin_axes_B = c.unit_rows("cmgs.spin_axes_B");
  for (Eigen::Index i = 0; i < m; ++i) {
    const double dot = g.gimbal_axes_B.col(i).dot(g.spin_axes_B.col(i));
    if (!(std::abs(dot) <= kUnitTol))
      c.bad("cmgs.spin_axes_B", "row " + std::to_string(i + 1) + " must be perpendicular to its gimbal axis (dot " +
                                    num(dot) + ")");
  }
  g.h_Nms = c.positive_vec("cmgs.h_Nms");
  g.gimbal_rate_max_rad_s = c.positive_vec("cmgs.gimbal_rate_max_rad_s");
  g.gamma0_rad = c.vec("cmgs.gamma0_rad");
  g.steering = c.name("cmgs.steering") == "robust" ? SteeringLaw::robust : SteeringLaw::escape;
  return g;
}

StarTrackerConfig read_star_tracker(const Checker& c, double period_s) {
  StarTrackerConfig s;
  s.noise_rad = c.nonnegative("sensors.star_tracker.noise_rad");
  s.rate_hz = c.positive("sensors.star_tracker.rate_hz");
  s.dropout_probability = c.nonnegative("sensors.star_tracker.dropout_probability");
  if (!(s.dropout_probability <= 1.0)) c.bad("sensors.star_tracker.dropout_probability", "must be in [0, 1]");
  const double ratio = 1.0 / (period_s * s.rate_hz), k = std::round(ratio);
  if (!(k >= 1.0 && std::abs(ratio - k) <= 1e-9 * ratio && k <= 1e9))
    c.bad("sensors.star_tracker.rate_hz", num(s.rate_hz) + " Hz must equal or divide the control rate 1/control_period_s = " +
                                              num(1.0 / period_s) + " Hz");
  s.every_samples = static_cast<int>(k);
  return s;
}

DisturbanceConfig read_disturbances(const Checker& c, const ParamSet& ps, const Layout& l) {
  DisturbanceConfig d;
  if (ps.has("disturbances.constant_torque_B_Nm")) d.constant_B_Nm = c.vec3("disturbances.constant_torque_B_Nm");
  d.harmonic = l.harmonic;
  if (d.harmonic) {
    d.amplitude_B_Nm = c.vec3("disturbances.harmonic.amplitude_B_Nm");
    d.frequency_rad_s = c.nonnegative("disturbances.harmonic.frequency_rad_s");
    d.phase_rad = c.vec3("disturbances.harmonic.phase_rad");
  }
  if (l.gravity_gradient) {
    d.gravity_gradient = c.name("disturbances.gravity_gradient.enabled") == "true";
    d.altitude_m = c.positive("disturbances.gravity_gradient.altitude_m");
  }
  return d;
}

ControllerConfig read_controller(const Checker& c, const Layout& l) {
  ControllerConfig k;
  k.ppc = l.controller == "ppc";
  k.on_failure = c.name("controller.on_failure") == "hold_last" ? FailurePolicy::hold_last : FailurePolicy::safe_command;
  if (!k.ppc) {
    k.K_Nm = c.positive("controller.K_Nm");
    k.P_Nms = c.positive_vec3("controller.P_Nms");
    return k;
  }
  const Vec3 rho0 = c.positive_vec3("controller.rho0_deg"), rinf = c.positive_vec3("controller.rho_inf_deg");
  for (int i = 0; i < 3; ++i)
    if (!(rho0(i) > rinf(i))) c.bad("controller.rho0_deg", "must exceed rho_inf_deg on every axis");
  const Vec3 k_rho = c.positive_vec3("controller.k_rho");
  for (int i = 0; i < 3; ++i)
    k.funnel.rho[static_cast<std::size_t>(i)] = PerformanceFunction{kDeg * rho0(i), kDeg * rinf(i), k_rho(i)};
  k.funnel.delta = c.vec3("controller.delta");
  if (!((k.funnel.delta.array() >= 0.0).all() && (k.funnel.delta.array() <= 1.0).all()))
    c.bad("controller.delta", "must be in [0, 1] on every axis");
  k.funnel.recovery = c.name("controller.funnel_recovery") == "none" ? FunnelRecovery::none : FunnelRecovery::reopen;
  k.lambda = c.positive_vec3("controller.lambda");
  k.K = c.positive_vec3("controller.K");
  k.tau_w = c.vec3("controller.tau_w");
  if (!(k.tau_w.array() >= 0.0).all()) c.bad("controller.tau_w", "must be >= 0");
  k.tau_mu = c.nonnegative("controller.tau_mu");
  k.beta = c.nonnegative("controller.beta");
  k.gamma = c.nonnegative("controller.gamma");
  k.sigma = c.positive("controller.sigma");
  return k;
}

ReferenceConfig read_reference(const Checker& c, int slews) {
  ReferenceConfig r;
  auto short_mrp = [&](const std::string& key) {
    const Vec3 s = c.vec3(key);
    if (!(s.norm() <= 1.0)) c.bad(key, "must be a short-set MRP (|sigma| <= 1), |sigma| = " + num(s.norm()));
    return s;
  };
  r.sigma_RN = short_mrp("reference.sigma_RN");
  double last = -1.0;
  for (int i = 1; i <= slews; ++i) {
    const std::string p = "reference.slews." + std::to_string(i) + ".";
    Slew s{c.number(p + "t_s"), short_mrp(p + "sigma_RN")};
    if (!(s.t_s >= 0.0 && s.t_s > last)) c.bad(p + "t_s", "slew times must be >= 0 and increasing");
    last = s.t_s;
    r.slews.push_back(s);
  }
  return r;
}

KnowledgeConfig read_knowledge(const Checker& c, const VehicleConfig& v) {
  KnowledgeConfig k;
  k.J_kgm2 = c.inertia("knowledge.J_kgm2");
  if (v.wheels.count > 0) {
    k.wheel_axes_B = c.unit_rows("knowledge.wheel_axes_B");
    k.wheel_J_s_kgm2 = c.positive_vec("knowledge.wheel_J_s_kgm2");
    c.body_without_wheels("knowledge.J_kgm2", k.J_kgm2, k.wheel_axes_B, k.wheel_J_s_kgm2);
  }
  if (v.cmgs.count > 0) {
    k.cmg_gimbal_axes_B = c.unit_rows("knowledge.cmg_gimbal_axes_B");
    k.cmg_spin_axes_B = c.unit_rows("knowledge.cmg_spin_axes_B");
    for (Eigen::Index i = 0; i < v.cmgs.count; ++i)
      if (!(std::abs(k.cmg_gimbal_axes_B.col(i).dot(k.cmg_spin_axes_B.col(i))) <= kUnitTol))
        c.bad("knowledge.cmg_spin_axes_B", "row " + std::to_string(i + 1) + " must be perpendicular to its gimbal axis");
    k.cmg_h_Nms = c.positive_vec("knowledge.cmg_h_Nms");
  }
  return k;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

Vec3 ReferenceConfig::target(double t_s) const {
  Vec3 s = sigma_RN;
  for (const Slew& slew : slews)
    if (slew.t_s <= t_s) s = slew.sigma_RN;
  return s;
}

double ReferenceConfig::last_change_s(double t_end_s) const {
  double t = 0.0;
  for (const Slew& slew : slews)
    if (slew.t_s <= t_end_s) t = slew.t_s;
  return t;
}

VehicleConfig read_config(const VehicleFile& file, const ParamSet& ps) {
  const Checker c(file, ps);
  const Layout& l = file.layout;
  VehicleConfig v;
  v.name = file.name;
  v.run = read_run(c);
  v.J_kgm2 = c.inertia("spacecraft.J_kgm2");
  v.sigma0_BN = c.vec3("spacecraft.sigma0_BN");
  v.omega0_BN_B = c.vec3("spacecraft.omega0_BN_B");
  v.steering = l.actuation == "vscmg_steering";
  v.wheels = read_wheels(c, l.wheels, v.steering);
  v.cmgs = read_cmgs(c, l.cmgs);
  if (v.wheels.count > 0) {
    c.body_without_wheels("spacecraft.J_kgm2", v.J_kgm2, v.wheels.axes_B, v.wheels.J_s_kgm2);
    // Three-axis torque from the wheels alone (rw_allocation's pseudo-inverse needs G G^T
    // invertible): its smallest eigenvalue, the square of G's smallest singular value, > 1e-12.
    const Mat3 GGt = v.wheels.axes_B * v.wheels.axes_B.transpose();
    if (!v.steering && !(Eigen::SelfAdjointEigenSolver<Mat3>(GGt).eigenvalues()(0) > 1e-12))
      c.bad("wheels.axes_B", "the wheel axes must span three dimensions");
  }
  if (l.gyro) {
    GyroConfig g;
    g.arw_rad_sqrt_s = c.nonnegative("sensors.gyro.arw_rad_sqrt_s");
    g.rrw_rad_s_sqrt_s = c.nonnegative("sensors.gyro.rrw_rad_s_sqrt_s");
    g.bias_rad_s = c.vec3("sensors.gyro.bias_rad_s");
    v.gyro = g;
  }
  if (l.star_tracker) v.star_tracker = read_star_tracker(c, v.run.control_period_s);
  v.disturbances = read_disturbances(c, ps, l);
  v.controller = read_controller(c, l);
  v.reference = read_reference(c, l.slews);
  v.knowledge = read_knowledge(c, v);
  if (l.pointing_requirement)
    v.pointing_deg = Requirement{c.positive("requirements.pointing_deg"), c.where("requirements.pointing_deg")};
  if (l.settle_requirement && !l.pointing_requirement)
    c.bad("requirements.settle_s", "needs requirements.pointing_deg (the band it settles into)");
  if (l.settle_requirement)
    v.settle_s = Requirement{c.nonnegative("requirements.settle_s"), c.where("requirements.settle_s")};
  return v;
}

}  // namespace adcs::sim::vehicle
