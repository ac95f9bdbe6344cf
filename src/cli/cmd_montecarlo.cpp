// adcs-sim montecarlo NAME|FILE --runs R: a dispersed Monte Carlo campaign (issue 18,
// docs/CAMPAIGNS.md, src/campaign/): --disperse KEY=EXPR, --jobs N, --shard i/N|auto[/N],
// --resume, --series COL, --rank-by METRIC. An unsplit campaign writes DIR/NAME-montecarlo.csv,
// .json and (with --series) -series.h5; a shard writes its log, joined later by `merge`.
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <thread>

#include "campaign/campaign.hpp"
#include "campaign/finalize.hpp"
#include "cli/command_line.hpp"
#include "cli/command_table.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "cli/scenario_runs.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

constexpr std::uint64_t kMaxRuns = 10000000;

struct Shard {
  std::uint64_t index = 0, count = 1;
};

std::uint64_t env_uint(const char* name) {
  const char* v = std::getenv(name);
  if (!v || !*v) throw UsageError(std::string("--shard auto: ") + name + " is not set");
  return parse_uint(std::string("--shard auto: ") + name, v);
}

//! "i/N", "auto" (Slurm array variables) or "auto/N" (Kubernetes' JOB_COMPLETION_INDEX, or
//! Slurm's task id with N given).
Shard parse_shard(const std::string& text) {
  Shard s;
  const auto slash = text.find('/');
  const std::string head = text.substr(0, slash);
  if (head == "auto") {
    const bool slurm = std::getenv("SLURM_ARRAY_TASK_ID") != nullptr;
    if (slurm) {
      const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
      const std::uint64_t id = env_uint("SLURM_ARRAY_TASK_ID"), lo = min && *min ? env_uint("SLURM_ARRAY_TASK_MIN") : 0;
      if (id < lo) throw UsageError("--shard auto: SLURM_ARRAY_TASK_ID below SLURM_ARRAY_TASK_MIN");
      s.index = id - lo;
    } else if (std::getenv("JOB_COMPLETION_INDEX")) {
      s.index = env_uint("JOB_COMPLETION_INDEX");
    } else {
      throw UsageError("--shard auto: neither SLURM_ARRAY_TASK_ID nor JOB_COMPLETION_INDEX is set");
    }
    if (slash != std::string::npos) s.count = parse_uint("--shard auto/N", text.substr(slash + 1));
    else if (slurm) s.count = env_uint("SLURM_ARRAY_TASK_COUNT");
    else throw UsageError("--shard auto with JOB_COMPLETION_INDEX needs the shard count: --shard auto/N");
  } else {
    if (slash == std::string::npos) throw UsageError("--shard expects i/N, auto or auto/N, got '" + text + "'");
    s.index = parse_uint("--shard i", head);
    s.count = parse_uint("--shard N", text.substr(slash + 1));
  }
  if (s.count < 1 || s.index >= s.count)
    throw UsageError("--shard " + std::to_string(s.index) + "/" + std::to_string(s.count) +
                     ": the index must be in 0.." + (s.count ? std::to_string(s.count - 1) : std::string("N-1")));
  return s;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

void declare_montecarlo(CommandLine& cl, Options& o) {
  declare_scenario_name(cl, o);
  cl.once("--runs", [&o](const std::string& v) {
    o.runs = parse_uint("--runs", v);
    if (*o.runs < 1 || *o.runs > kMaxRuns)
      throw UsageError("--runs must be between 1 and " + std::to_string(kMaxRuns) + ", got " + v);
  });
  cl.once("--seed0", [&o](const std::string& v) { o.seed0 = parse_uint("--seed0", v); });
  cl.repeatable("--disperse", [&o](const std::string& v) { o.disperse.push_back(v); });
  cl.once("--jobs", [&o](const std::string& v) {
    o.jobs = parse_uint("--jobs", v);
    if (*o.jobs < 1 || *o.jobs > 1024) throw UsageError("--jobs must be between 1 and 1024, got " + v);
  });
  cl.once("--shard", [&o](const std::string& v) {
    parse_shard(v);  // checked here, where the word is (the environment does not change)
    o.shard = v;
  });
  cl.flag("--resume", o.resume);
  cl.repeatable("--series", [&o](const std::string& v) {
    for (const std::string& c : split_commas(v)) o.series.push_back(c);
  });
  cl.once("--rank-by", [&o](const std::string& v) { o.rank_by = v; });
  declare_out(cl, o);
  declare_sets(cl, o);
  declare_progress(cl, o);
  cl.misplaced("--seed", "montecarlo takes --seed0 S (each run's seed is drawn from S and its index), not --seed");
}

void check_montecarlo(const Options& o) {
  if (!o.runs) throw UsageError("montecarlo needs --runs R");
}

int cmd_montecarlo(const Options& o, const CommandIo& io) {
  const Scenario& s = lookup(io.catalog, o.scenario);
  campaign::CampaignPlan plan;
  plan.scenario = &s;
  plan.name = s.name();
  plan.run_target = o.scenario;
  plan.source_id = target_source_id(o.scenario);
  plan.params = declared_params(s, o.sets);
  plan.sets = o.sets;
  for (const std::string& d : o.disperse) plan.dispersions.push_back(campaign::parse_dispersion(d));
  plan.runs = *o.runs;
  plan.seed0 = o.seed0.value_or(1);
  plan.series = o.series;
  plan.rank_metric = o.rank_by.value_or("");
  campaign::ExecOptions exec;
  exec.jobs = static_cast<unsigned>(o.jobs.value_or(std::max(1u, std::thread::hardware_concurrency())));
  if (o.shard) {
    const Shard sh = parse_shard(*o.shard);
    exec.shard_index = sh.index;
    exec.shard_count = sh.count;
  }
  exec.resume = o.resume;
  exec.out_dir = o.out_dir.value_or("out");
  exec.progress = &io.err;
  exec.progress_is_terminal = io.err_is_terminal;
  campaign::CampaignCounts counts;
  try {
    counts = campaign::run_campaign(plan, exec);
  } catch (const ParamError&) {
    throw;
  } catch (const std::runtime_error& e) {  // the log or an output file could not be written
    throw IoError(e.what());
  }
  if (exec.shard_count > 1) {
    io.out << "shard " << exec.shard_index << "/" << exec.shard_count << " of " << plan.name << ": " << counts.ok
           << " ok, " << counts.invalid << " invalid, " << counts.failed << " failed, " << counts.resumed
           << " already done; join the shards with: " << kProg << " merge " << exec.out_dir.string() << '\n';
    return kExitOk;
  }
  const campaign::FinalizeResult& r = counts.tables;  // written once, by run_campaign
  io.out << "wrote " << r.csv_path << " and " << r.json_path << (r.series_path.empty() ? "" : " and " + r.series_path) << '\n';
  io.out << json_text(r.summary_line) << std::endl;
  return kExitOk;
}

}  // namespace adcs::sim::cli
