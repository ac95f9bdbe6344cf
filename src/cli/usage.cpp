#include "cli/commands.hpp"

namespace adcs::sim::cli {

// Written by hand, not CLI11's generated help: its wording and layout are part of the contract
// (README.md, "adcs-sim"), and CLI11 would print one text per command.
std::string usage() {
  return R"(usage: adcs-sim COMMAND [ARGS]

commands:
  list                      scenario names, one a line
  describe NAME             NAME's description and parameters (default, unit, source)
  run NAME [--set KEY=VALUE]... [--seed N] [--out DIR] [--progress]
                            run once; writes DIR/NAME.csv (time series) and DIR/NAME.json
                            (every value used incl. --seed draws, metrics, claims, plots)
  montecarlo NAME --runs R [--seed0 S] [--disperse KEY=EXPR]... [--jobs N] [--shard i/N]
             [--resume] [--series COL] [--rank-by METRIC] [--out DIR] [--set KEY=VALUE]...
                            R dispersed runs (docs/CAMPAIGNS.md); writes DIR/NAME-montecarlo.csv
                            (one row per run), .json (statistics, claim pass counts, worst
                            runs with their rerun commands) and -series.h5 (with --series)
  merge DIR... [--out DIR]  joins the shard logs of one campaign into those tables
  help                      this text

NAME is a registered scenario (list) or a vehicle file (a path ending in .toml or holding a
'/', docs/VEHICLE-FILES.md) whose parameters are addressed by their dotted path.

options:
  --set KEY=VALUE  override a parameter (repeatable, each KEY once). VALUE is a number
                   (1e-3, -2, 0.5), a vector [a,b,c], a matrix [[a,b],[c,d]] (row-major)
                   or a name (adams). Every scenario has duration_s and control_period_s.
  --seed N         random seed of run (default 0)
  --runs R         number of Monte Carlo runs (required)
  --seed0 S        the campaign's seed (default 1): run k draws from (S, k, KEY) only
  --disperse KEY=EXPR  disperse a number, vector or matrix parameter (repeatable): normal(mu,sd),
                   uniform(a,b), truncnormal(mu,sd,lo,hi), rel_normal(sd), rel_uniform(a),
                   inertia(rel_sd,rot_sd_deg), axes(sd_deg)
  --jobs N         runs at once (default: all cores); the results do not depend on it
  --shard i/N      run only the runs k with k mod N = i (auto: Slurm's SLURM_ARRAY_TASK_ID and
                   SLURM_ARRAY_TASK_COUNT; auto/N: Kubernetes' JOB_COMPLETION_INDEX)
  --resume         continue a killed campaign from its log (DIR/NAME-montecarlo*.log.jsonl)
  --series COL     keep these time-series columns (comma-separated, repeatable) for the
                   percentile envelopes in NAME-montecarlo-series.h5
  --rank-by METRIC the metric the worst runs are ranked by (default: the first)
  --out DIR        output directory (default out; created if missing)
  --progress       progress on stderr (simulated time, wall time, ETA) at most once a second,
                   and a final line; shown anyway, in place, when stderr is a terminal and the
                   run lasts over 3 s. stdout is the same either way.
  Options also accept the form --opt=VALUE.

Refused before running (exit 2): duration_s or control_period_s <= 0; more than 1e8 steps
(duration_s / control_period_s, or duration_s / rk4_step_s with integrator=rk4); where
declared, rtol outside (0, 1), atol <= 0, rk4_step_s <= 0.

The last line on stdout is one JSON object: {"scenario": ..., "seed": N, "metrics": {...}}
for run, {"scenario": ..., "runs": R, "seed0": S, "counts": {...}, "metrics": {m: {"min",
"median", "max"}}} for montecarlo and merge. Errors are one line on stderr; exit status 2 for a bad command line (unknown
scenario, option, parameter or value), 1 if the simulation or writing fails. Either way no
output file is left behind.
)";
}

}  // namespace adcs::sim::cli
