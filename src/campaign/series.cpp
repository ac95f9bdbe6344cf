#include "campaign/series.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "campaign/statistics.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

constexpr std::uint32_t kMagic = 0x52534441u;  // "ADSR" in the file (little-endian)
constexpr std::uint64_t kHeaderBytes = 4 + 4 + 8 + 8;

void write_all(int fd, const void* data, std::size_t n, const std::string& path) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(path + ": write failed (" + std::strerror(errno) + ")");
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

void read_at(int fd, void* data, std::size_t n, std::uint64_t offset, const std::string& path) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t r = ::pread(fd, p, n, static_cast<off_t>(offset));
    if (r <= 0) {
      if (r < 0 && errno == EINTR) continue;
      throw std::runtime_error(path + ": read failed");
    }
    p += r;
    n -= static_cast<std::size_t>(r);
    offset += static_cast<std::uint64_t>(r);
  }
}

//! y at time t by linear interpolation of (ts, ys); NaN outside [ts.front(), ts.back()].
double interpolate(const std::vector<double>& ts, const std::vector<double>& ys, double t) {
  if (ts.empty() || t < ts.front() || t > ts.back()) return std::numeric_limits<double>::quiet_NaN();
  const auto it = std::lower_bound(ts.begin(), ts.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - ts.begin());
  if (ts[i] == t || i == 0) return ys[i];
  const double w = (t - ts[i - 1]) / (ts[i] - ts[i - 1]);
  return ys[i - 1] + w * (ys[i] - ys[i - 1]);
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

SeriesWriter::SeriesWriter(const std::string& path, bool resume) : path_(path) {
  std::uint64_t valid = 0;
  if (resume) index_series_file(path, &valid);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | (resume ? 0 : O_EXCL), 0644);
  if (fd_ < 0) throw std::runtime_error(path + ": cannot be opened (" + std::strerror(errno) + ")");
  if (::ftruncate(fd_, static_cast<off_t>(valid)) != 0 || ::lseek(fd_, 0, SEEK_END) < 0)
    throw std::runtime_error(path + ": cannot drop a torn record (" + std::strerror(errno) + ")");
}

SeriesWriter::~SeriesWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void SeriesWriter::append(const SeriesRecord& r) {
  const std::uint32_t magic = kMagic, s = static_cast<std::uint32_t>(r.y.size());
  const std::uint64_t n = r.t.size();
  std::vector<char> buf(kHeaderBytes + 8 * n * (1 + r.y.size()));
  char* p = buf.data();
  std::memcpy(p, &magic, 4);
  std::memcpy(p + 4, &s, 4);
  std::memcpy(p + 8, &r.run, 8);
  std::memcpy(p + 16, &n, 8);
  p += kHeaderBytes;
  std::memcpy(p, r.t.data(), 8 * n);
  p += 8 * n;
  for (const auto& y : r.y) {
    if (y.size() != n) throw std::runtime_error(path_ + ": a series has another length than its times");
    std::memcpy(p, y.data(), 8 * n);
    p += 8 * n;
  }
  write_all(fd_, buf.data(), buf.size(), path_);
  if (::fsync(fd_) != 0) throw std::runtime_error(path_ + ": fsync failed (" + std::strerror(errno) + ")");
}

std::vector<SeriesIndexEntry> index_series_file(const std::string& path, std::uint64_t* valid_bytes) {
  std::vector<SeriesIndexEntry> out;
  if (valid_bytes) *valid_bytes = 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return out;
    throw std::runtime_error(path + ": cannot be read (" + std::strerror(errno) + ")");
  }
  struct stat st {};
  ::fstat(fd, &st);
  const std::uint64_t size = static_cast<std::uint64_t>(st.st_size);
  std::uint64_t off = 0;
  try {
    while (off + kHeaderBytes <= size) {
      char h[kHeaderBytes];
      read_at(fd, h, kHeaderBytes, off, path);
      std::uint32_t magic = 0, s = 0;
      std::uint64_t run = 0, n = 0;
      std::memcpy(&magic, h, 4);
      std::memcpy(&s, h + 4, 4);
      std::memcpy(&run, h + 8, 8);
      std::memcpy(&n, h + 16, 8);
      if (magic != kMagic || s > 1024 || n > (std::uint64_t{1} << 32))
        throw std::runtime_error(path + ": not a series record at byte " + std::to_string(off));
      const std::uint64_t len = kHeaderBytes + 8 * n * (1 + s);
      if (off + len > size) break;  // torn tail
      out.push_back({path, run, off, n, s});
      off += len;
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  if (valid_bytes) *valid_bytes = off;
  return out;
}

void decimate(SeriesRecord& r, std::size_t max_samples) {
  const std::size_t n = r.t.size();
  if (n <= max_samples || max_samples < 2) return;
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < max_samples; ++i) keep.push_back(i * (n - 1) / (max_samples - 1));
  auto pick = [&](std::vector<double>& v) {
    std::vector<double> o;
    o.reserve(keep.size());
    for (std::size_t i : keep) o.push_back(v[i]);
    v.swap(o);
  };
  pick(r.t);
  for (auto& y : r.y) pick(y);
}

std::vector<Envelope> compute_envelopes(const std::vector<SeriesIndexEntry>& entries,
                                        const std::vector<std::string>& names) {
  std::vector<Envelope> env(names.size());
  for (std::size_t s = 0; s < names.size(); ++s) env[s].name = names[s];
  if (entries.empty()) return env;
  std::vector<int> fds;
  std::vector<std::string> paths;
  auto fd_of = [&](const std::string& path) {
    for (std::size_t i = 0; i < paths.size(); ++i)
      if (paths[i] == path) return fds[i];
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error(path + ": cannot be read");
    paths.push_back(path);
    fds.push_back(fd);
    return fd;
  };
  auto read_vec = [&](const SeriesIndexEntry& e, std::uint64_t which, std::uint64_t first, std::uint64_t count) {
    std::vector<double> v(count);  // which 0: t, 1..S: series
    read_at(fd_of(e.path), v.data(), 8 * count, e.offset + kHeaderBytes + 8 * (which * e.samples + first), e.path);
    return v;
  };
  try {
    const SeriesIndexEntry& ref = entries.front();
    const std::vector<double> grid = read_vec(ref, 0, 0, ref.samples);
    for (auto& e : env) {
      e.t = grid;
      e.percentiles.assign(kEnvelopeLevelCount, std::vector<double>(grid.size()));
      e.mean.assign(grid.size(), 0.0);
      e.runs = entries.size();
    }
    // Records on another grid are interpolated (their full series is small; read once per block).
    std::vector<char> same(entries.size());
    for (std::size_t r = 0; r < entries.size(); ++r) {
      if (entries[r].series != names.size())
        throw std::runtime_error(entries[r].path + ": run " + std::to_string(entries[r].run) + " has " +
                                 std::to_string(entries[r].series) + " series, the campaign " + std::to_string(names.size()));
      same[r] = entries[r].samples == grid.size() && read_vec(entries[r], 0, 0, entries[r].samples) == grid;
    }
    // A block of samples of every run is in memory at once: about 2^18 values (2 MiB) whatever the
    // number of runs (the blocks only change how often the files are read, not the envelopes).
    const std::size_t block = std::max<std::size_t>(16, (std::size_t{1} << 18) / std::max<std::size_t>(1, entries.size()));
    std::vector<double> column;
    for (std::size_t s = 0; s < names.size(); ++s) {
      for (std::size_t b0 = 0; b0 < grid.size(); b0 += block) {
        const std::size_t nb = std::min(block, grid.size() - b0);
        std::vector<std::vector<double>> vals(nb);  // [sample in block][run]
        for (auto& v : vals) v.reserve(entries.size());  // exactly, not up to twice by growing
        for (std::size_t r = 0; r < entries.size(); ++r) {
          std::vector<double> y;
          if (same[r]) {
            y = read_vec(entries[r], 1 + s, b0, nb);
          } else {
            const std::vector<double> tr = read_vec(entries[r], 0, 0, entries[r].samples);
            const std::vector<double> yr = read_vec(entries[r], 1 + s, 0, entries[r].samples);
            for (std::size_t i = 0; i < nb; ++i) y.push_back(interpolate(tr, yr, grid[b0 + i]));
          }
          for (std::size_t i = 0; i < nb; ++i) vals[i].push_back(y[i]);
        }
        for (std::size_t i = 0; i < nb; ++i) {
          column = vals[i];
          column.erase(std::remove_if(column.begin(), column.end(), [](double x) { return !std::isfinite(x); }), column.end());
          std::sort(column.begin(), column.end());
          for (int l = 0; l < kEnvelopeLevelCount; ++l)
            env[s].percentiles[static_cast<std::size_t>(l)][b0 + i] = percentile_sorted(column, kEnvelopeLevels[l]);
          env[s].mean[b0 + i] = summarize(column).mean;
        }
      }
    }
  } catch (...) {
    for (int fd : fds) ::close(fd);
    throw;
  }
  for (int fd : fds) ::close(fd);
  return env;
}

}  // namespace adcs::sim::campaign
