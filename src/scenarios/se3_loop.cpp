// Seed 003 closed loop (spec §A.5, §A.8): chaser and target rigid spacecraft on SE(3) in a 400 km,
// 45° circular orbit (point-mass gravity, J2, gravity gradient); the chaser holds the V-bar point
// 5 m behind the target under the GIVEN disturbance, ±12 % / ±3 % inertia uncertainty and
// actuator limits, 8 Hz, 200 s, under the BsPdTC (control/prescribed_time_se3.hpp, spec §A.5) or
// the FTSMC baseline (control/ftsmc_se3.hpp, spec §A.6).
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
// PTC step) → sat → Q (quantize=1) → ZOH. Outcome keeps, per tick, the largest |θ_i|, |β_i|,
// |ω_e,i|, |v_e,i| and the applied command u_c. Every value the paper does not give is a parameter with its spec tag ([A] assumed).
#include "scenarios/se3_loop.hpp"

#include "scenarios/truth_plants.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>

#include "adcs/actuator/saturation.hpp"
#include "adcs/math/quaternion.hpp"
#include "sim/closed_loop.hpp"
#include "sim/intervals.hpp"
#include "sim/metrics.hpp"
#include "sim/recorder.hpp"
#include "sim/law_at_scalar.hpp"
#include "sim/sim_error.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace adcs::sim::se3 {
namespace ADCS_UNITY_ID {

constexpr const char* kA8 = "seed 003 §4 (spec A.8)";
constexpr const char* kT1 = "spec A.8 Table 1 [A]";
constexpr const char* kT2 = "spec A.8 Table 2 [A]";
constexpr const char* kA9 = "spec A.9 [A]";


std::vector<std::vector<double>> to_rows(const Mat3& m) {
  std::vector<std::vector<double>> v(3, std::vector<double>(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[i][j] = m(i, j);
  return v;
}


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

    // The law in the scalar of `--set scalar` (issue 19) behind the loop's double interface
    // (sim/law_at_scalar.hpp): parameters and inputs cast into it, the wrench back; the plant and
    // the actuation stage stay double.
    std::optional<LawAtScalar<PrescribedTimeSe3T>> ptc;
    std::optional<LawAtScalar<FtsmcSe3T>> fts;
    if (law_ == Law::ptc) {
      PrescribedTimeSe3Params pp = c_.ptc;
      pp.nominal = nominal.params();
      ptc.emplace(LawAtScalar<PrescribedTimeSe3T>::Params{pp, c_.single});
      if (ptc->status() != Status::ok) throw ParamError("BsPdTC gains rejected (0 < p < 1, T > 0, a > 0, ...)");
    } else {
      FtsmcSe3Params fp = c_.fts;
      fp.nominal = nominal.params();
      fts.emplace(LawAtScalar<FtsmcSe3T>::Params{fp, c_.single});
      if (fts->status() != Status::ok) throw ParamError("FTSMC gains rejected (K >= 0, rho > 0, phi > 0, ...)");
    }
    // ψ̂ in double, from whichever scalar ran (exact: float to double).
    auto psi_hat = [&] { return ptc->visit([](const auto& l) noexcept { return static_cast<double>(l.psi_hat()); }); };
    // Actuation (spec §A.3): sat → Q, or sat alone with quantize=0.
    SaturatedQuantizer<6> quantized(SaturatedQuantizerParams<6>{c_.q, se3_actuator_limits(sp)});
    Saturation<6> saturated_only(SaturationParams<6>{se3_actuator_limits(sp)});
    if (quantized.status() != Status::ok) throw ParamError("quantizer parameters rejected");
    const CompositeQuantizer<6>& Q = quantized.quantizer();

    const Se3PairPlant plant{&chaser, &target, &sp};
    Se3PairPlant::State x;
    Se3PairPlant::put(x, 0, c0);
    Se3PairPlant::put(x, Se3PairPlant::kBody, o0);

    std::unique_ptr<CsvRecorder> csv;
    if (!csv_path.empty()) csv = std::make_unique<CsvRecorder>(csv_path, columns(), c_.record_every);

    const std::size_t n_ticks = interval_count(c_.duration, c_.period);
    Outcome out;
    std::size_t sample = 0;
    Vec6 last_uc = Vec6::Zero();
    double psi_used = NAN;
    std::vector<double> row;

    // The loop (sim/closed_loop.hpp), per tick (spec §A.5): the desired state from the target
    // model and the chaser's perfect state → the law (ψ̂ updated inside the PTC step) → the
    // actuation stage → the chaser's wrench, held (ZOH).
    auto sensors = [&](double, const Se3PairPlant::State& xs) {
      const Se3SpacecraftState c = Se3PairPlant::body(xs, 0), o = Se3PairPlant::body(xs, Se3PairPlant::kBody);
      Se3DesiredState d;
      if (se3_desired_state(target, o, sp, d) != Status::ok) throw SimError("se3: target state invalid");
      if (ptc) psi_used = psi_hat();
      return Se3TrackingInput{c, d};
    };
    auto to_actuation = [](double, const Se3PairPlant::State&, const Wrench& w) { return Vec6(w.stacked()); };
    auto to_plant = [](double, const Se3PairPlant::State&, const Vec6& uc, Vec6& u) { u = uc; };
    auto observe = [&](const auto& s) {
      const double t = s.t_s;
      const Se3PairPlant::State& xs = s.x;
      const Vec6& u = s.u;
      const Vec6 cmd = s.command.stacked();
      if (!s.final) {  // once per tick
        if (s.controller_status != Status::ok) ++out.nonok;
        if (s.actuation_status == Status::saturated) ++out.saturated;
        else if (s.actuation_status != Status::ok) throw SimError("se3: the actuation stage rejected the command");
        if (!c_.quantize)
          for (int i = 0; i < 6; ++i)  // same counting rule as the quantizer (spec §A.3)
            if (sample == 0 || u(i) != last_uc(i)) ++out.tx;
        last_uc = u;
      }
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
        if (ptc) row.push_back(sample < n_ticks ? psi_used : psi_hat());
        csv->record_row(row, s.final);
      }
      ++sample;
    };

    SampledDataOptions opt;
    opt.t_end = c_.duration;
    opt.sample_period = c_.period;
    IntegratorChoice ic;  // CVODE Adams + fixed point (the truth), or RK4 as the cross-check
    ic.kind = c_.rk4 ? IntegratorChoice::Kind::rk4 : IntegratorChoice::Kind::adams;
    ic.rtol = c_.rtol;
    ic.atol = c_.atol;
    ic.rk4_step_s = c_.rk4_step;
    auto fly = [&](auto& law) {
      out.steps = c_.quantize ? closed_loop(plant, x, opt, ic, sensors, law, to_actuation, quantized, to_plant, observe)
                              : closed_loop(plant, x, opt, ic, sensors, law, to_actuation, saturated_only, to_plant, observe);
    };
    if (ptc) fly(*ptc); else fly(*fts);
    if (csv) csv->close();
    if (c_.quantize) out.tx = Q.transmissions();
    if (ptc) out.psi_final = psi_hat();
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

Vec6 rot_trans(double rot, double trans) {
  Vec6 v;
  v << Vec3::Constant(rot), Vec3::Constant(trans);
  return v;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

void declare_environment(ParamSet& p) {
  const Se3ScenarioParams d;
  p.number("duration_s", d.horizon, "s", "seed 003 §4: 200 s (1600 commands)");
  p.number("control_period_s", d.control_period, "s", "seed 003 §4: 8 Hz");
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
}

void declare_ptc_gains(ParamSet& p) {
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
}

void declare_ftsmc_gains(ParamSet& p) {
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
}

Se3Config common_config(const ParamSet& p) {
  Se3Config c;
  Se3ScenarioParams& s = c.sp;
  c.duration = p.get_number("duration_s");
  c.period = p.get_number("control_period_s");
  if (!(c.duration >= 0.0)) throw ParamError("duration_s must be >= 0");
  if (!(c.period > 0.0)) throw ParamError("control_period_s must be > 0");
  c.state = p.has("initial_state") ? integer_in(p, "initial_state", {1, 2, 3, 4}) : 1;
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
  c.single = p.get_name("scalar") == "float";
  c.ptc.period_s = c.period;
  c.fts.period_s = c.period;
  c.ptc.zeta = quantization_compensation_gain(c.q, 1.05);
  return c;
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

bool prototype_conditions(const ParamSet& p) {
  // scalar: the claims are judged on the float law too (issue 19: which claims hold in float).
  static const std::set<std::string> free = {"initial_state", "T_s",        "integrator", "rtol",
                                             "atol",          "rk4_step_s", "record_every", "companion",
                                             "T_sweep_s",     "scalar"};
  for (const auto& q : p)
    if (q.overridden && !free.count(q.key) && format_value(q) != format_value(q.kind, q.default_value))
      return false;
  return true;
}


Outcome simulate(const Se3Config& c, Law law, const std::string& csv_path) {
  return Se3Loop(c, law).run(csv_path);
}

Steady steady_bounds(const Outcome& o, const Se3Config& c) {
  auto win = [&](const std::vector<double>& y) {
    return o.t.empty() ? NAN : metrics::max_abs_in_window(o.t, y, c.window0, c.window1);
  };
  return {win(o.att_deg), win(o.pos_m), win(o.rate_deg_s), win(o.vel_m_s)};
}

Claim accuracy_comparison_claim(const std::vector<SteadyPair>& pairs, bool judged) {
  auto f = [](const char* format, double a, double b = 0.0, double c = 0.0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return std::string(buf);
  };
  std::string states, ours, rates;
  int better = 0, parts = 0;  // (state, quantity) pairs with the BsPdTC no less accurate
  for (const SteadyPair& s : pairs) {
    states += (states.empty() ? "" : ", ") + f("%.0f", s.state);
    const double ra = s.ptc.att_deg / s.fts.att_deg, rp = s.ptc.pos_m / s.fts.pos_m;
    ours += (ours.empty() ? "" : "; ") +
            f("state %.0f: max|theta_i| %.3g / %.3g deg", s.state, s.ptc.att_deg, s.fts.att_deg) +
            f(" = %.2g, max|beta_i| %.3g / %.3g m", ra, s.ptc.pos_m, s.fts.pos_m) + f(" = %.2g", rp);
    rates += (rates.empty() ? "" : "; ") +
             f("state %.0f: rate %.2g, velocity %.2g", s.state, s.ptc.rate_deg_s / s.fts.rate_deg_s,
               s.ptc.vel_m_s / s.fts.vel_m_s);
    better += (s.ptc.att_deg <= s.fts.att_deg) + (s.ptc.pos_m <= s.fts.pos_m);
    parts += 2;
  }
  Claim c{"paper",
          "BsPdTC steady errors below the FTSMC's (paper §3.2 2), conclusion 4; state" +
              std::string(pairs.size() > 1 ? "s " : " ") + states + ")",
          "'the control accuracy is also slightly higher than the latter [the FTSMC]' (conclusion 4); "
          "state 1, §3.2 2): |theta_i| <= 3.72e-3 vs 4.77e-3 deg, |beta_i| 3.28e-5 vs 5.58e-5 m, "
          "i.e. BsPdTC/FTSMC = 0.78 and 0.59",
          "BsPdTC/FTSMC steady bounds over [150, 200] s: " + ours,
          std::nullopt};
  // Rule: a qualitative statement (verdict_if): reproduced when the BsPdTC is no less accurate in
  // attitude and position from every state, partly when in some of them, else not reproduced.
  if (judged) c.paper_verdict = verdict_if(better == parts, better > 0);
  c.note = (better == 0 ? std::string("the FTSMC is the more accurate law in attitude and position: the reverse "
                                      "of the paper's conclusion. ")
                        : std::string()) +
           "Rate / velocity ratios BsPdTC/FTSMC: " + rates +
           ". No criterion of ours (the spec has no item for this comparison); PROTO (spec C.3) also has "
           "the FTSMC lower: 1.3e-3 vs 8.6e-3 deg, 3.6e-6 vs 1.3e-5 m (state 1)" +
           (judged ? "" : ". Not judged: not the paper's conditions (parameters or run incomplete)");
  return c;
}

}  // namespace adcs::sim::se3
