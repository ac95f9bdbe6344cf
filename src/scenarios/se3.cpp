// Seed 003 scenarios (spec §A.8-§A.9): chaser and target rigid spacecraft on SE(3) in a 400 km,
// 45° circular orbit (point-mass gravity, J2, gravity gradient); the chaser holds the V-bar point
// 5 m behind the target under the GIVEN disturbance, ±12 % / ±3 % inertia uncertainty and
// actuator limits, 8 Hz, 200 s.
//   se3-ptc    BsPdTC: practical prescribed-time backstepping + quantization compensation +
//              adaptive squared-bound estimate ψ̂ (control/prescribed_time_se3.hpp, spec §A.5)
//   se3-ftsmc  the FTSMC baseline (control/ftsmc_se3.hpp, spec §A.6); by default it also runs the
//              BsPdTC from the same initial state for §A.9 #12 (companion=skip turns that off)
//
// Truth: both bodies integrated together by CVODE (Adams-Moulton + fixed point, rtol 1e-13, atol
// 1e-14, the harness of src/sim), 26 states [q, R_N, ω, v] per body × 2 (chaser first):
//   q  scalar-first unit quaternion of C_NB (Hamilton: C_NB = quat_to_dcm(q)ᵀ), q̇ = ½ q ⊗ (0, ω)
//   R_N, ω = omega_BN_B, v = v_B as in plant/se3_spacecraft.hpp (Ṙ = C v, Jω̇ = …, m v̇ = …).
// The DCM handed to the plant inside the right-hand side is built from q/‖q‖ (CVODE's stages are
// not exactly unit); q itself is re-normalised at every sample (normalize(), called by
// run_sampled_data before the controller; the integrator is re-initialised there anyway because
// the command changes). The disturbance u_d(t) is evaluated inside the right-hand side
// (continuous, not held); the command u_c is held over each 0.125 s tick (ZOH), spec §A.5 step 6.
// Why the absolute ECI states do not spoil the 1e-5 m steady error: both bodies share CVODE's
// step sequence, so the (≈1e-6 m) local truncation errors of the two orbits are almost equal and
// cancel in R − R_d. Checked against plain RK4 on the same 26 states at h_c/80 (integrator=rk4,
// kept as a cross-check): β agrees to 1e-9 m after one tick. The spec's RK4 + Lie-group prototype
// (stage attitudes of lower order, which v_B ≈ 7.7 km/s turns into ≈1e-8 m of R per tick) is
// matched to 0.5 s in settling time and 3 % in the steady errors; the transmission count varies by
// ±1 % with any 1e-9 m perturbation (quantized limit cycle), so it is compared at ±15 % only.
//
// Per tick (spec §A.5): desired state from the target model → control law (ψ̂ updated inside the
// PTC step) → sat → Q (quantize=1) → ZOH. Metrics follow spec §A.9: settling time of the largest
// |θ_i| (band 0.02°) and |β_i| (band 1e-4 m) over the ticks t_k = k h, k = 0..N−1; steady bounds =
// max over the ticks in [150, 200] s. disturbance_bound_est_final is ψ̂ at the end of the run;
// the FTSMC has no estimator, so it reports none of the ψ̂ metrics (absent, not 0).
// Every value the paper does not give is a parameter with its spec tag ([A] assumed).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "scenarios/scenario.hpp"
#include "sim/cvode_integrator.hpp"
#include "sim/intervals.hpp"
#include "sim/metrics.hpp"
#include "sim/recorder.hpp"
#include "sim/rk4_integrator.hpp"
#include "sim/sampled_data.hpp"

namespace adcs::sim {
namespace {

constexpr const char* kA8 = "seed 003 §4 (spec A.8)";
constexpr const char* kT1 = "spec A.8 Table 1 [A]";
constexpr const char* kT2 = "spec A.8 Table 2 [A]";
constexpr const char* kA9 = "spec A.9 [A]";
constexpr double kRad2Deg = 180.0 / 3.14159265358979323846;

enum class Law { ptc, ftsmc };

// ------------------------------------------------------------------ truth plant (26 states)
//! Chaser (states 0..12) and target (13..25), each [q (4), R_N (3), ω (3), v (3)].
struct Se3PairPlant {
  static constexpr int kBody = 13;
  static constexpr int kStateSize = 2 * kBody;
  static constexpr int kInputSize = 6;
  using State = Vec<kStateSize>;
  using Input = Vec6;

  const Se3Spacecraft* chaser;      //!< truth J, m
  const Se3Spacecraft* target;      //!< J_o, m_o
  const Se3ScenarioParams* scenario;  //!< disturbance

  //! The body at offset `off` (0 chaser, kBody target), C_NB from q/‖q‖.
  static Se3SpacecraftState body(const State& x, int off) noexcept {
    Se3SpacecraftState s;
    const Vec4 q = x.segment<4>(off);
    s.C_NB = quat_to_dcm(QuaternionSF::from_scalar_first(q / q.norm())).transpose();
    s.R_N = x.segment<3>(off + 4);
    s.omega_BN_B = x.segment<3>(off + 7);
    s.v_B = x.segment<3>(off + 10);
    return s;
  }
  static void put(State& x, int off, const Se3SpacecraftState& s) noexcept {
    x.segment<4>(off) = dcm_to_quat(s.C_NB.transpose()).scalar_first();
    x.segment<3>(off + 4) = s.R_N;
    x.segment<3>(off + 7) = s.omega_BN_B;
    x.segment<3>(off + 10) = s.v_B;
  }
  static void rates(const Se3Spacecraft& m, const State& x, int off, const Vec6& tau_c,
                    const Vec6& tau_d, State& xdot) noexcept {
    Se3SpacecraftRates r;
    if (m.derivative(body(x, off), tau_c, tau_d, r) != Status::ok) {
      xdot.segment<kBody>(off).setConstant(std::numeric_limits<double>::quiet_NaN());  // CVODE stops
      return;
    }
    const Vec4 q = x.segment<4>(off);
    const Vec3 w = x.segment<3>(off + 7);
    xdot(off) = -0.5 * q.tail<3>().dot(w);                            // q̇ = ½ q ⊗ (0, ω)
    xdot.segment<3>(off + 1) = 0.5 * (q(0) * w + q.tail<3>().cross(w));
    xdot.segment<3>(off + 4) = r.R_dot_N;
    xdot.segment<3>(off + 7) = r.omega_dot_B;
    xdot.segment<3>(off + 10) = r.v_dot_B;
  }
  void derivative(double t, const State& x, const Input& u, State& xdot) const noexcept {
    rates(*chaser, x, 0, u, se3_disturbance(t, *scenario), xdot);
    rates(*target, x, kBody, Vec6::Zero(), Vec6::Zero(), xdot);
  }
  //! Re-normalises both quaternions; true if either changed.
  bool normalize(State& x) const noexcept {
    bool changed = false;
    for (int off : {0, kBody}) {
      const double n = x.segment<4>(off).norm();
      if (n != 1.0 && n > 0.0) {
        x.segment<4>(off) /= n;
        changed = true;
      }
    }
    return changed;
  }
};

// ------------------------------------------------------------------ configuration
struct Se3Config {
  Se3ScenarioParams sp;
  int state = 1;
  bool quantize = true;
  double duration = 200.0, period = 0.125;
  PrescribedTimeSe3Params ptc;
  FtsmcSe3Params fts;
  CompositeQuantizerParams<6> q = seed003_quantizer_params();
  double band_att_deg = 0.02, band_pos_m = 1e-4;
  double window0 = 150.0, window1 = 200.0;
  bool rk4 = false;
  double rtol = 1e-13, atol = 1e-14, rk4_step = 0.0125;
  int record_every = 1;
};

std::vector<std::vector<double>> to_rows(const Mat3& m) {
  std::vector<std::vector<double>> v(3, std::vector<double>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[i][j] = m(i, j);
  return v;
}

void declare_common(ParamSet& p, Law law) {
  const Se3ScenarioParams d;
  p.number("duration_s", d.horizon, "s", "seed 003 §4: 200 s (1600 commands)");
  p.number("control_period_s", d.control_period, "s", "seed 003 §4: 8 Hz");
  p.number("initial_state", 1, "-", "seed 003 §4 initial-state table, rows 1-4 (spec A.8)");
  p.number("uncertainty_sign", d.uncertainty_sign, "-",
           "spec A.8 / A.10-5 [A]: truth = nominal + s (dJ, dm), s = +1 or -1");
  p.number("quantize", 1, "-",
           "seed 003: the comparison is under input quantization; 0 = saturation only (ours)");
  p.number("altitude_m", d.altitude, "m", kA8);
  p.number("inclination_deg", d.inclination * kRad2Deg, "deg", kA8);
  p.matrix("J_target_kgm2", to_rows(d.J_o), "kg m^2", kA8);
  p.number("m_target_kg", d.m_o, "kg", kA8);
  p.matrix("J0_kgm2", to_rows(d.J0), "kg m^2", std::string(kA8) + ": chaser nominal (controller model)");
  p.number("m0_kg", d.m0, "kg", std::string(kA8) + ": chaser nominal");
  p.number("dJ_ratio", d.dJ_ratio, "-", std::string(kA8) + ": dJ = 0.12 J0");
  p.number("dm_ratio", d.dm_ratio, "-", std::string(kA8) + ": dm = 0.03 m0");
  p.vector("r_chi_m", {d.r_chi(0), d.r_chi(1), d.r_chi(2)}, "m",
           std::string(kA8) + ": desired chaser position, target body (C_chi = I)");
  p.number("dist_amplitude", d.dist_amplitude, "N m, N", std::string(kA8) + " (chaser body frame [A])");
  p.vector("dist_freq_rad_s", {d.dist_freq(0), d.dist_freq(1), d.dist_freq(2)}, "rad/s", kA8);
  p.number("M_max_Nm", d.M_max, "N m", kA8);
  p.number("F_max_N", d.F_max, "N", kA8);
  const QuantizerChannelParams qt = seed003_quantizer_params().channel[0];
  const QuantizerChannelParams qf = seed003_quantizer_params().channel[3];
  p.vector("quantizer_torque", {qt.rho, qt.u_min, qt.u_s, qt.sigma}, "-, N m, N m, N m",
           std::string(kT1) + ": [rho, u_min, u_s, sigma]");
  p.vector("quantizer_force", {qf.rho, qf.u_min, qf.u_s, qf.sigma}, "-, N, N, N",
           std::string(kT1) + ": [rho, u_min, u_s, sigma]");
  p.number("band_att_deg", 0.02, "deg", std::string(kA9) + ": settling band of max |theta_i|");
  p.number("band_pos_m", 1e-4, "m", std::string(kA9) + ": settling band of max |beta_i|");
  p.vector("steady_window_s", {150.0, 200.0}, "s", "spec A.9: steady bound = max over [150, 200] s");
  p.name("integrator", "adams", {"adams", "rk4"},
         "adams = CVODE Adams + fixed point (truth); rk4 = fixed-step cross-check on the same states");
  p.number("rtol", 1e-13, "-",
           "CVODE relative tolerance (ours: matches RK4 at h_c/80 to 1e-7 m at 5 s; ~29k steps per 200 s)");
  p.number("atol", 1e-14, "state units", "CVODE absolute tolerance (ours, see rtol)");
  p.number("rk4_step_s", 0.0125, "s", "RK4 sub-step, integrator=rk4 only (spec C.1: h_c/10)");
  p.number("record_every", 1, "samples", "CSV decimation: one row every N ticks (>= 1)");
  if (law == Law::ptc) {
    const PrescribedTimeSe3Params g;
    p.number("T_s", g.T, "s", "seed 003 §4: T = 120 s (variants 80, 100, 140)");
    p.number("p", g.p, "-", kT1);
    p.number("K2_rot", g.K2(0), "1/s", kT1);
    p.number("K2_trans", g.K2(3), "1/s", kT1);
    p.number("Lambda_rot", g.Lambda(0), "-", kT1);
    p.number("Lambda_trans", g.Lambda(3), "-", kT1);
    p.number("Upsilon_rot", g.Upsilon(0), "-", kT1);
    p.number("Upsilon_trans", g.Upsilon(3), "-", kT1);
    p.number("eps1", g.eps1, "rad, m", kT1);
    p.number("K3_rot", g.K3(0), "1/s", kT1);
    p.number("K3_trans", g.K3(3), "1/s", kT1);
    p.number("Lambda2", g.Lambda2(0), "-", std::string(kT1) + ": Lambda' (all channels)");
    p.number("Upsilon2", g.Upsilon2(0), "-", std::string(kT1) + ": Upsilon' (all channels)");
    p.number("eps2", g.eps2, "-", kT1);
    p.number("zeta_margin", 1.05, "-", std::string(kT1) + ": zeta_i = margin * varpi_i of the quantizer");
    p.number("eps_q", g.eps_q, "-", kT1);
    p.number("a", g.a, "-", kT1);
    p.number("gamma", g.gamma, "-", kT1);
    p.number("sigma1", g.sigma1, "1/s", kT1);
    p.number("sigma2", g.sigma2, "-", kT1);
    p.number("psi_hat0", g.psi_hat0, "-", kA8);
  } else {
    const FtsmcSe3Params g;
    p.number("p_s", g.p_s, "-", std::string(kT2) + ": exponent r = 1 - p_s = 0.5");
    p.number("eps", g.eps, "rad, m", kT2);
    p.number("C1_rot", g.C1(0), "1/s", kT2);
    p.number("C1_trans", g.C1(3), "1/s", kT2);
    p.number("C2_rot", g.C2(0), "-", kT2);
    p.number("C2_trans", g.C2(3), "-", kT2);
    p.number("K_a", g.K_a(0), "1/s", std::string(kT2) + " (all channels)");
    p.number("K_b", g.K_b(0), "-", std::string(kT2) + " (all channels)");
    p.number("rho_reach", g.rho, "-", kT2);
    p.number("k_s", g.k_s, "-", kT2);
    p.number("phi", g.phi, "-", kT2);
    p.name("companion", "run", {"run", "skip"},
           "run: also simulate the BsPdTC (Table 1, T = 120 s) from the same state (spec A.9 #12)");
  }
}

int integer_in(const ParamSet& p, const std::string& key, std::initializer_list<int> allowed) {
  const double v = p.get_number(key);
  for (int a : allowed)
    if (v == a) return a;
  std::string list;
  for (int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
  throw ParamError(key + " must be one of " + list + ", got " + format_number(v));
}

QuantizerChannelParams channel(const ParamSet& p, const std::string& key) {
  const Vec4 v = p.get_vec<4>(key);
  return QuantizerChannelParams{v(0), v(1), v(2), v(3)};
}

//! Everything but the law's gains (shared by the FTSMC's PTC companion).
Se3Config common_config(const ParamSet& p) {
  Se3Config c;
  Se3ScenarioParams& s = c.sp;
  c.duration = p.get_number("duration_s");
  c.period = p.get_number("control_period_s");
  if (!(c.duration >= 0.0)) throw ParamError("duration_s must be >= 0");
  if (!(c.period > 0.0)) throw ParamError("control_period_s must be > 0");
  c.state = integer_in(p, "initial_state", {1, 2, 3, 4});
  s.uncertainty_sign = integer_in(p, "uncertainty_sign", {1, -1});
  c.quantize = integer_in(p, "quantize", {0, 1}) == 1;
  s.altitude = p.get_number("altitude_m");
  s.inclination = p.get_number("inclination_deg") / kRad2Deg;
  s.J_o = p.get_mat<3, 3>("J_target_kgm2");
  s.m_o = p.get_number("m_target_kg");
  s.J0 = p.get_mat<3, 3>("J0_kgm2");
  s.m0 = p.get_number("m0_kg");
  s.dJ_ratio = p.get_number("dJ_ratio");
  s.dm_ratio = p.get_number("dm_ratio");
  s.r_chi = p.get_vec<3>("r_chi_m");
  s.dist_amplitude = p.get_number("dist_amplitude");
  s.dist_freq = p.get_vec<3>("dist_freq_rad_s");
  s.M_max = p.get_number("M_max_Nm");
  s.F_max = p.get_number("F_max_N");
  s.control_period = c.period;
  s.horizon = c.duration;
  if (!(s.M_max > 0.0) || !(s.F_max > 0.0)) throw ParamError("M_max_Nm and F_max_N must be > 0");
  for (int i = 0; i < 3; ++i) {
    c.q.channel[i] = channel(p, "quantizer_torque");
    c.q.channel[i + 3] = channel(p, "quantizer_force");
  }
  if (!valid(c.q.channel[0]) || !valid(c.q.channel[3]))
    throw ParamError("quantizer_torque/force: need rho in (0,1), 0 < u_min <= u_s, sigma > 0");
  c.band_att_deg = p.get_number("band_att_deg");
  c.band_pos_m = p.get_number("band_pos_m");
  const Vec<2> w = p.get_vec<2>("steady_window_s");
  c.window0 = w(0);
  c.window1 = w(1);
  if (!(c.band_att_deg > 0.0) || !(c.band_pos_m > 0.0) || !(w(1) >= w(0)))
    throw ParamError("bands must be > 0 and steady_window_s increasing");
  c.rk4 = p.get_name("integrator") == "rk4";
  c.rtol = p.get_number("rtol");
  c.atol = p.get_number("atol");
  c.rk4_step = p.get_number("rk4_step_s");
  if (!(c.rtol > 0.0) || !(c.atol > 0.0) || !(c.rk4_step > 0.0))
    throw ParamError("rtol, atol and rk4_step_s must be > 0");
  const double every = p.get_number("record_every");
  if (!(every >= 1.0) || every != std::floor(every)) throw ParamError("record_every must be an integer >= 1");
  c.record_every = static_cast<int>(every);
  c.ptc.h = c.period;
  c.ptc.zeta = quantization_compensation_gain(c.q, 1.05);
  return c;
}

Vec6 rot_trans(double rot, double trans) {
  Vec6 v;
  v << Vec3::Constant(rot), Vec3::Constant(trans);
  return v;
}

Se3Config make_config(const ParamSet& p, Law law) {
  Se3Config c = common_config(p);
  if (law == Law::ptc) {
    PrescribedTimeSe3Params& g = c.ptc;
    g.T = p.get_number("T_s");
    g.p = p.get_number("p");
    g.K2 = rot_trans(p.get_number("K2_rot"), p.get_number("K2_trans"));
    g.Lambda = rot_trans(p.get_number("Lambda_rot"), p.get_number("Lambda_trans"));
    g.Upsilon = rot_trans(p.get_number("Upsilon_rot"), p.get_number("Upsilon_trans"));
    g.eps1 = p.get_number("eps1");
    g.K3 = rot_trans(p.get_number("K3_rot"), p.get_number("K3_trans"));
    g.Lambda2 = Vec6::Constant(p.get_number("Lambda2"));
    g.Upsilon2 = Vec6::Constant(p.get_number("Upsilon2"));
    g.eps2 = p.get_number("eps2");
    g.zeta = quantization_compensation_gain(c.q, p.get_number("zeta_margin"));
    g.eps_q = p.get_number("eps_q");
    g.a = p.get_number("a");
    g.gamma = p.get_number("gamma");
    g.sigma1 = p.get_number("sigma1");
    g.sigma2 = p.get_number("sigma2");
    g.psi_hat0 = p.get_number("psi_hat0");
  } else {
    FtsmcSe3Params& g = c.fts;
    g.p_s = p.get_number("p_s");
    g.eps = p.get_number("eps");
    g.C1 = rot_trans(p.get_number("C1_rot"), p.get_number("C1_trans"));
    g.C2 = rot_trans(p.get_number("C2_rot"), p.get_number("C2_trans"));
    g.K_a = Vec6::Constant(p.get_number("K_a"));
    g.K_b = Vec6::Constant(p.get_number("K_b"));
    g.rho = p.get_number("rho_reach");
    g.k_s = p.get_number("k_s");
    g.phi = p.get_number("phi");
  }
  return c;
}

//! True when every parameter that changes the physics, the law or the measurement is at its
//! default (the state, T, the integrator and the CSV may differ): the spec's prototype table
//! (Appendix C.3) then applies and the claims get a verdict.
bool prototype_conditions(const ParamSet& p) {
  static const std::set<std::string> free = {"initial_state", "T_s",        "integrator", "rtol",
                                             "atol",          "rk4_step_s", "record_every", "companion"};
  for (const auto& q : p)
    if (q.overridden && !free.count(q.key) && format_value(q) != format_value(q.kind, q.default_value))
      return false;
  return true;
}

// ------------------------------------------------------------------ simulation
struct Outcome {
  // per control tick t_k, k = 0..N-1 (the ticks at which a command was computed)
  std::vector<double> t, att_deg, pos_m, rate_deg_s, vel_m_s, psi;
  std::vector<Vec6> u_c;
  double eta0_att_deg = NAN, eta0_pos_m = NAN, Re0_m = NAN, beta_norm_peak_m = 0.0;
  double torque_max = 0.0, force_max = 0.0, torque_cmd_peak = 0.0, force_cmd_peak = 0.0;
  double psi_final = NAN;
  std::uint64_t tx = 0;
  long saturated = 0, nonok = 0, steps = 0;
};

class Se3Loop {
 public:
  Se3Loop(const Se3Config& c, Law law) : c_(c), law_(law) {}

  Outcome run(const std::string& csv_path) const {
    const Se3ScenarioParams& sp = c_.sp;
    Se3SpacecraftParams truth_p;
    if (se3_chaser_truth_params(sp, truth_p) != Status::ok)
      throw ParamError("dJ_ratio, dm_ratio must be in [0, 1)");
    const Se3Spacecraft chaser(truth_p), target(se3_target_params(sp)),
        nominal(se3_chaser_nominal_params(sp));
    if (chaser.status() != Status::ok || target.status() != Status::ok || nominal.status() != Status::ok)
      throw ParamError("J_target_kgm2, J0_kgm2 must be SPD and the masses > 0");
    Se3SpacecraftState o0;
    if (se3_target_initial_state(sp, o0) != Status::ok) throw ParamError("altitude_m/inclination_deg rejected");
    const Se3SpacecraftState c0 =
        se3_chaser_initial_state(o0, kSe3InitialPoses[static_cast<std::size_t>(c_.state - 1)]);

    std::optional<PrescribedTimeSe3> ptc;
    std::optional<FtsmcSe3> fts;
    if (law_ == Law::ptc) {
      ptc.emplace(c_.ptc, nominal.params());
      if (ptc->status() != Status::ok) throw ParamError("BsPdTC gains rejected (0 < p < 1, T > 0, a > 0, ...)");
    } else {
      fts.emplace(c_.fts, nominal.params());
      if (fts->status() != Status::ok) throw ParamError("FTSMC gains rejected (K >= 0, rho > 0, phi > 0, ...)");
    }
    CompositeQuantizer<6> Q(c_.q);
    if (Q.status() != Status::ok) throw ParamError("quantizer parameters rejected");
    const Vec6 limit = se3_actuator_limits(sp);

    const Se3PairPlant plant{&chaser, &target, &sp};
    Se3PairPlant::State x;
    Se3PairPlant::put(x, 0, c0);
    Se3PairPlant::put(x, Se3PairPlant::kBody, o0);

    std::unique_ptr<CsvRecorder> csv;
    if (!csv_path.empty()) csv = std::make_unique<CsvRecorder>(csv_path, columns(), c_.record_every);

    const std::size_t n_ticks = interval_count(c_.duration, c_.period);
    Outcome out;
    std::size_t sample = 0;
    Vec6 cmd = Vec6::Zero(), last_uc = Vec6::Zero();
    double psi_used = NAN;
    std::vector<double> row;

    auto control = [&](double, const Se3PairPlant::State& xs, Vec6& u) {
      const Se3SpacecraftState c = Se3PairPlant::body(xs, 0), o = Se3PairPlant::body(xs, Se3PairPlant::kBody);
      Se3DesiredState d;
      if (se3_desired_state(target, o, sp, d) != Status::ok) throw SimError("se3: target state invalid");
      if (ptc) psi_used = ptc->psi_hat();
      const Status s = ptc ? ptc->step(c, d, cmd) : fts->step(c, d, cmd);
      if (s != Status::ok) ++out.nonok;
      Vec6 uc;
      if (c_.quantize) {
        const Status q = saturate_then_quantize<6>(cmd, limit, Q, uc);
        if (q == Status::saturated) ++out.saturated;
        else if (q != Status::ok) throw SimError("se3: quantizer rejected the command");
      } else {
        uc = cmd;
        if (saturate_each<6>(uc, limit) > 0) ++out.saturated;
        for (int i = 0; i < 6; ++i)  // same counting rule as the quantizer (spec §A.3)
          if (sample == 0 || uc(i) != last_uc(i)) ++out.tx;
      }
      last_uc = uc;
      u = uc;
    };
    auto observe = [&](double t, const Se3PairPlant::State& xs, const Vec6& u) {
      const Se3SpacecraftState c = Se3PairPlant::body(xs, 0), o = Se3PairPlant::body(xs, Se3PairPlant::kBody);
      Se3DesiredState d;
      Se3TrackingError e;
      if (se3_desired_state(target, o, sp, d) != Status::ok || se3_tracking_error(c, d, nominal, e) != Status::ok)
        throw SimError("se3: closed loop diverged at t = " + format_number(t) + " s");
      const Vec3 th = e.eta.head<3>() * kRad2Deg, be = e.eta.tail<3>();
      const Vec3 we = e.xi_e.head<3>() * kRad2Deg, ve = e.xi_e.tail<3>();
      if (sample == 0) {
        out.eta0_att_deg = th.norm();
        out.eta0_pos_m = be.norm();
        out.Re0_m = (c.R_N - d.R_N).norm();
      }
      if (sample < n_ticks) {  // a tick with a command (the final call at t_end has none)
        out.t.push_back(t);
        out.att_deg.push_back(th.cwiseAbs().maxCoeff());
        out.pos_m.push_back(be.cwiseAbs().maxCoeff());
        out.rate_deg_s.push_back(we.cwiseAbs().maxCoeff());
        out.vel_m_s.push_back(ve.cwiseAbs().maxCoeff());
        if (ptc) out.psi.push_back(psi_used);
        out.u_c.push_back(u);
        out.beta_norm_peak_m = std::max(out.beta_norm_peak_m, be.norm());
        out.torque_max = std::max(out.torque_max, u.head<3>().cwiseAbs().maxCoeff());
        out.force_max = std::max(out.force_max, u.tail<3>().cwiseAbs().maxCoeff());
        out.torque_cmd_peak = std::max(out.torque_cmd_peak, cmd.head<3>().cwiseAbs().maxCoeff());
        out.force_cmd_peak = std::max(out.force_cmd_peak, cmd.tail<3>().cwiseAbs().maxCoeff());
      }
      if (csv) {
        row.assign({t});
        for (int i = 0; i < 3; ++i) row.push_back(th(i));
        for (int i = 0; i < 3; ++i) row.push_back(be(i));
        for (int i = 0; i < 3; ++i) row.push_back(we(i));
        for (int i = 0; i < 3; ++i) row.push_back(ve(i));
        row.push_back(th.cwiseAbs().maxCoeff());
        row.push_back(be.cwiseAbs().maxCoeff());
        for (int i = 0; i < 6; ++i) row.push_back(u(i));
        for (int i = 0; i < 6; ++i) row.push_back(cmd(i));
        row.push_back(static_cast<double>(c_.quantize ? Q.transmissions() : out.tx));
        // ψ̂ used in u3 at this tick (before its update); at t_end the last updated value.
        if (ptc) row.push_back(sample < n_ticks ? psi_used : ptc->psi_hat());
        if (sample == n_ticks) csv->record_final(row.data()); else csv->record(row.data());
      }
      ++sample;
    };

    SampledDataOptions opt;
    opt.t_end = c_.duration;
    opt.sample_period = c_.period;
    if (c_.rk4) {
      Rk4Integrator<Se3PairPlant> integ(plant, c_.rk4_step);
      run_sampled_data(plant, integ, x, opt, control, observe);
      out.steps = integ.steps();
    } else {
      CvodeOptions co;
      co.method = CvodeOptions::Method::adams_fixed_point;
      co.rtol = c_.rtol;
      co.atol = c_.atol;
      CvodeIntegrator<Se3PairPlant> integ(plant, co);
      run_sampled_data(plant, integ, x, opt, control, observe);
      out.steps = integ.steps();
    }
    if (csv) csv->close();
    if (c_.quantize) out.tx = Q.transmissions();
    if (ptc) out.psi_final = ptc->psi_hat();
    return out;
  }

  std::vector<Column> columns() const {
    std::vector<Column> c{{"t", "s"}};
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("theta_") + a + "_deg", "deg"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("beta_") + a + "_m", "m"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("omega_e_") + a + "_deg_s", "deg/s"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("v_e_") + a + "_m_s", "m/s"});
    c.push_back({"att_err_max_deg", "deg"});
    c.push_back({"pos_err_max_m", "m"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("M_c_") + a + "_Nm", "N m"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("F_c_") + a + "_N", "N"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("M_cmd_") + a + "_Nm", "N m"});
    for (const char* a : {"x", "y", "z"}) c.push_back({std::string("F_cmd_") + a + "_N", "N"});
    c.push_back({"transmissions", "-"});
    if (law_ == Law::ptc) c.push_back({"psi_hat", "-"});
    return c;
  }

 private:
  Se3Config c_;
  Law law_;
};

// ------------------------------------------------------------------ metrics
struct Dwell {
  double max_torque_s = NAN, max_force_s = NAN, steady_share_multi = NAN, steady_mean_s = NAN;
};

//! Runs of a constant applied command per channel. Early: ticks with t < 60 s (spec A.9 #9), runs
//! cut at 60 s. Steady: ticks with t >= 100 s, the share of runs longer than one tick and the
//! mean run length (all six channels).
Dwell dwell_times(const Outcome& o, double h) {
  Dwell d;
  auto runs = [&](int ch, double t0, double t1) {
    std::vector<long> r;
    long len = 0;
    for (std::size_t k = 0; k < o.t.size(); ++k) {
      if (o.t[k] < t0 || o.t[k] >= t1) continue;
      if (len > 0 && o.u_c[k](ch) == o.u_c[k - 1](ch)) {
        ++len;
      } else {
        if (len > 0) r.push_back(len);
        len = 1;
      }
    }
    if (len > 0) r.push_back(len);
    return r;
  };
  long mt = 0, mf = 0, steady_n = 0, steady_multi = 0, steady_ticks = 0;
  bool early = false;
  for (int ch = 0; ch < 6; ++ch) {
    for (long len : runs(ch, -INFINITY, 60.0)) {
      early = true;
      (ch < 3 ? mt : mf) = std::max(ch < 3 ? mt : mf, len);
    }
    for (long len : runs(ch, 100.0, INFINITY)) {
      ++steady_n;
      steady_ticks += len;
      if (len > 1) ++steady_multi;
    }
  }
  if (early) {
    d.max_torque_s = mt * h;
    d.max_force_s = mf * h;
  }
  if (steady_n > 0) {
    d.steady_share_multi = double(steady_multi) / double(steady_n);
    d.steady_mean_s = h * double(steady_ticks) / double(steady_n);
  }
  return d;
}

double window_max(const std::vector<double>& t, const std::vector<double>& y, double a, double b) {
  return t.empty() ? NAN : metrics::max_abs_in_window(t, y, a, b);
}

//! The spec's prototype (Appendix C.3) and paper (A.9) values for one run, when it has a row.
struct Reference {
  double att_s, pos_s, att_ss_deg, pos_ss_m, tx, psi_peak;
  double paper_att_s, paper_pos_s;  // NaN when the paper gives none
};
std::optional<Reference> prototype_row(Law law, int state, double T) {
  if (law == Law::ftsmc) {
    if (state == 1) return Reference{23.6, 50.8, 1.3e-3, 3.6e-6, 6416, NAN, NAN, 89.7};
    if (state == 4) return Reference{31.6, 105.8, 1.1e-3, 3.5e-6, 5540, NAN, NAN, 127.6};
    return std::nullopt;
  }
  if (T == 120.0) {
    switch (state) {
      case 1: return Reference{30.5, 57.1, 8.6e-3, 1.3e-5, 2957, 3.2e-4, 75.8, 90.5};
      case 2: return Reference{39.6, 74.8, 8.7e-3, 1.3e-5, 3027, 6.6e-4, NAN, NAN};
      case 3: return Reference{62.4, 86.5, 8.6e-3, 1.3e-5, 2905, 9.2e-4, NAN, 95.2};
      default: return Reference{61.8, 116.4, 8.8e-3, 1.3e-5, 3049, 1.8e-3, NAN, 96.8};
    }
  }
  if (state != 1) return std::nullopt;
  if (T == 80.0) return Reference{30.4, 46.5, 4.3e-3, 6.8e-6, 3330, 7.0e-4, NAN, 75.6};
  if (T == 100.0) return Reference{29.5, 51.0, 6.3e-3, 9.8e-6, 3125, 4.5e-4, NAN, 82.8};
  if (T == 140.0) return Reference{31.1, 62.8, 1.13e-2, 1.65e-5, 3060, 2.5e-4, NAN, 94.5};
  return std::nullopt;
}

bool within15(double ours, double proto) { return std::abs(ours - proto) <= 0.15 * std::abs(proto); }
bool within10s(double ours, double proto) { return std::abs(ours - proto) <= 10.0; }

std::string fmt(const char* f, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buf[240];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

std::optional<bool> verdict(bool applies, bool holds) {
  return applies ? std::optional<bool>(holds) : std::nullopt;
}

class Se3Scenario final : public Scenario {
 public:
  explicit Se3Scenario(Law law) : law_(law) {}
  std::string name() const override { return law_ == Law::ptc ? "se3-ptc" : "se3-ftsmc"; }
  std::string description() const override {
    return law_ == Law::ptc
               ? "seed 003: SE(3) chaser/target pose tracking, prescribed-time backstepping (BsPdTC) "
                 "with quantization compensation and adaptive bound, sat + composite quantizer, 8 Hz, 200 s"
               : "seed 003: SE(3) chaser/target pose tracking, FTSMC baseline through the same sat + "
                 "quantizer chain, 8 Hz, 200 s";
  }
  void declare(ParamSet& p) const override { declare_common(p, law_); }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    const Se3Config cfg = make_config(p, law_);
    const Outcome o = Se3Loop(cfg, law_).run(ctx.csv_path);
    const double h = cfg.period;
    const double settle_att = metrics::settling_time(o.t, o.att_deg, cfg.band_att_deg);
    const double settle_pos = metrics::settling_time(o.t, o.pos_m, cfg.band_pos_m);
    const double settle_att_fine = metrics::settling_time(o.t, o.att_deg, 0.01);  // A.9: report both bands
    const double att_ss = window_max(o.t, o.att_deg, cfg.window0, cfg.window1);
    const double pos_ss = window_max(o.t, o.pos_m, cfg.window0, cfg.window1);
    const double rate_ss = window_max(o.t, o.rate_deg_s, cfg.window0, cfg.window1);
    const double vel_ss = window_max(o.t, o.vel_m_s, cfg.window0, cfg.window1);
    const double tx_unq = 6.0 * static_cast<double>(o.t.size());
    const Dwell dw = dwell_times(o, h);

    RunResult r;
    r.metrics = {{"settle_att_s", settle_att},
                 {"settle_pos_s", settle_pos},
                 {"settle_s", std::isnan(settle_att) || std::isnan(settle_pos) ? NAN
                                                                                : std::max(settle_att, settle_pos)},
                 {"att_err_ss_deg", att_ss},
                 {"pos_err_ss_m", pos_ss},
                 {"rate_err_ss_deg_s", rate_ss},
                 {"vel_err_ss_m_s", vel_ss},
                 {"transmissions", double(o.tx)},
                 {"transmissions_unquantized", tx_unq},
                 {"tx_reduction", tx_unq > 0 ? 1.0 - double(o.tx) / tx_unq : NAN},
                 {"force_max_N", o.force_max},
                 {"torque_max_Nm", o.torque_max}};
    double psi_peak = NAN, psi_peak_t = NAN;
    if (law_ == Law::ptc) {
      for (std::size_t k = 0; k < o.psi.size(); ++k)
        if (!(o.psi[k] <= psi_peak)) psi_peak = o.psi[k], psi_peak_t = o.t[k];
      r.metrics.push_back({"disturbance_bound_est_final", o.psi_final});
      r.metrics.push_back({"psi_hat_peak", psi_peak});
      r.metrics.push_back({"psi_hat_peak_time_s", psi_peak_t});
    }
    const std::vector<std::pair<std::string, double>> more = {
        {"settle_att_s_band001", settle_att_fine},
        {"eta0_att_deg", o.eta0_att_deg},
        {"eta0_pos_m", o.eta0_pos_m},
        {"Re0_m", o.Re0_m},
        {"beta_norm_peak_m", o.beta_norm_peak_m},
        {"max_dwell_torque_s", dw.max_torque_s},
        {"max_dwell_force_s", dw.max_force_s},
        {"steady_dwell_share_multi_tick", dw.steady_share_multi},
        {"steady_dwell_mean_s", dw.steady_mean_s},
        {"torque_cmd_peak_Nm", o.torque_cmd_peak},
        {"force_cmd_peak_N", o.force_cmd_peak},
        {"saturated_ticks", double(o.saturated)},
        {"nonok_steps", double(o.nonok)},
        {"integrator_steps", double(o.steps)}};
    r.metrics.insert(r.metrics.end(), more.begin(), more.end());

    const bool complete = cfg.duration >= cfg.window1 && !o.t.empty();
    const bool proto_cond = prototype_conditions(p) && complete;
    const double T = cfg.ptc.T;
    const std::optional<Reference> ref = proto_cond ? prototype_row(law_, cfg.state, law_ == Law::ptc ? T : 120.0)
                                                    : std::nullopt;
    const std::string run_tag = fmt("state %.0f", cfg.state) + (law_ == Law::ptc ? fmt(", T = %.0f s", T) : "");
    if (law_ == Law::ptc) {
      ptc_claims(r, cfg, o, ref, complete, run_tag, settle_att, settle_pos, att_ss, pos_ss, rate_ss, vel_ss,
                 psi_peak, psi_peak_t);
    } else {
      ftsmc_claims(r, p, cfg, o, ref, complete, run_tag, settle_att, settle_pos, settle_att_fine);
    }
    r.claims.push_back({"check", "commands within the actuator limits; control law never failed",
                        fmt("|M_i| <= %.3g N m, |F_i| <= %.3g N, 0 failed ticks", cfg.sp.M_max, cfg.sp.F_max),
                        fmt("%.3g N m, %.3g N, %.0f failed ticks", o.torque_max, o.force_max, double(o.nonok)),
                        o.torque_max <= cfg.sp.M_max && o.force_max <= cfg.sp.F_max && o.nonok == 0});
    plots(r);
    return r;
  }

 private:
  void ptc_claims(RunResult& r, const Se3Config& cfg, const Outcome& o, const std::optional<Reference>& ref,
                  bool complete, const std::string& tag, double s_att, double s_pos, double att_ss, double pos_ss,
                  double rate_ss, double vel_ss, double psi_peak, double psi_peak_t) const {
    const double T = cfg.ptc.T;
    const bool base = ref && cfg.state == 1 && T == 120.0;  // the A.9 rows for state 1, T = 120 s
    const std::string na = "no prototype row for this run: informative";
    auto paper = [](double v, const char* unit) { return std::isnan(v) ? std::string("-") : fmt("%.1f", v) + unit; };
    // 1: attitude settling.
    r.claims.push_back(
        {"paper", "A.9-1 attitude converges (" + tag + ")",
         ref ? "paper " + paper(ref->paper_att_s, " s") + "; proto " + fmt("%.1f s", ref->att_s) +
                   "; criterion proto +-10 s"
             : na,
         fmt("t_s(theta) = %.2f s (band %.3g deg)", s_att, cfg.band_att_deg),
         verdict(bool(ref), within10s(s_att, ref ? ref->att_s : 0))});
    // 2 / 6 / 7: position settling before T.
    r.claims.push_back(
        {"paper", "A.9-2/6/7 position converges before the prescribed time T (" + tag + ")",
         (ref ? "paper " + paper(ref->paper_pos_s, " s") + "; proto " + fmt("%.1f s", ref->pos_s) +
                    "; criterion proto +-10 s and "
              : std::string("hard requirement: ")) + fmt("t_s(beta) < T = %.0f s", T),
         fmt("t_s(beta) = %.2f s (band %.3g m)", s_pos, cfg.band_pos_m),
         verdict(complete, s_pos < T && (!ref || within10s(s_pos, ref->pos_s)))});
    // 3, 4: steady attitude / position.
    r.claims.push_back({"paper", "A.9-3 steady attitude error, max |theta_i| over [150, 200] s",
                        ref ? "paper <= 3.72e-3 deg (not met by the reconstruction); proto " +
                                  fmt("%.3g deg", ref->att_ss_deg) + "; criterion proto +-15%"
                            : na,
                        fmt("%.3g deg", att_ss), verdict(bool(ref), within15(att_ss, ref ? ref->att_ss_deg : 0))});
    r.claims.push_back({"paper", "A.9-4 steady position error, max |beta_i| over [150, 200] s",
                        ref ? "paper <= 3.28e-5 m; proto " + fmt("%.3g m", ref->pos_ss_m) + "; criterion proto +-15%"
                            : na,
                        fmt("%.3g m", pos_ss), verdict(bool(ref), within15(pos_ss, ref ? ref->pos_ss_m : 0))});
    // 5: steady rate / velocity (proto only for state 1, T = 120 s).
    r.claims.push_back({"paper", "A.9-5 steady rate / velocity errors, max |omega_e,i|, max |v_e,i|",
                        base ? "paper 1.60e-3 deg/s, 1.02e-5 m/s; proto 3.5e-3 deg/s, 5.5e-6 m/s; criterion proto +-15%"
                             : "paper 1.60e-3 deg/s, 1.02e-5 m/s (state 1, T = 120 s): informative here",
                        fmt("%.3g deg/s, %.3g m/s", rate_ss, vel_ss),
                        verdict(base, within15(rate_ss, 3.5e-3) && within15(vel_ss, 5.5e-6))});
    // 8: transmissions.
    const bool tx_hard = base && cfg.quantize;
    r.claims.push_back(
        {"paper", "A.9-8 transmissions over 200 s",
         ref ? "paper 9600 -> ~2863 (>70% less); proto " + fmt("%.0f", ref->tx) + "; criterion proto +-15%" +
                   (tx_hard ? " and N_tx <= 0.32 x 9600 = 3072" : "")
             : std::string("paper ~2863 of 9600: ") + na,
         fmt("N_tx = %.0f of %.0f (%.1f%% less)", double(o.tx), 6.0 * o.t.size(),
             o.t.empty() ? NAN : 100.0 * (1.0 - double(o.tx) / (6.0 * o.t.size()))),
         verdict(bool(ref), within15(double(o.tx), ref ? ref->tx : 0) && (!tx_hard || o.tx <= 3072))});
    // 10: ψ̂ overshoots, then decays before convergence.
    r.claims.push_back(
        {"paper", "A.9-10 psi_hat overshoots, then decays before convergence (Fig. 7)",
         ref ? "Fig. 7 (no numbers); proto peak " + fmt("%.2g", ref->psi_peak) +
                   "; criterion peak proto +-15%, peak before t_s(beta), final < 1% of peak"
             : na,
         fmt("peak %.3g at %.2f s, final %.3g", psi_peak, psi_peak_t, o.psi_final),
         verdict(bool(ref), ref && within15(psi_peak, ref->psi_peak) && psi_peak_t < s_pos &&
                                o.psi_final < 0.01 * psi_peak)});
    // 14: initial errors (the paper gives state 4).
    const bool s4 = cfg.state == 4 && cfg.sp.r_chi == Se3ScenarioParams{}.r_chi;
    r.claims.push_back(
        {"paper", "A.9-14 initial errors ||theta(0)||, ||beta(0)|| (" + tag + ")",
         std::string("paper state 4: 165.5 deg, ~79.9 m; proto 165.48 deg, 71.2 m; criterion (state 4) ") +
             "|theta| within 0.05 deg of 165.48, ||beta|| in [55, 81] m (A.10-9)" + (s4 ? "" : ": informative here"),
         fmt("%.2f deg, %.2f m (||R_e(0)|| = %.2f m)", o.eta0_att_deg, o.eta0_pos_m, o.Re0_m),
         verdict(s4, std::abs(o.eta0_att_deg - 165.48) < 0.05 && o.eta0_pos_m >= 55.0 && o.eta0_pos_m <= 81.0)});
  }

  void ftsmc_claims(RunResult& r, const ParamSet& p, const Se3Config& cfg, const Outcome& o,
                    const std::optional<Reference>& ref, bool complete, const std::string& tag,
                    double s_att, double s_pos, double s_att_fine) const {
    double ptc_pos = NAN, ptc_tx = NAN;
    if (p.get_name("companion") == "run") {
      Se3Config pc = common_config(p);  // Table 1 gains, T = 120 s, same state and conditions
      const Outcome c = Se3Loop(pc, Law::ptc).run("");
      ptc_pos = metrics::settling_time(c.t, c.pos_m, pc.band_pos_m);
      ptc_tx = double(c.tx);
      r.metrics.push_back({"ptc_settle_pos_s", ptc_pos});
      r.metrics.push_back({"ptc_transmissions", ptc_tx});
    }
    r.claims.push_back(
        {"paper", "A.9-12 FTSMC position settles no later than the BsPdTC (" + tag + ")",
         cfg.state == 1 ? "paper 89.7 vs 90.5 s; proto 50.8 vs 57.1 s; criterion t_s,FTSMC(beta) <= t_s,BsPdTC(beta)"
                        : "paper: state 1 only; informative here",
         fmt("FTSMC %.2f s, BsPdTC %.2f s", s_pos, ptc_pos),
         verdict(complete && cfg.state == 1 && !std::isnan(ptc_pos), s_pos <= ptc_pos)});
    r.claims.push_back({"paper", "A.9-12 FTSMC state 4 needs more than 120 s; spread over states ~40 s (informational)",
                        "paper 127.6 s (state 4), 116.5 s (state 3); proto 105.8 s (state 4): not reproduced",
                        fmt("t_s(beta) = %.2f s (", s_pos) + tag + ")", std::nullopt});
    r.claims.push_back(
        {"paper", "FTSMC settling and steady errors (" + tag + ", informational)",
         ref ? fmt("proto t_s(theta) %.1f s (0.01 deg band), t_s(beta) %.1f s, ", ref->att_s, ref->pos_s) +
                   fmt("steady %.2g deg / %.2g m", ref->att_ss_deg, ref->pos_ss_m)
             : std::string("no prototype row for this run"),
         fmt("t_s(theta) %.2f s (0.01 deg band; %.2f s at 0.02 deg), t_s(beta) %.2f s", s_att_fine, s_att, s_pos),
         std::nullopt});
    r.claims.push_back({"paper", "FTSMC transmissions (informational)",
                        ref ? fmt("proto %.0f, about 2x the BsPdTC", ref->tx) : std::string("proto 6416 (state 1)"),
                        fmt("N_tx = %.0f", double(o.tx)) +
                            (std::isnan(ptc_tx) ? std::string() : fmt(" (BsPdTC %.0f)", ptc_tx)),
                        std::nullopt});
  }

  void plots(RunResult& r) const {
    const std::string n = name();
    PlotSpec att{n + "-attitude-error.png", "Attitude error theta = log(C_e) (exponential coordinates)", "t",
                 {"theta_x_deg", "theta_y_deg", "theta_z_deg"}, "theta [deg]"};
    PlotSpec pos{n + "-position-error.png", "Position error beta (exponential coordinates)", "t",
                 {"beta_x_m", "beta_y_m", "beta_z_m"}, "beta [m]"};
    PlotSpec att_log{n + "-attitude-error-max.png", "max |theta_i| and the 0.02 deg settling band", "t",
                     {"att_err_max_deg"}, "[deg]", true};
    att_log.hline = {{0.02, "band 0.02 deg"}};
    PlotSpec pos_log{n + "-position-error-max.png", "max |beta_i| and the 1e-4 m settling band", "t",
                     {"pos_err_max_m"}, "[m]", true};
    pos_log.hline = {{1e-4, "band 1e-4 m"}};
    r.plots = {att, pos, att_log, pos_log,
               {n + "-rate-error.png", "Angular-velocity error omega_e", "t",
                {"omega_e_x_deg_s", "omega_e_y_deg_s", "omega_e_z_deg_s"}, "[deg/s]"},
               {n + "-velocity-error.png", "Velocity error v_e", "t", {"v_e_x_m_s", "v_e_y_m_s", "v_e_z_m_s"}, "[m/s]"},
               {n + "-torque.png", "Applied (saturated, quantized) torque", "t", {"M_c_x_Nm", "M_c_y_Nm", "M_c_z_Nm"},
                "M_c [N m]"},
               {n + "-force.png", "Applied (saturated, quantized) force", "t", {"F_c_x_N", "F_c_y_N", "F_c_z_N"},
                "F_c [N]"},
               {n + "-transmissions.png", "Cumulative transmissions", "t", {"transmissions"}, "N_tx [-]"}};
    if (law_ == Law::ptc)
      r.plots.push_back({n + "-psi-hat.png", "Adaptive squared-bound estimate psi_hat (Fig. 7)", "t", {"psi_hat"},
                         "psi_hat [-]", true});
  }

  Law law_;
};

}  // namespace

std::unique_ptr<Scenario> make_se3_ptc() { return std::make_unique<Se3Scenario>(Law::ptc); }
std::unique_ptr<Scenario> make_se3_ftsmc() { return std::make_unique<Se3Scenario>(Law::ftsmc); }

}  // namespace adcs::sim
