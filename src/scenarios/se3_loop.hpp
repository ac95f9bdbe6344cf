#pragma once
// Seed 003 closed loop (spec §A.5, §A.8), shared by the single-run scenarios se3-ptc/se3-ftsmc
// (se3.cpp) and the multi-run campaign se3-campaign (se3_campaign.cpp): the parameters every run
// declares, the configuration read from them, and one simulated 200 s run with its per-tick record.
// Truth model, integrator and per-tick order are described in se3_loop.cpp.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "scenarios/params.hpp"
#include "scenarios/verdicts.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace adcs::sim::se3 {

constexpr double kRad2Deg = 180.0 / 3.14159265358979323846;

enum class Law { ptc, ftsmc };

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
  bool single = false;  //!< `--set scalar=float`: the law runs in float (issue 19), the plant in double
};

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

//! Parameters shared by every seed-003 run: environment, chaser/target, disturbance, limits,
//! quantizer, metric bands, integrator (not the initial state, not the law's gains).
void declare_environment(ParamSet& p);
//! BsPdTC gains (spec A.8 Table 1), T_s included.
void declare_ptc_gains(ParamSet& p);
//! FTSMC gains (spec A.8 Table 2).
void declare_ftsmc_gains(ParamSet& p);

//! Everything but the law's gains; state 1 unless the set declares `initial_state`.
Se3Config common_config(const ParamSet& p);
//! common_config plus the gains of `law` (which the set must declare).
Se3Config make_config(const ParamSet& p, Law law);

//! True when every parameter that changes the physics, the law or the measurement is at its
//! default (the state, T, the integrator and the CSV may differ): the spec's prototype table
//! (Appendix C.3) then applies and the claims get a verdict.
bool prototype_conditions(const ParamSet& p);

//! One closed-loop run; writes its time series to csv_path unless it is empty. Throws ParamError
//! for rejected parameters, SimError when the loop diverges.
Outcome simulate(const Se3Config& c, Law law, const std::string& csv_path);

//! Steady bounds of one run (spec A.9): max |.| over the ticks in [window0, window1]; NaN when
//! the run has no tick there. The same numbers as the single runs' *_ss metrics.
struct Steady {
  double att_deg = NAN, pos_m = NAN, rate_deg_s = NAN, vel_m_s = NAN;
};
Steady steady_bounds(const Outcome& o, const Se3Config& c);

//! Paper verdict of a statement made of several parts (e.g. "settles before T, in about 90.5 s"):
//! reproduced when every part is, not reproduced when none is even partly, else partly
//! (verdict_if: the run shows the statement only in part).
inline PaperVerdict all_parts(std::initializer_list<PaperVerdict> parts) {
  bool all = true, some = false;
  for (PaperVerdict v : parts) {
    all = all && v == PaperVerdict::reproduced;
    some = some || v != PaperVerdict::not_reproduced;
  }
  return verdict_if(all, some);
}

//! The BsPdTC's and the FTSMC's steady bounds from one initial state (same conditions).
struct SteadyPair {
  int state;
  Steady ptc, fts;
};
//! The paper's accuracy comparison (§3.2 2), conclusion 4): "the BsPdTC's control accuracy is also
//! slightly higher than the FTSMC's" (state 1: 3.72e-3 vs 4.77e-3 deg, 3.28e-5 vs 5.58e-5 m).
//! Paper verdict (when `judged`, i.e. the paper's conditions): the BsPdTC's steady max |θ_i| and
//! max |β_i| no larger than the FTSMC's in every pair; `ours` gives the ratios BsPdTC/FTSMC.
//! No criterion of ours: the spec has no item for this comparison (informative, holds empty).
Claim accuracy_comparison_claim(const std::vector<SteadyPair>& pairs, bool judged);

}  // namespace adcs::sim::se3
