#pragma once
// Time series of a campaign's runs, for percentile envelopes (issue 18). Each run's chosen
// columns (e.g. the attitude error) are appended, fsync'ed, to one binary file per shard as
// one record; envelopes (percentiles over the runs at each sample time) are then computed in
// blocks of samples, so memory does not grow with the number of runs, and written to one HDF5
// file per campaign (envelopes_h5.hpp).
//
// Record (native little-endian, as written on this machine): u32 magic 'ADSR', u32 series count
// S, u64 run index, u64 sample count n, then t[n], then y_1[n] .. y_S[n], all binary64.
#include <cstdint>
#include <string>
#include <vector>

namespace adcs::sim::campaign {

struct SeriesRecord {
  std::uint64_t run = 0;
  std::vector<double> t;               //!< [s] sample times
  std::vector<std::vector<double>> y;  //!< one vector per chosen series, each t.size() long
};

//! Appends records durably (write + fsync per record). A resumed file is first cut to its last
//! complete record.
class SeriesWriter {
 public:
  explicit SeriesWriter(const std::string& path, bool resume);
  ~SeriesWriter();
  SeriesWriter(const SeriesWriter&) = delete;
  SeriesWriter& operator=(const SeriesWriter&) = delete;
  void append(const SeriesRecord& r);

 private:
  std::string path_;
  int fd_ = -1;
};

//! Where each record of a series file is (a scan of the file, no samples kept).
struct SeriesIndexEntry {
  std::string path;
  std::uint64_t run = 0, offset = 0, samples = 0, series = 0;
};

//! Scans one file; records after a torn tail are ignored. `valid_bytes` receives the length of
//! the complete records (for resume). Throws std::runtime_error on a record with a bad header.
std::vector<SeriesIndexEntry> index_series_file(const std::string& path, std::uint64_t* valid_bytes = nullptr);

//! The percentile levels of the envelopes (in %), and the envelope of one series.
inline constexpr double kEnvelopeLevels[] = {0.0, 1.0, 5.0, 25.0, 50.0, 75.0, 95.0, 99.0, 100.0};
inline constexpr int kEnvelopeLevelCount = 9;

struct Envelope {
  std::string name;
  std::vector<double> t;
  std::vector<std::vector<double>> percentiles;  //!< [level][sample], levels kEnvelopeLevels
  std::vector<double> mean;
  std::uint64_t runs = 0;                        //!< runs that contributed
};

//! Envelopes of every series over the records `entries` (one per run, sorted by run), on the
//! time grid of the first; a record on another grid is interpolated linearly onto it (NaN outside
//! its span). Reads the files block by block (memory ~ runs x block, not runs x samples).
std::vector<Envelope> compute_envelopes(const std::vector<SeriesIndexEntry>& entries,
                                        const std::vector<std::string>& names);

//! Keeps at most `max_samples` evenly spaced samples of a series (always the last one).
void decimate(SeriesRecord& r, std::size_t max_samples);

}  // namespace adcs::sim::campaign
