#pragma once
// The durable record of a campaign shard (issue 18): a JSON Lines file, one header line (the
// campaign's identity and this shard), then one line per finished run, appended and fsync'ed the
// moment the run ends. A kill loses at most the run in progress; --resume reads the file back,
// drops a torn last line, and runs only what is missing. Lines are in completion order; the
// campaign's tables are built from them sorted by run index (finalize.hpp), so they do not
// depend on --jobs, on the shard split or on the order runs finished in.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace adcs::sim::campaign {

using Json = nlohmann::ordered_json;

enum class RunStatus { ok, invalid, failed };
const char* to_string(RunStatus s) noexcept;

//! A claim row's outcome in one run (scenario.hpp's Claim, reduced to what is counted).
struct ClaimOutcome {
  std::string kind, claim;
  std::optional<bool> holds;
};

//! One finished run.
struct RunRow {
  std::uint64_t run = 0;   //!< index in the campaign, 0 .. runs-1
  std::uint64_t seed = 0;  //!< the scenario seed it ran with (seeding.hpp run_seed)
  RunStatus status = RunStatus::ok;
  std::string error;  //!< why it is invalid / failed (one line)
  std::vector<std::string> drawn_names;  //!< element-wise ("KEY[i][j]"), in --disperse order
  std::vector<double> drawn_values;
  std::vector<std::string> drawn_sets;  //!< the same draws as --set texts "KEY=VALUE" (rerun command)
  std::vector<std::pair<std::string, double>> metrics;
  std::vector<ClaimOutcome> claims;
};

Json to_json(const RunRow& r);
RunRow row_from_json(const Json& j);  //!< throws std::runtime_error on a malformed row

//! A finite number as itself, NaN / ±inf as the strings "nan", "inf", "-inf" (JSON has no
//! such numbers; nlohmann would write null and lose which one it was).
Json json_number(double x);
double number_from_json(const Json& j);

//! The header line: the campaign's identity (what makes two shards parts of one campaign) and
//! the shard this file holds.
struct LogHeader {
  Json identity;               //!< scenario, sets, dispersions, seed0, runs, series, parameters, ...
  std::string campaign_id;     //!< hex hash of identity
  std::uint64_t shard_index = 0, shard_count = 1;
};

std::string campaign_id_of(const Json& identity);

//! What a log file holds.
struct LogContents {
  LogHeader header;
  std::vector<RunRow> rows;
  std::uint64_t valid_bytes = 0;  //!< up to the end of the last complete line
  bool torn_tail = false;         //!< a partial last line (a kill mid-write) was dropped
};

//! Reads a log; throws std::runtime_error naming the file and line when it is not one.
LogContents read_log(const std::string& path);

//! Where a row's line is in its log file (for read_row_at).
struct RowSpan {
  std::uint64_t offset = 0, length = 0;  //!< bytes, without the newline
};

//! Reads a log line by line without keeping its rows (a campaign of many runs is read in memory
//! that does not grow with the runs): `on_row` is called with each complete row, in file order,
//! and where its line is. Returns what read_log() does, with `rows` empty; the same errors.
LogContents scan_log(const std::string& path, const std::function<void(RunRow&&, const RowSpan&)>& on_row);

//! The row whose line is at `span` of the log file `path` (a span scan_log() gave); throws
//! std::runtime_error naming the file and byte offset when it cannot be read or parsed.
RunRow read_row_at(const std::string& path, const RowSpan& span);

//! Appends rows to a log, each fsync'ed before append() returns. Opening a new file writes the
//! header; opening an existing one (resume) truncates it to `valid_bytes` first.
class LogWriter {
 public:
  //! New log (the file must not exist).
  LogWriter(const std::string& path, const LogHeader& header);
  //! Existing log, resumed: cut to `valid_bytes` (drops a torn last line).
  LogWriter(const std::string& path, std::uint64_t valid_bytes);
  ~LogWriter();
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;
  void append(const RunRow& row);  //!< throws std::runtime_error on a write or fsync failure

 private:
  void write_line(const std::string& line);
  std::string path_;
  int fd_ = -1;
};

//! The log file name of shard i of n of campaign NAME ("NAME-montecarlo.log.jsonl" for 0 of 1).
std::string log_file_name(const std::string& name, std::uint64_t shard_index, std::uint64_t shard_count);
std::string series_file_name(const std::string& name, std::uint64_t shard_index, std::uint64_t shard_count);

}  // namespace adcs::sim::campaign
