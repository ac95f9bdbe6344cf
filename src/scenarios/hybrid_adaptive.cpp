// Seed 001 scenarios (spec §A.5): hybrid 4-CMG pyramid + 3 wheels with installation deviations,
// tracking the eq. (27) reference under the adaptive MIMO law (control/hybrid_adaptive.hpp).
//   hybrid-adaptive / hybrid-nonadaptive           A-REF (D1, Ω_w(0) = 0), 800 s, T_c = 1 ms
//   hybrid-adaptive-bias / hybrid-nonadaptive-bias A-BIAS (Ω_w(0) = 150 rad/s, H_I^n told 0)
//   hybrid-fault-stuck-gimbal / hybrid-fault-wheel  A-REF with one actuator failed at t = 100 s
//     (issue 7, ours): a frozen gimbal (its rate stays 0 whatever is commanded) or a lost wheel
//     (no motor torque; it keeps its momentum, the plant has no bearing friction). FDIR reports
//     the failure fdir_delay_s later; the controller then steers over the remaining actuators
//     (HybridAdaptive::set_available). fdir=none shows the same fault without the fallback.
// Truth plant TP-FULL (momentum form) with σ_d integrated alongside by the same integrator.
// Every parameter the paper does not give is declared below with "assumed (spec A.5)".
#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include "adcs/actuator/saturation.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "scenarios/param_binding.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/truth_plants.hpp"
#include "scenarios/status_counts.hpp"
#include "scenarios/verdicts.hpp"
#include "sim/closed_loop.hpp"
#include "sim/law_at_scalar.hpp"
#include "sim/metrics.hpp"
#include "sim/random.hpp"
#include "sim/recorder.hpp"
#include "sim/sampled_data.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

constexpr int kM = 4, kN = 3;
using FullPlant = VscmgFullPlant<kM, kN>;
//! The law in the scalar of `--set scalar` (issue 19) behind the loop's double interface
//! (sim/law_at_scalar.hpp); the plant stays double under the integrator.
template <class S>
using Controller = HybridAdaptive<kM, kN, S>;
using HybridLaw = LawAtScalar<Controller>;


constexpr const char* kA5 = "assumed (spec A.5)";

//! |Θ̂_cGi|² (i = 1..M) then |Θ̂_wGj|² (j = 1..N), in double whatever the law's scalar.
Vec<kM + kN> estimate_norms2(const HybridLaw& law) noexcept {
  return law.visit([](const auto& c) noexcept {
    Vec<kM + kN> n;
    for (int i = 0; i < kM; ++i) n(i) = static_cast<double>(c.theta_cG(i).squaredNorm());
    for (int j = 0; j < kN; ++j) n(kM + j) = static_cast<double>(c.theta_wG(j).squaredNorm());
    return n;
  });
}
std::uint32_t safeguard_count(const HybridLaw& law) noexcept {
  return law.visit([](const auto& c) noexcept { return c.safeguard_count(); });
}

//! Per-sample errors of the no-adaptation run, overlaid on the adaptive run's plots (Figs. 2-5).
struct BaselineTrace {
  std::vector<double> principal_err, rate_err;
};
constexpr const char* kPaper = "seed 001 §4";

enum class Fault { none, stuck_gimbal, wheel };

//! What a scenario changes from the spec's A-REF configuration (issue 16).
enum class Variant {
  paper,       //!< the spec's choices for what the paper omits (A-REF / A-BIAS)
  projection,  //!< alpha_G raised until the smooth projection acts (R7 with teeth)
  calibrated,  //!< the paper's unreported J, h_cw, deviation and bias from tools/calibrate-seed001.py
};

//! Every parameter of the seed-001 scenarios, declared once (scenarios/param_binding.hpp). The
//! first five members are not parameters: they are the scenario's variant, which chooses the
//! list and its defaults.
struct HybridConfig {
  bool adaptive = true, bias = false, flight_rate = false;
  Fault fault = Fault::none;
  Variant variant = Variant::paper;

  double duration_s = 0, fault_time_s = 0, fault_actuator = 0, fdir_delay_s = 0, control_period_s = 0;
  std::string fdir, deviation, integrator, initial_estimates, adaptation_step, H_I_n, baseline, scalar;
  Vec3 J_s_diag_kgm2 = Vec3::Zero(), I_c_sgt_kgm2 = Vec3::Zero(), tau_ext_Nm = Vec3::Zero();
  Vec3 Kp_diag = Vec3::Zero(), Kd_diag = Vec3::Zero();
  double h_cw_Nms = 0, I_wws_kgm2 = 0, deviation_seed = 0, deviation_max = 0, deviation_rot_max_rad = 0;
  double gimbal_rate_max_rad_s = 0, wheel_accel_max_rad_s2 = 0, alpha_F = 0, alpha_G = 0, beta_G = 0, delta_G = 0;
  double Omega_w0_rad_s = 0, record_every = 0, max_step_gain = 0;
  Vec<2> window_s = Vec<2>::Zero();

  template <class F>
  void visit(F&& f) {
    if (fault != Fault::none) {
      f.number("duration_s", duration_s, 300.0, "s", "ours: 100 s before the fault, 200 s after");
      f.number("fault_time_s", fault_time_s, 100.0, "s", "issue 7: the actuator fails at t = 100 s");
      f.number("fault_actuator", fault_actuator, 1, "-",
               fault == Fault::stuck_gimbal ? "ours: which gimbal freezes (1..4)" : "ours: which wheel is lost (1..3)");
      f.number("fdir_delay_s", fdir_delay_s, 0.1, "s", "assumed (ours): time from the fault to the FDIR report");
      f.name("fdir", fdir, "mask", {"mask", "none"},
             "mask: the controller is told and steers over the remaining actuators; none: it is not told");
    } else {
      f.number("duration_s", duration_s, 800.0, "s", std::string(kA5) + ": one period of the slowest ω_f");
    }
    if (flight_rate)
      f.number("control_period_s", control_period_s, 0.1, "s", "ours: a flight rate, 10 Hz (the paper's law needs <= 3 ms)");
    else
      f.number("control_period_s", control_period_s, 1e-3, "s", std::string(kA5) + ": T_c = 1 ms (≥ 5 ms unstable)");
    // The calibrated variant's values are the best point of tools/calibrate-seed001.py's grid
    // (docs/data/seed001-calibration-grid.csv): the non-adaptive baseline closest to the paper's
    // R1/R2 orders (0.3 rad, 1e-3 rad/s) within what the paper states. Gains are never changed.
    const bool cal = variant == Variant::calibrated;
    constexpr const char* kCal = "issue 16 calibration (tools/calibrate-seed001.py, best grid point)";
    if (cal)
      f.vec("J_s_diag_kgm2", J_s_diag_kgm2, Vec3(30.0, 25.0, 20.0), "kg m^2", std::string(kCal) + ": 0.25 x A-REF's body inertia");
    else
      f.vec("J_s_diag_kgm2", J_s_diag_kgm2, Vec3(120.0, 100.0, 80.0), "kg m^2", std::string(kA5) + ": body inertia");
    f.number("h_cw_Nms", h_cw_Nms, cal ? 40.0 : 10.0, "N m s", cal ? std::string(kCal) : std::string(kA5) + ": CMG rotor momentum");
    f.number("I_wws_kgm2", I_wws_kgm2, 0.02, "kg m^2", std::string(kA5) + ": wheel spin inertia");
    f.vec("I_c_sgt_kgm2", I_c_sgt_kgm2, Vec3(0.012, 0.006, 0.01), "kg m^2",
          std::string(kA5) + ": CMG gimbal+rotor inertia about s, t, g");
    f.name("deviation", deviation, cal ? "random" : "D1", {"D1", "none", "random", "rigid"},
           (cal ? std::string(kCal) + ": a Mode-A draw (deviation_seed); " : std::string(kA5) + ": ") +
               "D1 fixed set (with --seed N > 0: a Mode-A set drawn from N, our "
               "portable generator); random = always drawn (Mode A); rigid = Mode B, each actuator "
               "rotated by a drawn rotation vector; none = truth equals nominal");
    f.number("deviation_seed", deviation_seed, cal ? 1.0 : 0.0, "-",
             cal ? std::string(kCal) + ": the Mode-A draw of --seed 1"
                 : "ours: the generator seed of random/rigid draws when --seed is 0");
    f.number("deviation_max", deviation_max, 0.05, "-", "seed 001 §4: ±0.05 per element (Mode A)");
    f.number("deviation_rot_max_rad", deviation_rot_max_rad, 0.05, "rad", "spec A.2.3 Mode B: φ ~ U[−0.05, 0.05]³ rad");
    f.vec("tau_ext_Nm", tau_ext_Nm, Vec3::Zero(), "N m",
          "spec A.5: 0 (paper); robustness case 1e-5 per axis, body components, constant");
    f.number("gimbal_rate_max_rad_s", gimbal_rate_max_rad_s, 0.0, "rad/s",
             "spec A.5: none (0) in the baseline; optional 1 rad/s, per gimbal, flagged if hit");
    f.number("wheel_accel_max_rad_s2", wheel_accel_max_rad_s2, 0.0, "rad/s^2",
             "spec A.5: none (0) in the baseline; optional 50 rad/s^2, per wheel, flagged if hit");
    f.number("alpha_F", alpha_F, adaptive ? 1.0e7 : 0.0, "-", kPaper);
    if (variant == Variant::projection)  // 1e5 x the paper's: max |Θ̂_G|² 0.148, in (β, β + δ)
      f.number("alpha_G", alpha_G, 1.0e8, "-", "ours: raised from seed 001's 1e3 until the projection acts (issue 16, R7)");
    else
      f.number("alpha_G", alpha_G, adaptive ? 1.0e3 : 0.0, "-", kPaper);
    f.number("beta_G", beta_G, 0.05, "-", kPaper);
    f.number("delta_G", delta_G, 0.1, "-", kPaper);
    f.vec("Kp_diag", Kp_diag, Vec3(0.08, 0.18, 0.12), "1/s^2", "spec §A.3 (eig listed in seed 001 §4)");
    f.vec("Kd_diag", Kd_diag, Vec3(0.4, 0.6, 0.5 * std::sqrt(2.0)), "1/s", "spec §A.3 (eig listed in seed 001 §4)");
    f.number("Omega_w0_rad_s", Omega_w0_rad_s, bias || cal ? 150.0 : 0.0, "rad/s",
             cal ? std::string(kCal) + ": A-BIAS's 150 rad/s wheel bias"
                 : bias ? std::string("spec §A.5 A-BIAS: bias momentum on all wheels") : std::string(kA5));
    f.name("H_I_n", H_I_n, bias || cal ? "zero" : "nominal", {"nominal", "zero"},
           "controller's H_I^n: nominal model at t = 0, or zero (A-BIAS: unknown bias)");
    if (fault != Fault::none)
      f.vec("window_s", window_s, Vec<2>(50.0, 100.0), "s", "ours: steady window before the fault");
    else
      f.vec("window_s", window_s, Vec<2>(200.0, 800.0), "s", std::string(kA5) + ": steady-state window");
    f.name("integrator", integrator, "rk4", {"rk4", "adams"},
           "rk4: one RK4 step per control period (spec §A.5); adams: CVODE Adams");
    f.number("record_every", record_every, flight_rate ? 1 : 100, "samples", "CSV decimation (in control samples)");
    f.name("initial_estimates", initial_estimates, "zero", {"zero", "truth"},
           "spec §A.5: Θ̂(0) = 0; truth = oracle check S11 (Θ̂ set to the true deviations)");
    f.name("adaptation_step", adaptation_step, flight_rate ? "normalized" : "explicit_euler", {"explicit_euler", "normalized"},
           "explicit_euler: the paper's estimate update (spec A.3 step 13); normalized: ours, "
           "keeps the per-step adaptation gain below max_step_gain (stable at 10 Hz)");
    f.number("max_step_gain", max_step_gain, 0.2, "-", "ours: lambda_max of the normalized step");
    if (adaptive && fault == Fault::none)
      f.name("baseline", baseline, "run", {"run", "skip"},
             "run: also simulate alpha_F = alpha_G = 0 for the R5 improvement ratio");
    f.name("scalar", scalar, "double", {"double", "float"}, kScalarHelp);
  }
};

class HybridScenario final : public Scenario {
 public:
  //! flight_rate: A-REF at 10 Hz with the normalized adaptation step (beyond the paper).
  HybridScenario(bool adaptive, bool bias, bool flight_rate = false, Fault fault = Fault::none,
                 Variant variant = Variant::paper)
      : adaptive_(adaptive), bias_(bias), flight_rate_(flight_rate), fault_(fault), variant_(variant) {}

  std::string name() const override {
    if (fault_ == Fault::stuck_gimbal) return "hybrid-fault-stuck-gimbal";
    if (fault_ == Fault::wheel) return "hybrid-fault-wheel";
    return std::string("hybrid-") + (adaptive_ ? "adaptive" : "nonadaptive") + (bias_ ? "-bias" : "") +
           (flight_rate_ ? "-10hz" : "") + (variant_ == Variant::projection ? "-projection" : "") +
           (variant_ == Variant::calibrated ? "-calibrated" : "");
  }
  std::string description() const override {
    return std::string("seed 001 ") + (bias_ ? "A-BIAS" : "A-REF") + ": 4-CMG pyramid + 3 wheels, D1 "
           "deviations, eq. (27) reference, " + (adaptive_ ? "adaptive law (25)-(26)" : "no adaptation") +
           (flight_rate_ ? ", at 10 Hz with the normalized adaptation step (ours)" : "") +
           (fault_ == Fault::stuck_gimbal ? "; fault: one CMG gimbal frozen at t = 100 s, FDIR fallback to the "
                                            "remaining actuators (ours)"
            : fault_ == Fault::wheel      ? "; fault: one reaction wheel lost at t = 100 s, FDIR fallback (ours)"
                                          : "") +
           (variant_ == Variant::projection ? "; alpha_G = 1e8 (ours) so that the projection bounds |Θ̂_G|² (R7)"
            : variant_ == Variant::calibrated ? "; the paper's unreported J, h_cw, deviation and wheel bias chosen by "
                                                "tools/calibrate-seed001.py (docs/data/seed001-calibration-grid.csv)"
                                              : "");
  }

  void declare(ParamSet& p) const override { declare_config(p, prototype()); }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    const HybridConfig c = read_config(p, prototype());
    const bool with_baseline = adaptive_ && fault_ == Fault::none && c.baseline == "run" && c.alpha_F + c.alpha_G > 0.0;
    if (!with_baseline) return simulate(p, ctx, nullptr, nullptr);
    // R5 needs the same configuration without adaptation: run it first (no CSV), keep its error
    // trace for the overlay plots, then take the ratios.
    ParamSet base = p;
    base.set("alpha_F", "0");
    base.set("alpha_G", "0");
    base.set("baseline", "skip");
    RunContext quiet = ctx;
    quiet.csv_path.clear();
    BaselineTrace trace;
    const RunResult b = simulate(base, quiet, nullptr, &trace);
    RunResult r = simulate(p, ctx, &trace, nullptr);
    const double ratio_att = b.metric("euler_err_ss_max_rad") / r.metric("euler_err_ss_max_rad");
    const double ratio_rate = b.metric("rate_err_ss_max_rad_s") / r.metric("rate_err_ss_max_rad_s");
    r.metrics.push_back({"improvement_ratio_euler", ratio_att});
    r.metrics.push_back({"improvement_ratio_rate", ratio_rate});
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.2g x attitude, %.2g x rate", ratio_att, ratio_rate);
    // Paper: "two orders of magnitude" in attitude, "one order" in rate: ratios >= 100 and >= 10
    // (verdict_at_least on each; the row takes the worse of the two).
    const PaperVerdict v_att = verdict_at_least(ratio_att, 100.0), v_rate = verdict_at_least(ratio_rate, 10.0);
    const bool a_ref = !bias_ && variant_ == Variant::paper;
    Claim r5{"paper", std::string("R5 improvement over no adaptation: 2 orders attitude, 1 order rate") +
                          (bias_ ? " (A-BIAS)" : ""),
             "'two orders of magnitude' attitude, 'one order' rate (§4): >= 100x / >= 10x", buf,
             a_ref ? std::optional<bool>(ratio_att >= 5.0 && ratio_rate >= 4.0) : std::optional<bool>(),
             static_cast<int>(v_att) > static_cast<int>(v_rate) ? v_att : v_rate,
             a_ref ? ">= 5x / >= 4x on A-REF (spec A.6 R5; PROTO 6.7x / 6.3x)"
                   : "informative (the spec's >= 5x / >= 4x is for A-REF)"};
    if (a_ref && r5.paper_verdict != PaperVerdict::reproduced)
      r5.note = "the paper's baseline is 360x / 25x worse than ours (R1/R2): the paper omits J, h_cw, the "
                "deviation draw and the wheel bias; see hybrid-adaptive-calibrated";
    if (variant_ == Variant::calibrated) {
      char cb[160];
      std::snprintf(cb, sizeof cb, "on the calibrated configuration: baseline %.3g rad / %.3g rad/s (the paper's "
                    "'0.3 rad' / '1e-3 rad/s' orders)", b.metric("euler_err_ss_max_rad"), b.metric("rate_err_ss_max_rad_s"));
      r5.note = cb;
    }
    r.claims.push_back(r5);
    // R3/R4 are bounds the baseline may meet without any adaptation: then they do not show that
    // adaptation works, and the row says so (R5's ratio is the discriminating criterion).
    const double base_att = b.metric("euler_err_ss_max_rad"), base_rate = b.metric("rate_err_ss_max_rad_s");
    for (Claim& c : r.claims) {
      char nb[160];
      if (c.claim.rfind("R3 ", 0) == 0 && base_att <= 3e-3) {
        std::snprintf(nb, sizeof nb, "not discriminating: the non-adaptive baseline meets it too (%.3g rad); R5 is", base_att);
        c.note = nb;
      } else if (c.claim.rfind("R4 ", 0) == 0 && base_rate <= 1e-4) {
        std::snprintf(nb, sizeof nb, "not discriminating: the non-adaptive baseline meets it too (%.3g rad/s); R5 is",
                      base_rate);
        c.note = nb;
      }
    }
    const std::string n = name();
    r.plots.push_back({n + "-compare-attitude.png", "Principal-angle error: adaptive vs no adaptation (Figs. 2, 4)",
                       "t", {"principal_err", "principal_err_nonadaptive"}, "error [rad]", true});
    r.plots.push_back({n + "-compare-rate.png", "Rate error: adaptive vs no adaptation (Figs. 3, 5)", "t",
                       {"rate_err", "rate_err_nonadaptive"}, "rate error [rad/s]", true});
    return r;
  }

 private:
  HybridConfig prototype() const {
    HybridConfig c;
    c.adaptive = adaptive_;
    c.bias = bias_;
    c.flight_rate = flight_rate_;
    c.fault = fault_;
    c.variant = variant_;
    return c;
  }

  //! One closed-loop run. `overlay` (optional) adds the no-adaptation errors as CSV columns;
  //! `capture` (optional) stores this run's per-sample errors for such an overlay. The law runs
  //! in the scalar `scalar` names (HybridLaw: parameters and inputs cast into it, commands back).
  RunResult simulate(const ParamSet& p, const RunContext& ctx, const BaselineTrace* overlay,
                     BaselineTrace* capture) const {
    const HybridConfig c = read_config(p, prototype());
    // --- configuration (spec §A.5) ---
    VscmgGeometry<kM, kN> nominal = pyramid_4cmg_3rw_nominal();
    nominal.J_s = c.J_s_diag_kgm2.asDiagonal();
    nominal.h_cw.setConstant(c.h_cw_Nms);
    nominal.I_wws.setConstant(c.I_wws_kgm2);
    const Vec3& Ic = c.I_c_sgt_kgm2;
    nominal.I_cs.setConstant(Ic(0));
    nominal.I_ct.setConstant(Ic(1));
    nominal.I_cg.setConstant(Ic(2));
    VscmgDeviation<kM, kN> dev;
    const std::string& mode = c.deviation;
    // Every value drawn from --seed, and what it derives, goes to the run's JSON (issue 15).
    std::vector<UsedValue> used;
    // The draw's generator seed: --seed, or deviation_seed when --seed is 0 (checked before the
    // conversion: a negative or NaN double has no uint64 value).
    const double deviation_seed = c.deviation_seed;
    if (!(deviation_seed >= 0.0 && deviation_seed < 1.8e19)) throw ParamError("deviation_seed must be in [0, 1.8e19)");
    const std::uint64_t draw_seed = ctx.seed != 0 ? ctx.seed : static_cast<std::uint64_t>(deviation_seed);
    const std::string from =
        std::string(ctx.seed != 0 ? "drawn from --seed " : "drawn from deviation_seed ") + std::to_string(draw_seed) + ": ";
    auto record_deviation = [&](const std::string& how) {
      used.push_back(UsedValue::matrix("dA_cs0", dev.dA_cs0, "-", how));
      used.push_back(UsedValue::matrix("dA_ct0", dev.dA_ct0, "-", how));
      used.push_back(UsedValue::matrix("dA_ws", dev.dA_ws, "-", how));
      used.push_back(UsedValue::matrix("dA_cg", dev.dA_cg, "-", how));
    };
    if (mode == "random" || (mode == "D1" && ctx.seed != 0)) {  // --seed N > 0 draws Mode A
      Rng rng(draw_seed);
      const double a = c.deviation_max;
      auto draw = [&](auto& m) {
        for (int j = 0; j < m.cols(); ++j)
          for (int i = 0; i < m.rows(); ++i) m(i, j) = rng.uniform(-a, a);
      };
      draw(dev.dA_cs0);
      draw(dev.dA_ct0);
      draw(dev.dA_ws);
      draw(dev.dA_cg);
      if (mode == "D1") used.push_back(UsedValue::name("deviation", "random", "--seed > 0 draws Mode A (spec A.2.3)"));
      record_deviation(from + "uniform in +-deviation_max per entry (spec A.2.3 Mode A)");
    } else if (mode == "rigid") {  // Mode B (spec A.2.3): one rotation vector per actuator
      Rng rng(draw_seed);
      const double a = c.deviation_rot_max_rad;
      Mat<3, kM> phi_c;
      Mat<3, kN> phi_w;
      for (int i = 0; i < kM; ++i)
        for (int k = 0; k < 3; ++k) phi_c(k, i) = rng.uniform(-a, a);
      for (int j = 0; j < kN; ++j)
        for (int k = 0; k < 3; ++k) phi_w(k, j) = rng.uniform(-a, a);
      dev = rigid_mounting_deviation(nominal, phi_c, phi_w);
      const std::string per = "uniform in +-deviation_rot_max_rad per component (spec A.2.3 Mode B)";
      used.push_back(UsedValue::matrix("phi_c_rad", phi_c, "rad", from + "CMG mounting rotation vectors (columns), " + per));
      used.push_back(UsedValue::matrix("phi_w_rad", phi_w, "rad", from + "wheel mounting rotation vectors (columns), " + per));
      record_deviation("derived from phi_c_rad, phi_w_rad (rigid_mounting_deviation)");
    } else if (mode == "D1") {
      dev = deviation_set_D1();
    }
    VscmgParams<kM, kN> pp;
    pp.nominal = nominal;
    pp.truth = apply_deviation(nominal, dev);
    FullPlant plant(pp);
    if (plant.status() != Status::ok) throw ParamError("plant parameters are not physical");
    const Vec3 tau_ext = c.tau_ext_Nm;
    plant.set_external_torque(tau_ext);
    Vec<kM + kN> u_limit;  // 0 = no limit (saturate_each)
    u_limit << Vec<kM>::Constant(c.gimbal_rate_max_rad_s),
        Vec<kN>::Constant(c.wheel_accel_max_rad_s2);
    if (!(u_limit.array() >= 0.0).all()) throw ParamError("actuator limits must be >= 0 (0 = none)");

    const double T = c.control_period_s;
    HybridAdaptiveParams<kM, kN> cp;
    cp.nominal = nominal;
    cp.alpha_F = c.alpha_F;
    cp.alpha_G = c.alpha_G;
    cp.beta_G = c.beta_G;
    cp.delta_G = c.delta_G;
    cp.period_s = T;
    cp.adaptation_step = c.adaptation_step == "normalized" ? AdaptationStep::normalized
                                                                       : AdaptationStep::explicit_euler;
    cp.max_step_gain = c.max_step_gain;
    const Vec3 kp = c.Kp_diag, kd = c.Kd_diag;
    for (int i = 0; i < 3; ++i) {  // s² + kd s + kp = 0 per axis
      const std::complex<double> disc = std::sqrt(std::complex<double>(kd(i) * kd(i) - 4 * kp(i)));
      cp.poles[i] = {{(-kd(i) + disc) / 2.0, (-kd(i) - disc) / 2.0}};
    }
    // Initial state: σ = σ_d = 0, ω = 0, γ = 0, Ω_w = Omega_w0 (spec §A.4 #24, §A.5).
    const Vec3 Omega0 = Vec3::Constant(c.Omega_w0_rad_s);
    const FullPlant::State x0p = plant.initial_state(Vec3::Zero(), Vec3::Zero(), Vec<kM>::Zero(), Omega0);
    const Vec3 H_true = plant.momentum_N(x0p);
    // H_I^n from the nominal model at t = 0 (σ = 0, ω = 0, γ = 0).
    const Vec3 H_n_model = nominal.internal_momentum(Vec<kM>::Zero(), Vec<kM>::Zero(), Omega0);
    cp.H_I_n = c.H_I_n == "zero" ? Vec3::Zero() : H_n_model;
    HybridLaw ctrl({cp, c.scalar == "float"});
    if (ctrl.status() != Status::ok) throw ParamError("controller parameters rejected (alpha, beta, delta, gains)");
    if (c.initial_estimates == "truth") {  // spec §A.7 S11: the oracle controller
      Mat<6, kM> th_c;
      Mat<3, kN> th_w;
      for (int i = 0; i < kM; ++i) th_c.col(i) = dev.theta_cG(i);
      for (int j = 0; j < kN; ++j) th_w.col(j) = dev.theta_wG(j);
      const Vec3 theta_F0 = H_true - cp.H_I_n;
      const Status set = ctrl.visit([&](auto& law) noexcept {
        using S = typename std::decay_t<decltype(law)>::Scalar;
        return law.set_estimates(scalar_cast<S>(theta_F0), scalar_cast<S>(th_c), scalar_cast<S>(th_w));
      });
      if (set != Status::ok)
        throw ParamError("initial_estimates=truth: deviations outside the projection ball");
    }

    HybridSimPlant sim{&plant, SinusoidalRateReference{}};
    HybridSimPlant::State x;
    x << x0p, Vec3::Zero();

    std::unique_ptr<CsvRecorder> csv;
    if (!ctx.csv_path.empty()) {
      std::vector<Column> cols{{"t", "s"}};
      for (const char* n : {"euler_err_1", "euler_err_2", "euler_err_3"}) cols.push_back({n, "rad"});
      cols.push_back({"principal_err", "rad"});
      cols.push_back({"rate_err", "rad/s"});
      for (int i = 1; i <= kM; ++i) cols.push_back({"gamma_" + std::to_string(i), "rad"});
      for (int j = 1; j <= kN; ++j) cols.push_back({"Omega_w_" + std::to_string(j), "rad/s"});
      for (int k = 1; k <= 3; ++k) cols.push_back({"theta_F_" + std::to_string(k), "N m s"});
      for (int k = 1; k <= 3; ++k) cols.push_back({"H_est_" + std::to_string(k), "N m s"});
      for (int k = 1; k <= 3; ++k) cols.push_back({"H_true_" + std::to_string(k), "N m s"});
      for (int i = 1; i <= kM; ++i) cols.push_back({"theta_cG_norm2_" + std::to_string(i), "-"});
      for (int j = 1; j <= kN; ++j) cols.push_back({"theta_wG_norm2_" + std::to_string(j), "-"});
      cols.push_back({"pinv_sigma_min", "-"});
      if (overlay) {
        cols.push_back({"principal_err_nonadaptive", "rad"});
        cols.push_back({"rate_err_nonadaptive", "rad/s"});
      }
      csv = std::make_unique<CsvRecorder>(ctx.csv_path, cols, static_cast<int>(c.record_every));
    }

    const Vec<2> window = c.window_s;
    double e_att_max = 0, e_p_max = 0, e_rate_max = 0, proj_max = 0, sigma_min = INFINITY;
    double gimbal_max = 0, wheel_max = 0, drift_max = 0, E_H_final = NAN, E_H0 = NAN, E_H_late_max = 0;
    long nonok = 0, limit_hits = 0;
    double gimbal_rate_peak = 0, wheel_accel_peak = 0;
    std::size_t sample = 0;             // observer call index, aligns the baseline overlay
    Vec3 H_expected = H_true;           // H(0) + ∫ Cᵀ τ_ext dt (trapezoid at the samples)
    Vec3 torque_N_prev = Vec3::Zero();  // Cᵀ τ_ext at the previous sample
    double t_prev = 0.0;
    std::vector<double> row;
    const SinusoidalRateReference& ref = sim.ref;

    // Fault injection (fault scenarios only): actuator k_fail stops responding at t_fault; the
    // FDIR report reaches the controller at t_fdir (never with fdir=none).
    const bool faulty = fault_ != Fault::none;
    double t_fault = INFINITY, t_fdir = INFINITY;
    int k_fail = -1;
    if (faulty) {
      const double a = c.fault_actuator;
      const int count = fault_ == Fault::stuck_gimbal ? kM : kN;
      if (!(a >= 1 && a <= count) || a != std::floor(a))
        throw ParamError("fault_actuator must be an integer in 1.." + std::to_string(count));
      k_fail = (fault_ == Fault::stuck_gimbal ? 0 : kM) + static_cast<int>(a) - 1;
      t_fault = c.fault_time_s;
      const double delay = c.fdir_delay_s;
      if (!(t_fault >= 0.0) || !(delay >= 0.0)) throw ParamError("fault_time_s and fdir_delay_s must be >= 0");
      if (c.fdir == "mask") t_fdir = t_fault + delay;
    }
    bool fdir_applied = false;
    StatusCounts statuses;
    long nonfinite_cmd = 0;
    double failed_cmd_after_fdir = 0.0, e_p_after = 0.0, e_rate_after = 0.0, e_p_pre = 0.0;

    // The loop (sim/closed_loop.hpp): perfect sensors (spec §A.5) → the law, which steers its
    // own actuators (PassThrough) → optional limits and the failed actuator → the truth plant.
    auto sensors = [&](double t, const HybridSimPlant::State& xs, const HybridSimPlant::Input& u_held) {
      const FullPlant::State xp = xs.head<FullPlant::kStateSize>();
      if (faulty && !fdir_applied && t >= t_fdir) {  // the FDIR report reaches the controller
        const ActuatorMask mask = all_actuators<kM + kN>() & ~(ActuatorMask{1} << k_fail);
        if (ctrl.visit([mask](auto& law) noexcept { return law.set_available(mask); }) != Status::ok)
          throw SimError("hybrid fault: actuator mask rejected");
        fdir_applied = true;
      }
      HybridAdaptiveInput<kM, kN> m;
      m.state.sigma_BN = FullPlant::sigma_BN(xp);
      m.state.omega_BN_B = plant.omega_BN_B(xp, u_held);  // ω with the γ̇ held over the last period
      m.actuators.gamma_rad = FullPlant::gamma(xp);
      m.actuators.Omega_rad_s = FullPlant::Omega_w(xp);
      m.reference = ref.sample(t, xs.tail<3>());
      return m;
    };
    using Output = HybridLaw::Output;
    auto to_actuation = [](double, const HybridSimPlant::State&, const Output& cmd) { return cmd; };
    auto to_plant = [&](double t, const HybridSimPlant::State&, const Output& cmd, HybridSimPlant::Input& u) {
      u = cmd.stacked();
      if (saturate_each<kM + kN>(u, u_limit) > 0) ++limit_hits;  // spec A.5: flag if hit
      if (t >= t_fault) u(k_fail) = 0.0;  // frozen gimbal (γ̇ = 0) / lost wheel (no torque)
    };
    auto observe = [&](const auto& s) {
      const double t = s.t_s;
      const HybridSimPlant::State& xs = s.x;
      const HybridSimPlant::Input& u = s.u;
      if (!s.final) {  // once per control step
        if (s.controller_status != Status::ok) ++nonok;
        statuses.add(s.controller_status);
        const Vec<kM + kN> commanded = s.command.stacked();
        if (!all_finite(commanded)) ++nonfinite_cmd;
        if (fdir_applied) failed_cmd_after_fdir = std::max(failed_cmd_after_fdir, std::abs(commanded(k_fail)));
        gimbal_rate_peak = std::max(gimbal_rate_peak, commanded.head<kM>().cwiseAbs().maxCoeff());
        wheel_accel_peak = std::max(wheel_accel_peak, commanded.tail<kN>().cwiseAbs().maxCoeff());
      }
      const FullPlant::State xp = xs.head<FullPlant::kStateSize>();
      const Vec3 sigma = FullPlant::sigma_BN(xp);
      const Mat3 C_e = mrp_to_dcm(sigma) * mrp_to_dcm(xs.tail<3>()).transpose();  // spec §A.4 #23
      const Vec3 ypr = dcm_to_euler321(C_e);
      const double e_att = ypr.cwiseAbs().maxCoeff();
      const double e_p = mrp_principal_angle(dcm_to_mrp(C_e));
      const double e_rate = (plant.omega_BN_B(xp, u) - C_e * ref.omega(t)).norm();  // spec #28
      const Vec3 theta_F = ctrl.visit([](const auto& law) noexcept -> Vec3 { return law.theta_F().template cast<double>(); });
      const Vec3 H_est = cp.H_I_n + theta_F;
      const Vec3 H_now = plant.momentum_N(xp);  // = H_true(0) when τ_ext = 0 (spec S4)
      const double E_H = (H_est - H_now).norm();
      const Vec3 torque_N = mrp_to_dcm(sigma).transpose() * tau_ext;  // spec S4: d/dt(Cᵀh) = Cᵀτ
      if (t > t_prev) H_expected += 0.5 * (t - t_prev) * (torque_N + torque_N_prev);
      torque_N_prev = torque_N;
      t_prev = t;
      if (t == 0.0) E_H0 = E_H;
      if (t >= window(0) && t <= window(1)) {
        e_att_max = std::max(e_att_max, e_att);
        e_p_max = std::max(e_p_max, e_p);
        e_rate_max = std::max(e_rate_max, e_rate);
      }
      if (t >= 100.0) E_H_late_max = std::max(E_H_late_max, E_H);
      if (t >= t_fault) {
        e_p_after = std::max(e_p_after, e_p);
        e_rate_after = std::max(e_rate_after, e_rate);
      } else if (t >= window(0)) {
        e_p_pre = std::max(e_p_pre, e_p);
      }
      E_H_final = E_H;
      const Vec<kM + kN> theta_G_norm2 = estimate_norms2(ctrl);
      proj_max = std::max(proj_max, theta_G_norm2.maxCoeff());
      const double pinv_sigma_min = ctrl.visit(
          s.controller_diagnostics, [](const auto& d) noexcept { return static_cast<double>(d.steering.pinv.sigma_min); });
      if (t > 0.0) sigma_min = std::min(sigma_min, pinv_sigma_min);
      gimbal_max = std::max(gimbal_max, FullPlant::gamma(xp).cwiseAbs().maxCoeff());
      wheel_max = std::max(wheel_max, (FullPlant::Omega_w(xp) - Omega0).cwiseAbs().maxCoeff());
      drift_max = std::max(drift_max, (H_now - H_expected).norm());
      if (capture) {
        capture->principal_err.push_back(e_p);
        capture->rate_err.push_back(e_rate);
      }
      if (csv) {
        row.assign({t, ypr(2), ypr(1), ypr(0), e_p, e_rate});
        for (int i = 0; i < kM; ++i) row.push_back(FullPlant::gamma(xp)(i));
        for (int j = 0; j < kN; ++j) row.push_back(FullPlant::Omega_w(xp)(j));
        for (int k = 0; k < 3; ++k) row.push_back(theta_F(k));
        for (int k = 0; k < 3; ++k) row.push_back(H_est(k));
        for (int k = 0; k < 3; ++k) row.push_back(H_now(k));
        for (int k = 0; k < kM + kN; ++k) row.push_back(theta_G_norm2(k));
        row.push_back(pinv_sigma_min);
        if (overlay) {
          const bool have = sample < overlay->principal_err.size();
          row.push_back(have ? overlay->principal_err[sample] : NAN);
          row.push_back(have ? overlay->rate_err[sample] : NAN);
        }
        csv->record_row(row, s.final);
      }
      ++sample;
    };
    SampledDataOptions opt;
    opt.t_end = c.duration_s;
    opt.sample_period = T;
    IntegratorChoice ic;  // rk4: one RK4 step per control period (spec §A.5); adams: CVODE 1e-10 / 1e-12
    ic.kind = c.integrator == "rk4" ? IntegratorChoice::Kind::rk4 : IntegratorChoice::Kind::adams;
    ic.rk4_step_s = T;
    PassThrough<Output> actuation;
    closed_loop(sim, x, opt, ic, sensors, ctrl, to_actuation, actuation, to_plant, observe);
    if (csv) csv->close();

    RunResult r;
    r.used = std::move(used);
    r.metrics = {{"euler_err_ss_max_rad", e_att_max},
                 {"principal_err_ss_max_rad", e_p_max},
                 {"rate_err_ss_max_rad_s", e_rate_max},
                 {"proj_norm2_max", proj_max},
                 {"proj_safeguard_count", double(safeguard_count(ctrl))},
                 {"momentum_drift_rel", drift_max / std::max(H_true.norm(), 1e-12)},
                 {"momentum_est_err_final_Nms", E_H_final},
                 {"pinv_sigma_min", sigma_min},
                 {"gimbal_angle_max_rad", gimbal_max},
                 {"wheel_speed_max_rad_s", wheel_max},
                 {"momentum_est_err_initial_Nms", E_H0},
                 {"momentum_est_err_late_max_Nms", E_H_late_max},
                 {"nonok_steps", double(nonok)},
                 {"gimbal_rate_peak_rad_s", gimbal_rate_peak},
                 {"wheel_accel_peak_rad_s2", wheel_accel_peak},
                 {"actuator_limit_hits", double(limit_hits)}};
    if (faulty) {
      fault_results(r, c.fdir == "mask", k_fail, e_p_pre, e_p_after, e_rate_after, failed_cmd_after_fdir, nonfinite_cmd,
                    statuses);
      return r;
    }
    if ((u_limit.array() > 0.0).any())
      r.claims.push_back({"check", "actuator limits (optional, spec A.5) never reached",
                          "0 samples clipped (PROTO peaks 3.1e-3 rad/s, 8e-6 rad/s^2)",
                          std::to_string(limit_hits) + " samples clipped", limit_hits == 0});
    add_claims(r, c.beta_G, e_att_max, e_p_max, e_rate_max, proj_max, safeguard_count(ctrl), sigma_min, E_H0,
               E_H_late_max, gimbal_max, wheel_max, variant_ == Variant::paper && mode == "D1" && ctx.seed == 0);
    const std::string n = name();
    r.plots = {
        {n + "-theta-F.png", "Momentum-deviation estimate theta_F = H_I^Delta-hat", "t",
         {"theta_F_1", "theta_F_2", "theta_F_3"}, "theta_F [N m s]", false},
        {n + "-pinv-sigma-min.png", "Smallest singular value of the steering matrix X (R9)", "t",
         {"pinv_sigma_min"}, "sigma_min(X) [1/s, 1/s^2]", false},
        {n + "-euler.png", "Euler-angle (3-2-1) tracking error", "t",
         {"euler_err_1", "euler_err_2", "euler_err_3"}, "error [rad]", false},
        {n + "-rate.png", "Rate tracking error |omega - C_e omega_f|", "t", {"rate_err"},
         "rate error [rad/s]", true},
        {n + "-gimbal.png", "Gimbal angles", "t", {"gamma_1", "gamma_2", "gamma_3", "gamma_4"},
         "gamma [rad]", false},
        {n + "-wheels.png", "Wheel speeds", "t", {"Omega_w_1", "Omega_w_2", "Omega_w_3"},
         "Omega_w [rad/s]", false},
        {n + "-momentum.png", "Momentum estimate H_I^n + theta_F vs truth", "t",
         {"H_est_1", "H_est_2", "H_est_3", "H_true_1", "H_true_2", "H_true_3"}, "H_I [N m s]", false},
        {n + "-theta-cG.png", "CMG deviation estimates |theta_cG|^2 (bound 0.15)", "t",
         {"theta_cG_norm2_1", "theta_cG_norm2_2", "theta_cG_norm2_3", "theta_cG_norm2_4"}, "[-]", false},
        {n + "-theta-wG.png", "Wheel deviation estimates |theta_wG|^2 (bound 0.15)", "t",
         {"theta_wG_norm2_1", "theta_wG_norm2_2", "theta_wG_norm2_3"}, "[-]", false},
    };
    return r;
  }

  //! Fault scenarios: bounded attitude after the fault, the failed actuator never commanded after
  //! the FDIR report, finite commands, and every step() status returned.
  void fault_results(RunResult& r, bool fdir, int k_fail, double e_pre, double e_after,
                     double rate_after, double failed_cmd, long nonfinite_cmd, const StatusCounts& statuses) const {
    r.metrics.push_back({"att_err_max_rad", e_after});
    r.metrics.push_back({"att_err_max_pre_fault_rad", e_pre});
    r.metrics.push_back({"rate_err_max_after_fault_rad_s", rate_after});
    r.metrics.push_back({"failed_actuator_cmd_max_after_fdir", fdir ? failed_cmd : NAN});
    r.metrics.push_back({"nonfinite_commands", double(nonfinite_cmd)});
    statuses.to_metrics(r);
    const std::string what = (fault_ == Fault::stuck_gimbal ? "gimbal " : "wheel ") +
                             std::to_string(fault_ == Fault::stuck_gimbal ? k_fail + 1 : k_fail - kM + 1);
    char buf[200];
    std::snprintf(buf, sizeof buf, "max principal error %.3g rad after the fault (%.3g rad before), rate %.3g rad/s",
                  e_after, e_pre, rate_after);
    // Bounded: within the paper's R3 accuracy (3e-3 rad) with the fallback; informative without.
    r.claims.push_back({"check", "attitude stays bounded after the failure of " + what +
                                     (fdir ? " (FDIR fallback)" : " (no FDIR: informative)"),
                        "max principal error after the fault <= 3e-3 rad (the paper's R3 accuracy)", buf,
                        fdir ? std::optional<bool>(e_after <= 3e-3) : std::nullopt});
    if (fdir) {
      std::snprintf(buf, sizeof buf, "max |u_%d| = %.3g after the report", k_fail + 1, failed_cmd);
      r.claims.push_back({"check", "the failed actuator is never commanded after the FDIR report",
                          "exactly 0 (steering over the available actuators)", buf, failed_cmd == 0.0});
    }
    r.claims.push_back({"check", "every command finite; step() statuses returned", "0 non-finite commands",
                        std::to_string(nonfinite_cmd) + " non-finite; statuses: " + statuses.summary(), nonfinite_cmd == 0});
  }

  void add_claims(RunResult& r, double beta_G, double e_att, double e_p, double e_rate, double proj,
                  unsigned safeguards, double sigma_min, double E_H0, double E_H_late, double gimbal, double wheel,
                  bool reference_set) const {
    char ours[128];
    auto fmt = [&](const char* f, double a, double b = 0) {
      std::snprintf(ours, sizeof ours, f, a, b);
      return std::string(ours);
    };
    // Within +-30 % of the prototype (spec A.6), where the run is the spec's reference set.
    auto near_proto = [&](double x, double proto) { return !reference_set || std::abs(x / proto - 1.0) <= 0.3; };
    if (bias_) {  // A-BIAS is the spec's case, not the paper's: a check against the prototype
      r.claims.push_back({"check", adaptive_ ? "A-BIAS adaptive: attitude error (informative)"
                                             : "A-BIAS no adaptation: attitude error (informative)",
                          "PROTO θ_p " + std::string(adaptive_ ? "4.5e-4" : "1.46e-2") + " rad",
                          fmt("θ_p %.3g rad (Euler %.3g)", e_p, e_att), std::nullopt});
      return;
    }
    if (!adaptive_) {
      // Paper: "of the order of 0.3 rad" / "1e-3 rad/s" (verdict_order_of). Our criterion pins the
      // spec's reference set to the prototype: the paper omits what sets the baseline's size.
      r.claims.push_back({"paper", "R1 no adaptation: Euler error '0.3 rad order' (Fig. 2)",
                          "'0.3 rad order' (Fig. 2)", fmt("%.3g rad (θ_p %.3g)", e_att, e_p),
                          std::optional<bool>(near_proto(e_att, 8.35e-4)), verdict_order_of(e_att, 0.3),
                          reference_set ? "within ±30 % of PROTO 8.35e-4 rad (spec A.6 R1)" : "informative (not the reference set)",
                          "the paper omits J, h_cw, the deviation draw and the wheel bias, which set this size; "
                          "hybrid-nonadaptive-calibrated searches them"});
      if (!reference_set) r.claims.back().holds = std::nullopt;
      r.claims.push_back({"paper", "R2 no adaptation: rate error '1e-3 rad/s order' (Fig. 3)",
                          "'1e-3 rad/s order' (Fig. 3)", fmt("%.3g rad/s", e_rate),
                          std::optional<bool>(near_proto(e_rate, 3.95e-5)), verdict_order_of(e_rate, 1e-3),
                          reference_set ? "within ±30 % of PROTO 3.95e-5 rad/s (spec A.6 R2)" : "informative (not the reference set)",
                          "as R1"});
      if (!reference_set) r.claims.back().holds = std::nullopt;
      return;
    }
    const std::string rate_tag = flight_rate_ ? " — at 10 Hz, normalized step (ours)" : "";
    // R3/R4: the paper's numbers are bounds the error settles within (verdict_at_most).
    r.claims.push_back({"paper", "R3 adaptive: Euler error settles at 0.003 rad (Fig. 4)" + rate_tag,
                        "'settles at 0.003 rad' (Fig. 4): <= 3e-3 rad", fmt("%.3g rad (θ_p %.3g)", e_att, e_p),
                        e_att <= 3e-3 && near_proto(e_att, 1.25e-4), verdict_at_most(e_att, 3e-3),
                        "<= 3e-3 rad and within ±30 % of PROTO 1.25e-4 rad on the reference set (spec A.6 R3)"});
    r.claims.push_back({"paper", "R4 adaptive: rate error '1e-4 rad/s order' (Fig. 5)" + rate_tag,
                        "'1e-4 rad/s order' (Fig. 5): <= 1e-4 rad/s", fmt("%.3g rad/s", e_rate), e_rate <= 1e-4,
                        verdict_at_most(e_rate, 1e-4), "<= 1e-4 rad/s (spec A.6 R4; PROTO 6.27e-6)"});
    r.claims.push_back({"paper", "R6 momentum estimate approaches the true momentum (Figs. 8-9)",
                        "'the estimate approaches the true momentum' (Figs. 8-9)",
                        fmt("E_H(0) %.3g, max after 100 s %.3g N m s", E_H0, E_H_late), E_H_late < E_H0,
                        verdict_if(E_H_late < E_H0),
                        "E_H(t) < E_H(0) for t >= 100 s (spec A.6 R6; PROTO 0.335 -> 0.11..0.27)"});
    Claim r7{"paper", "R7 |theta_G|^2 never exceeds beta+delta = 0.15 (Figs. 10-11)",
             "'|Θ̂_G|² stays within β + δ' (Figs. 10-11): <= 0.15", fmt("%.3g, safeguards %.0f", proj, double(safeguards)),
             proj <= 0.15 + 1e-9 && safeguards == 0, verdict_if(proj <= 0.15 + 1e-9),
             "<= 0.15 and safeguard count 0 (spec A.6 R7; PROTO 4e-4)"};
    if (proj < beta_G) {
      char nb[160];
      std::snprintf(nb, sizeof nb, "mechanism never active: max |Θ̂_G|² %.2g < β = %.2g, the projection did not act; "
                    "hybrid-adaptive-projection exercises it", proj, beta_G);
      r7.note = nb;
    }
    r.claims.push_back(r7);
    if (variant_ == Variant::projection) {
      char pb[96];
      std::snprintf(pb, sizeof pb, "max |Θ̂_G|² %.3g vs β = %.2g", proj, beta_G);
      r.claims.push_back({"check", "the projection acts in this variant (R7 exercised)",
                          "max |Θ̂_G|² > β (the band where the smooth projection bends the update)", pb,
                          proj > beta_G});
    }
    r.claims.push_back({"paper", "R8 gimbal angles and wheel speeds bounded (Figs. 6-7)",
                        "'gimbal angles and wheel speeds remain bounded' (Figs. 6-7)",
                        fmt("%.3g rad; %.3g rad/s", gimbal, wheel),
                        reference_set ? std::optional<bool>(near_proto(gimbal, 0.274)) : std::nullopt,
                        verdict_if(std::isfinite(gimbal) && std::isfinite(wheel)),
                        reference_set ? "max gimbal angle within ±30 % of PROTO 0.274 rad (spec A.6 R8)"
                                      : "informative (not the reference set)"});
    r.claims.push_back({"paper", "R9 pseudo-inverse exists throughout", "'the pseudo-inverse exists' (§3): σ_min(X) > 0",
                        fmt("%.4g", sigma_min), sigma_min > 0.0, verdict_if(sigma_min > 0.0),
                        "σ_min(X) > 0 (spec A.6 R9; PROTO 0.0170)",
                        "not discriminating: the three body-axis wheel columns alone keep σ_min(X) > 0 for any "
                        "gimbal angles"});
  }

  bool adaptive_, bias_, flight_rate_;
  Fault fault_;
  Variant variant_ = Variant::paper;
};

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::unique_ptr<Scenario> make_hybrid_adaptive() { return std::make_unique<HybridScenario>(true, false); }
std::unique_ptr<Scenario> make_hybrid_nonadaptive() { return std::make_unique<HybridScenario>(false, false); }
std::unique_ptr<Scenario> make_hybrid_adaptive_bias() { return std::make_unique<HybridScenario>(true, true); }
std::unique_ptr<Scenario> make_hybrid_nonadaptive_bias() { return std::make_unique<HybridScenario>(false, true); }
std::unique_ptr<Scenario> make_hybrid_adaptive_10hz() { return std::make_unique<HybridScenario>(true, false, true); }
std::unique_ptr<Scenario> make_hybrid_adaptive_calibrated() {
  return std::make_unique<HybridScenario>(true, false, false, Fault::none, Variant::calibrated);
}
std::unique_ptr<Scenario> make_hybrid_nonadaptive_calibrated() {
  return std::make_unique<HybridScenario>(false, false, false, Fault::none, Variant::calibrated);
}
std::unique_ptr<Scenario> make_hybrid_adaptive_projection() {
  return std::make_unique<HybridScenario>(true, false, false, Fault::none, Variant::projection);
}
std::unique_ptr<Scenario> make_hybrid_fault_stuck_gimbal() {
  return std::make_unique<HybridScenario>(true, false, false, Fault::stuck_gimbal);
}
std::unique_ptr<Scenario> make_hybrid_fault_wheel() {
  return std::make_unique<HybridScenario>(true, false, false, Fault::wheel);
}

}  // namespace adcs::sim
