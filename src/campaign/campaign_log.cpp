#include "campaign/campaign_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "campaign/seeding.hpp"

namespace adcs::sim::campaign {

const char* to_string(RunStatus s) noexcept {
  switch (s) {
    case RunStatus::ok: return "ok";
    case RunStatus::invalid: return "invalid";
    case RunStatus::failed: return "failed";
  }
  return "?";
}

Json json_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

double number_from_json(const Json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  throw std::runtime_error("not a number: " + s);
}

Json to_json(const RunRow& r) {
  Json j;
  j["run"] = r.run;
  j["seed"] = r.seed;
  j["status"] = to_string(r.status);
  if (!r.error.empty()) j["error"] = r.error;
  Json drawn = Json::array();
  for (std::size_t i = 0; i < r.drawn_names.size(); ++i) drawn.push_back(Json::array({r.drawn_names[i], json_number(r.drawn_values[i])}));
  j["drawn"] = drawn;
  j["sets"] = r.drawn_sets;
  Json metrics = Json::array();
  for (const auto& [k, v] : r.metrics) metrics.push_back(Json::array({k, json_number(v)}));
  j["metrics"] = metrics;
  Json claims = Json::array();
  for (const auto& c : r.claims)
    claims.push_back(Json::array({c.kind, c.claim, c.holds ? Json(*c.holds) : Json(nullptr)}));
  j["claims"] = claims;
  return j;
}

RunRow row_from_json(const Json& j) {
  RunRow r;
  r.run = j.at("run").get<std::uint64_t>();
  r.seed = j.at("seed").get<std::uint64_t>();
  const std::string st = j.at("status").get<std::string>();
  if (st == "ok") r.status = RunStatus::ok;
  else if (st == "invalid") r.status = RunStatus::invalid;
  else if (st == "failed") r.status = RunStatus::failed;
  else throw std::runtime_error("unknown status '" + st + "'");
  if (j.contains("error")) r.error = j.at("error").get<std::string>();
  for (const auto& d : j.at("drawn")) {
    r.drawn_names.push_back(d.at(0).get<std::string>());
    r.drawn_values.push_back(number_from_json(d.at(1)));
  }
  r.drawn_sets = j.at("sets").get<std::vector<std::string>>();
  for (const auto& m : j.at("metrics")) r.metrics.emplace_back(m.at(0).get<std::string>(), number_from_json(m.at(1)));
  for (const auto& c : j.at("claims")) {
    ClaimOutcome o{c.at(0).get<std::string>(), c.at(1).get<std::string>(), std::nullopt};
    if (!c.at(2).is_null()) o.holds = c.at(2).get<bool>();
    r.claims.push_back(std::move(o));
  }
  return r;
}

std::string campaign_id_of(const Json& identity) {
  // The path a target was given by is not part of the identity: every Slurm task may spell the
  // same vehicle file differently (the file's content is, in source_id).
  Json hashed = identity;
  hashed.erase("run_target");
  const std::string text = hashed.dump();
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(mix64(name_hash(text))));
  return buf;
}

LogContents read_log(const std::string& path) {
  std::vector<RunRow> rows;
  LogContents c = scan_log(path, [&](RunRow&& r, const RowSpan&) { rows.push_back(std::move(r)); });
  c.rows = std::move(rows);
  return c;
}

LogContents scan_log(const std::string& path, const std::function<void(RunRow&&, const RowSpan&)>& on_row) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  LogContents c;
  std::uint64_t pos = 0, line_no = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    if (in.eof()) {  // no newline: a line torn by a kill (we always end lines)
      c.torn_tail = true;
      break;
    }
    std::optional<RunRow> row;
    try {
      const Json j = Json::parse(line);
      if (line_no == 1) {
        c.header.identity = j.at("identity");
        c.header.campaign_id = j.at("campaign_id").get<std::string>();
        c.header.shard_index = j.at("shard_index").get<std::uint64_t>();
        c.header.shard_count = j.at("shard_count").get<std::uint64_t>();
        if (campaign_id_of(c.header.identity) != c.header.campaign_id)
          throw std::runtime_error("the header's campaign_id does not match its identity");
      } else {
        row = row_from_json(j);
      }
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": not a campaign log line (" + e.what() + ")");
    }
    // Outside the try: what the caller throws for a well-formed row is its own error.
    if (row) on_row(std::move(*row), RowSpan{pos, line.size()});
    pos += line.size() + 1;
    c.valid_bytes = pos;
  }
  if (in.bad()) throw std::runtime_error(path + ": read failed");
  if (line_no == 0 || c.header.campaign_id.empty()) throw std::runtime_error(path + ": empty campaign log (no header)");
  return c;
}

RunRow read_row_at(const std::string& path, const RowSpan& span) {
  std::ifstream in(path, std::ios::binary);
  std::string line(span.length, '\0');
  if (!in || !in.seekg(static_cast<std::streamoff>(span.offset)) ||
      !in.read(line.data(), static_cast<std::streamsize>(span.length)))
    throw std::runtime_error(path + ": cannot be read at byte " + std::to_string(span.offset));
  try {
    return row_from_json(Json::parse(line));
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": byte " + std::to_string(span.offset) + ": not a campaign log line (" + e.what() + ")");
  }
}

LogWriter::LogWriter(const std::string& path, const LogHeader& h) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error(path + ": cannot be created (" + std::strerror(errno) + ")");
  Json j;
  j["format"] = "adcs-montecarlo-log 1";
  j["campaign_id"] = h.campaign_id;
  j["shard_index"] = h.shard_index;
  j["shard_count"] = h.shard_count;
  j["identity"] = h.identity;
  write_line(j.dump());
}

LogWriter::LogWriter(const std::string& path, std::uint64_t valid_bytes) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error(path + ": cannot be opened (" + std::strerror(errno) + ")");
  if (::ftruncate(fd_, static_cast<off_t>(valid_bytes)) != 0 || ::lseek(fd_, 0, SEEK_END) < 0)
    throw std::runtime_error(path + ": cannot drop the torn last line (" + std::strerror(errno) + ")");
}

LogWriter::~LogWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void LogWriter::append(const RunRow& row) { write_line(to_json(row).dump()); }

void LogWriter::write_line(const std::string& text) {
  const std::string line = text + "\n";
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(path_ + ": write failed (" + std::strerror(errno) + ")");
    }
    done += static_cast<std::size_t>(n);
  }
  // The row is on disk before the run counts as done: a kill (or power loss) after this point
  // cannot lose it, so --resume never runs it again.
  if (::fsync(fd_) != 0) throw std::runtime_error(path_ + ": fsync failed (" + std::strerror(errno) + ")");
}

std::string log_file_name(const std::string& name, std::uint64_t i, std::uint64_t n) {
  if (n == 1) return name + "-montecarlo.log.jsonl";
  return name + "-montecarlo.shard-" + std::to_string(i) + "-of-" + std::to_string(n) + ".log.jsonl";
}

std::string series_file_name(const std::string& name, std::uint64_t i, std::uint64_t n) {
  if (n == 1) return name + "-montecarlo.series.bin";
  return name + "-montecarlo.shard-" + std::to_string(i) + "-of-" + std::to_string(n) + ".series.bin";
}

}  // namespace adcs::sim::campaign
