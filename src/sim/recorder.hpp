#pragma once
// CSV time-series recorder in the format of docs/CONTRACTS.md:
//   # units: t [s], sigma_BN_1 [-], ...
//   t,sigma_BN_1,...
//   0,0.10000000000000001,...
// Values are printed with %.17g, so every double reads back bit-exactly (nan/inf as "nan"/"inf").
#include <Eigen/Core>
#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "sim/sim_error.hpp"

namespace adcs::sim {

struct Column {
  std::string name;  //!< CSV column name, e.g. "sigma_BN_1" (non-empty; no ',', '\n' or '\r')
  std::string unit;  //!< unit shown in the units line, e.g. "s", "rad/s", "-" for dimensionless
};

//! Chosen columns of the time series a run records, captured in memory while it is written (the
//! Monte Carlo envelopes of issue 18: no CSV is read back). While a RowCaptureScope is alive on
//! the calling thread, a CsvRecorder opened on `path` appends each row it writes (after
//! decimation) to `values`, one vector per wanted column; a wanted column the recorder does not
//! have is listed in `missing`.
struct RowCapture {
  std::string path;                          //!< the run's csv_path the capture listens to
  std::vector<std::string> columns;          //!< wanted column names
  std::vector<std::vector<double>> values;   //!< per wanted column, one value per written row
  std::vector<std::string> missing;          //!< wanted columns the recorder lacks
  std::vector<std::string> available;        //!< the recorder's columns (for the error message)
  bool opened = false;                       //!< a recorder opened `path`
};

//! Installs a capture for the calling thread for its lifetime (scoped, like ProgressScope).
class RowCaptureScope {
 public:
  explicit RowCaptureScope(RowCapture& c);
  ~RowCaptureScope();
  RowCaptureScope(const RowCaptureScope&) = delete;
  RowCaptureScope& operator=(const RowCaptureScope&) = delete;

 private:
  RowCapture* previous_;
};

//! Writes one row per kept record() call: with decimation k, calls 0, k, 2k, ... are written.
//! record_final() is meant for the last sample: it always writes, whatever the decimation, so the
//! end of the run is in the file. Not copyable; movable.
class CsvRecorder {
 public:
  //! Opens (truncates) path and writes the two header lines. Throws SimError if the file cannot
  //! be opened, a column name is invalid, columns is empty, or decimation < 1.
  CsvRecorder(const std::string& path, std::vector<Column> columns, int decimation = 1);
  ~CsvRecorder();  //!< Closes the file; errors are swallowed (call close() to see them).
  CsvRecorder(const CsvRecorder&) = delete;
  CsvRecorder& operator=(const CsvRecorder&) = delete;
  CsvRecorder(CsvRecorder&&) noexcept;
  CsvRecorder& operator=(CsvRecorder&&) noexcept;

  //! values: one per column, in column order. The list and Eigen overloads throw SimError on a
  //! size mismatch; all throw SimError after close() or on a write error.
  void record(const double* values);
  void record(std::initializer_list<double> values);
  void record(const Eigen::Ref<const Eigen::VectorXd>& values);
  void record_final(const double* values);
  void record_final(std::initializer_list<double> values);
  void record_final(const Eigen::Ref<const Eigen::VectorXd>& values);
  //! record(row), or record_final(row) when `final` (the loop's last observation, at t_end):
  //! the one "a row, or the final row" of every scenario. Throws SimError on a size mismatch.
  void record_row(const std::vector<double>& row, bool final);

  //! Flushes and closes; throws SimError if a write or the close failed. Idempotent.
  void close();

  const std::vector<Column>& columns() const noexcept { return columns_; }
  const std::string& path() const noexcept { return path_; }
  std::size_t rows_written() const noexcept { return rows_written_; }

 private:
  struct FileCloser {
    void operator()(std::FILE* f) const noexcept { std::fclose(f); }
  };
  void submit(const double* values, bool always_write);
  void check_size(std::size_t n) const;

  std::string path_;
  std::vector<Column> columns_;
  std::size_t decimation_ = 1;
  std::size_t calls_ = 0;         //!< record()/record_final() calls so far
  std::size_t rows_written_ = 0;  //!< data rows in the file
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::string line_;  //!< row buffer, reused
  RowCapture* capture_ = nullptr;          //!< the thread's capture, when it listens to path_
  std::vector<std::size_t> capture_index_; //!< recorder column of each wanted column
};

}  // namespace adcs::sim
