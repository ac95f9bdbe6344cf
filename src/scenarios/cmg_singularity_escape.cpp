// cmg-singularity-escape: a pure four-CMG pyramid (no wheels) asked for a constant torque, with
// three steering laws side by side on the same cluster:
//   pinv    the exact pseudo-inverse (right_pinv_solve); where it refuses (singular), the CMG
//           safe command, zero gimbal rate, is applied;
//   damped  steer(): the pseudo-inverse with the singularity-robust (damped) fallback, default
//           SteeringParams, its command applied as written;
//   escape  steer_escape(): Wie's generalized singularity-robust inverse with deterministic
//           dither, default EscapeSteeringParams, its command applied as written (that is how it
//           leaves a singular configuration).
// Two cases, each run with all three laws from γ = 0:
//   internal    torque along +x: the gimbals are driven to the elliptic internal singularity
//               (90, 0, −90, 0)° where x is lost, long before the momentum envelope;
//   saturation  torque along +z: the cluster's momentum grows to the envelope (an external
//               singularity no law can leave: the statuses must say so).
// Gimbal kinematics γ̇ = u with each gimbal rate clipped at its motor limit (saturate_each),
// held over the sample (ZOH): γ_{k+1} = γ_k + T u_k is the exact solution, so no integrator is
// involved. Delivered torque τ = −X(γ) γ̇ with X = A_ct(γ) diag(h_cw) (seed 001 eq. (11)); each
// law solves X u = v = −τ_req.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "adcs/actuator/saturation.hpp"
#include "adcs/actuator/steering.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/status_counts.hpp"
#include "sim/recorder.hpp"
#include "sim/format.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

constexpr double kDeg = kPiRad / 180.0;
constexpr const char* kUser = "assumed: small-satellite 4-CMG pyramid of issue 15 (skew 60 deg, 0.03 N m s)";
constexpr int kLaws = 3;
const std::array<const char*, kLaws> kLawNames = {"pinv", "damped", "escape"};

using Cluster = VscmgGeometry<4, 0>;

//! What one law did over one case.
struct LawRun {
  std::vector<double> t, m, err;
  std::vector<std::array<double, 4>> gamma;
  StatusCounts statuses;
  double time_above_10pct_s = 0.0, err_max = 0.0, err_mean = 0.0, m_min = 1e300;
  double t_enter = -1.0, t_leave = -1.0;  //!< first entry into / exit from m < m_singular
  double momentum_fraction_final = 0.0;   //!< |H_cmg| / (4 h) at the end
  double err_final = 0.0;                 //!< mean torque error over the last 5 s
};

struct Setup {
  Cluster g;
  double T = 0.1, t_end = 35.0, m_singular = 0.05;
  Vec<4> rate_limit = Vec<4>::Zero();
  SteeringParams damped;
  EscapeSteeringParams escape;
};

//! One law on one case: constant request tau_req from γ = 0.
LawRun run_law(const Setup& s, int law, const Vec3& tau_req, double t_end) {
  LawRun r;
  Vec<4> gamma = Vec<4>::Zero();
  const Vec3 v = -tau_req;  // X u = −τ_req  (τ = −X γ̇)
  const long steps = std::lround(t_end / s.T);
  const long final_from = steps - std::max(1L, std::lround(5.0 / s.T));  // the last 5 s
  double err_sum = 0.0;
  bool inside = false;
  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * s.T;
    const Mat<3, 4> X = s.g.A_ct(gamma) * s.g.h_cw.asDiagonal();
    Vec<4> u = Vec<4>::Zero();  // the CMG safe command: zero gimbal rate
    Status st = Status::ok;
    SteeringInfo info;
    if (law == 0) {
      PinvInfo pi;
      st = right_pinv_solve<3, 4>(X, v, u, &pi);
      if (!usable(st)) u.setZero();
    } else if (law == 1) {
      st = steer<4>(X, v, s.damped, u, &info);
      if (!written(st)) u.setZero();
    } else {
      st = steer_escape<4>(X, v, s.escape, t, u, &info);
      if (!written(st)) u.setZero();
    }
    r.statuses.add(st);
    saturate_each<4>(u, s.rate_limit);  // each gimbal motor's rate limit
    // What the cluster delivers with the rates actually applied.
    const double err = (X * u - v).norm() / v.norm();
    double scale = 0.0;
    Mat3 G;
    const double m = detail::singularity_measure<4>(X, scale, G);
    r.t.push_back(t);
    r.m.push_back(m);
    r.err.push_back(err);
    r.gamma.push_back({gamma(0), gamma(1), gamma(2), gamma(3)});
    if (k < steps) {  // the sample [t, t + T) counts; the last row only records the end state
      if (err > 0.1) r.time_above_10pct_s += s.T;
      if (k >= final_from) r.err_final += err / static_cast<double>(steps - final_from);
      r.err_max = std::max(r.err_max, err);
      err_sum += err;
    }
    r.m_min = std::min(r.m_min, m);
    if (!inside && m < s.m_singular && r.t_enter < 0.0) {
      inside = true;
      r.t_enter = t;
    } else if (inside && m >= s.m_singular && r.t_leave < 0.0) {
      inside = false;
      r.t_leave = t;
    }
    gamma += s.T * u;  // exact ZOH solution of γ̇ = u
  }
  r.err_mean = err_sum / static_cast<double>(steps);
  r.momentum_fraction_final = (s.g.A_cs(gamma) * s.g.h_cw).norm() / s.g.h_cw.sum();
  return r;
}

//! Time spent inside the singular neighbourhood after first reaching it (to the end if it never
//! leaves); 0 if never reached.
double dwell_s(const LawRun& r, double t_end) {
  if (r.t_enter < 0.0) return 0.0;
  return (r.t_leave >= 0.0 ? r.t_leave : t_end) - r.t_enter;
}

class CmgSingularityEscape final : public Scenario {
 public:
  std::string name() const override { return "cmg-singularity-escape"; }
  std::string description() const override {
    return "Pure 4-CMG pyramid under a constant torque request: plain pseudo-inverse, damped "
           "fallback and the singularity-escape (GSR) law at the internal singularity and the envelope";
  }

  void declare(ParamSet& p) const override {
    p.number("duration_s", 35.0, "s",
             "ours: internal case; the singularity is reached at ~15 s, the x envelope (0.09 N m s) at 45 s");
    p.number("duration_sat_s", 70.0, "s", "ours: saturation case; the z envelope (0.104 N m s) is reached at ~52 s");
    p.number("control_period_s", 0.1, "s", "assumed: 10 Hz steering, a small-satellite ADCS rate");
    p.number("skew_deg", 60.0, "deg", kUser);
    p.number("h_cw_Nms", 0.03, "N m s", kUser);
    p.number("gimbal_rate_max_rad_s", 1.0, "rad/s", "assumed: small-CMG gimbal motor limit");
    p.number("torque_Nm", 2e-3, "N m", "issue 15: constant request (x: internal case, z: saturation case)");
    p.number("m_singular", 0.05, "-",
             "ours: 'on the singular surface' while sqrt(det(Xn Xn^T)) < this (0.87 at gamma = 0)");
    p.number("lambda0", EscapeSteeringParams{}.lambda0, "-", "Wie 2005 (GSR inverse)");
    p.number("mu", EscapeSteeringParams{}.mu, "-", "Wie 2005 (GSR inverse)");
    p.number("epsilon0", 0.3, "-",
             "ours: Wie 2005's 0.01 leaves this cluster's elliptic singularity in 19.5 s, 0.1 in 11.5 s, "
             "0.3 in 7.6 s (at 2 mN m on 0.03 N m s rotors); must stay < 0.5");
    p.number("omega_rad_s", EscapeSteeringParams{}.omega_rad_s, "rad/s", "Wie 2005 (GSR inverse)");
    p.number("max_torque_error", EscapeSteeringParams{}.max_torque_error, "-",
             "ours: bound of a usable steering command (SteeringParams / EscapeSteeringParams)");
  }

  RunResult run(const ParamSet& p, const RunContext& ctx) const override {
    Setup s;
    s.T = p.get_number("control_period_s");
    s.t_end = p.get_number("duration_s");
    const double t_end_sat = p.get_number("duration_sat_s");
    if (!(s.T > 0.0) || !(s.t_end >= 10.0 * s.T) || !(t_end_sat >= 10.0 * s.T) || s.t_end / s.T > 1e7 ||
        t_end_sat / s.T > 1e7)
      throw ParamError("cmg-singularity-escape: need control_period_s > 0, durations of 10 to 1e7 periods");
    if (set_cmg_pyramid(p.get_number("skew_deg") * kDeg, p.get_number("h_cw_Nms"), s.g) != Status::ok)
      throw ParamError("cmg-singularity-escape: skew_deg must be in (0, 90) and h_cw_Nms > 0");
    s.m_singular = p.get_number("m_singular");
    const double rate_max = p.get_number("gimbal_rate_max_rad_s");
    const double torque = p.get_number("torque_Nm");
    if (!(s.m_singular > 0.0) || !(rate_max > 0.0) || !(torque > 0.0))
      throw ParamError("cmg-singularity-escape: m_singular, gimbal_rate_max_rad_s and torque_Nm must be > 0");
    s.rate_limit.setConstant(rate_max);
    s.damped.max_torque_error = p.get_number("max_torque_error");
    s.escape.lambda0 = p.get_number("lambda0");
    s.escape.mu = p.get_number("mu");
    s.escape.epsilon0 = p.get_number("epsilon0");
    s.escape.omega_rad_s = p.get_number("omega_rad_s");
    s.escape.max_torque_error = p.get_number("max_torque_error");
    if (!valid(s.damped) || !valid(s.escape))
      throw ParamError("cmg-singularity-escape: steering parameters out of range (lambda0 >= 1e-8, mu >= 0, "
                       "0 <= epsilon0 < 0.5, omega_rad_s >= 0, 0 < max_torque_error <= 1)");

    std::array<LawRun, kLaws> internal, saturation;
    for (int law = 0; law < kLaws; ++law) {
      internal[law] = run_law(s, law, Vec3(torque, 0.0, 0.0), s.t_end);
      saturation[law] = run_law(s, law, Vec3(0.0, 0.0, torque), t_end_sat);
    }

    if (!ctx.csv_path.empty()) {
      std::vector<Column> cols = {{"t", "s"}};
      for (const char* n : kLawNames) {
        for (int i = 1; i <= 4; ++i) cols.push_back({std::string("gamma_") + std::to_string(i) + "_" + n, "rad"});
        cols.push_back({std::string("m_") + n, "-"});
        cols.push_back({std::string("torque_err_") + n, "-"});
      }
      CsvRecorder csv(ctx.csv_path, cols);
      std::vector<double> row;
      for (std::size_t k = 0; k < internal[0].t.size(); ++k) {
        row.assign(1, internal[0].t[k]);
        for (const LawRun& r : internal) {
          row.insert(row.end(), r.gamma[k].begin(), r.gamma[k].end());
          row.push_back(r.m[k]);
          row.push_back(r.err[k]);
        }
        csv.record(row.data());
      }
      csv.close();
    }

    RunResult res;
    Table sat{name() + "-saturation.csv", {"t"}, {"s"}, {saturation[0].t}};
    for (int law = 0; law < kLaws; ++law) {
      sat.names.push_back(std::string("m_") + kLawNames[law]);
      sat.units.push_back("-");
      sat.columns.push_back(saturation[law].m);
      sat.names.push_back(std::string("torque_err_") + kLawNames[law]);
      sat.units.push_back("-");
      sat.columns.push_back(saturation[law].err);
    }
    res.tables.push_back(sat);

    for (int law = 0; law < kLaws; ++law) {
      const std::string n = kLawNames[law];
      const LawRun& r = internal[law];
      res.metrics.push_back({"torque_err_time_above_10pct_s_" + n, r.time_above_10pct_s});
      res.metrics.push_back({"torque_err_max_" + n, r.err_max});
      res.metrics.push_back({"torque_err_mean_" + n, r.err_mean});
      res.metrics.push_back({"torque_err_final_" + n, r.err_final});
      res.metrics.push_back({"singularity_measure_min_" + n, r.m_min});
      res.metrics.push_back({"singular_dwell_s_" + n, dwell_s(r, s.t_end)});
    }
    const LawRun& esc = internal[2];
    // Time to leave the internal singular surface with the escape law (0 if it never came near).
    res.metrics.push_back({"escape_time_s", dwell_s(esc, s.t_end)});
    res.metrics.push_back({"escape_left_singular_surface", esc.t_enter < 0.0 || esc.t_leave >= 0.0 ? 1.0 : 0.0});
    res.metrics.push_back({"escape_steps_request_not_met", double(esc.statuses.count(Status::request_not_met))});
    res.metrics.push_back({"damped_steps_request_not_met", double(internal[1].statuses.count(Status::request_not_met))});
    for (int law = 0; law < kLaws; ++law) {
      const std::string n = kLawNames[law];
      const LawRun& r = saturation[law];
      res.metrics.push_back({"sat_torque_err_time_above_10pct_s_" + n, r.time_above_10pct_s});
      res.metrics.push_back({"sat_momentum_fraction_final_" + n, r.momentum_fraction_final});
    }
    res.metrics.push_back({"sat_escape_steps_request_not_met", double(saturation[2].statuses.count(Status::request_not_met))});

    // Checks of ours (issue 15): the escape law leaves the internal singularity within 10 s and
    // keeps the mean torque error small, while the exact and damped inverses stall there; at the
    // envelope no law delivers, and the escape law's status says so instead of "usable".
    const double dwell_escape = dwell_s(esc, s.t_end);
    const bool escaped = esc.t_enter < 0.0 || (esc.t_leave >= 0.0 && dwell_escape <= 10.0);
    res.claims.push_back({"check", "escape law leaves the internal singularity (sqrt det < m_singular) within",
                          "<= 10 s (ours)", fmt("%.3g s", dwell_escape), escaped});
    res.claims.push_back({"check", "escape law mean torque error over the internal case",
                          "<= half the damped fallback's (ours)",
                          fmt("%.3g", esc.err_mean) + " vs " + fmt("%.3g", internal[1].err_mean),
                          esc.err_mean <= 0.5 * internal[1].err_mean});
    res.claims.push_back({"check", "escape law torque error over the last 5 s of the internal case", "<= 1 % (ours)",
                          fmt("%.3g", esc.err_final), esc.err_final <= 0.01});
    const double stall = std::min(internal[0].time_above_10pct_s, internal[1].time_above_10pct_s);
    res.claims.push_back({"check", "pseudo-inverse and damped fallback stall at the internal singularity",
                          ">= 10 s with torque error > 10 % each (the defect of issue 15)",
                          fmt("%.3g s", stall), stall >= 10.0});
    res.claims.push_back({"check", "at the momentum envelope the escape law reports request_not_met",
                          "> 0 steps (never 'usable' while missing the torque)",
                          fmt("%.0f steps", double(saturation[2].statuses.count(Status::request_not_met))),
                          saturation[2].statuses.count(Status::request_not_met) > 0});

    res.plots = {
        {name() + "-measure.png", "Singularity measure sqrt(det(Xn Xn^T)), torque along +x", "t",
         {"m_pinv", "m_damped", "m_escape"}, "m [-]", false, {}, {}, {}, {{s.m_singular, "singular surface"}}},
        {name() + "-torque-error.png", "Torque error |X u - v| / |v|, torque along +x", "t",
         {"torque_err_pinv", "torque_err_damped", "torque_err_escape"}, "error [-]", false, {}, {}, {},
         {{0.1, "10 %"}}},
        {name() + "-gimbals-escape.png", "Gimbal angles, escape law, torque along +x", "t",
         {"gamma_1_escape", "gamma_2_escape", "gamma_3_escape", "gamma_4_escape"}, "gamma [rad]", false},
        {name() + "-saturation.png", "Torque error toward the momentum envelope (torque along +z)", "t",
         {"torque_err_pinv", "torque_err_damped", "torque_err_escape"}, "error [-]", false, {},
         name() + "-saturation.csv"},
    };
    return res;
  }
};

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

std::unique_ptr<Scenario> make_cmg_singularity_escape() { return std::make_unique<CmgSingularityEscape>(); }

}  // namespace adcs::sim
