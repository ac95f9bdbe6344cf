#include "sim/recorder.hpp"

#include <utility>

namespace adcs::sim {

namespace {

void check_column(const Column& c) {
  if (c.name.empty() || c.name.find_first_of(",\n\r") != std::string::npos ||
      c.unit.find_first_of(",\n\r") != std::string::npos)
    throw SimError("CsvRecorder: invalid column '" + c.name + "' [" + c.unit +
                   "] (names must be non-empty; no commas or line breaks)");
}

thread_local RowCapture* t_capture = nullptr;

}  // namespace

RowCaptureScope::RowCaptureScope(RowCapture& c) : previous_(t_capture) { t_capture = &c; }
RowCaptureScope::~RowCaptureScope() { t_capture = previous_; }

CsvRecorder::CsvRecorder(const std::string& path, std::vector<Column> columns, int decimation)
    : path_(path), columns_(std::move(columns)) {
  if (columns_.empty()) throw SimError("CsvRecorder: no columns for " + path_);
  if (decimation < 1)
    throw SimError("CsvRecorder: decimation must be >= 1, got " + std::to_string(decimation));
  decimation_ = static_cast<std::size_t>(decimation);
  for (const Column& c : columns_) check_column(c);

  if (t_capture && t_capture->path == path_) {
    capture_ = t_capture;
    capture_->opened = true;
    capture_->values.assign(capture_->columns.size(), {});
    for (const Column& c : columns_) capture_->available.push_back(c.name);
    for (const std::string& want : capture_->columns) {
      std::size_t k = 0;
      while (k < columns_.size() && columns_[k].name != want) ++k;
      if (k == columns_.size()) capture_->missing.push_back(want);
      capture_index_.push_back(k);
    }
  }
  file_.reset(std::fopen(path_.c_str(), "w"));
  if (!file_) throw SimError("CsvRecorder: cannot open " + path_ + " for writing");

  std::string header = "# units: ";
  std::string names;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) {
      header += ", ";
      names += ',';
    }
    header += columns_[i].name + " [" + columns_[i].unit + "]";
    names += columns_[i].name;
  }
  header += '\n';
  names += '\n';
  if (std::fputs(header.c_str(), file_.get()) < 0 || std::fputs(names.c_str(), file_.get()) < 0)
    throw SimError("CsvRecorder: write to " + path_ + " failed");
}

CsvRecorder::~CsvRecorder() {
  try {
    close();
  } catch (...) {  // why: a destructor must not throw; close() reports errors to who asks
  }
}

CsvRecorder::CsvRecorder(CsvRecorder&&) noexcept = default;
CsvRecorder& CsvRecorder::operator=(CsvRecorder&&) noexcept = default;

void CsvRecorder::record(const double* values) { submit(values, false); }

void CsvRecorder::record(std::initializer_list<double> values) {
  check_size(values.size());
  submit(values.begin(), false);
}

void CsvRecorder::record(const Eigen::Ref<const Eigen::VectorXd>& values) {
  check_size(static_cast<std::size_t>(values.size()));
  submit(values.data(), false);
}

void CsvRecorder::record_final(const double* values) { submit(values, true); }

void CsvRecorder::record_row(const std::vector<double>& row, bool final) {
  check_size(row.size());
  submit(row.data(), final);
}

void CsvRecorder::record_final(std::initializer_list<double> values) {
  check_size(values.size());
  submit(values.begin(), true);
}

void CsvRecorder::record_final(const Eigen::Ref<const Eigen::VectorXd>& values) {
  check_size(static_cast<std::size_t>(values.size()));
  submit(values.data(), true);
}

void CsvRecorder::check_size(std::size_t n) const {
  if (n != columns_.size())
    throw SimError("CsvRecorder: " + std::to_string(n) + " values for " +
                   std::to_string(columns_.size()) + " columns in " + path_);
}

void CsvRecorder::submit(const double* values, bool always_write) {
  if (!file_) throw SimError("CsvRecorder: record() after close() on " + path_);
  const bool keep = always_write || calls_ % decimation_ == 0;
  ++calls_;
  if (!keep) return;
  line_.clear();
  char buffer[32];  // "%.17g" needs at most 24 characters ("-2.2250738585072014e-308")
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) line_ += ',';
    const int n = std::snprintf(buffer, sizeof buffer, "%.17g", values[i]);
    line_.append(buffer, static_cast<std::size_t>(n));
  }
  line_ += '\n';
  if (std::fwrite(line_.data(), 1, line_.size(), file_.get()) != line_.size())
    throw SimError("CsvRecorder: write to " + path_ + " failed");
  ++rows_written_;
  if (capture_)
    for (std::size_t c = 0; c < capture_index_.size(); ++c)
      if (capture_index_[c] < columns_.size()) capture_->values[c].push_back(values[capture_index_[c]]);
}

void CsvRecorder::close() {
  if (!file_) return;
  std::FILE* f = file_.release();
  const bool write_error = std::ferror(f) != 0;
  const bool close_error = std::fclose(f) != 0;
  if (write_error || close_error) throw SimError("CsvRecorder: writing " + path_ + " failed");
}

}  // namespace adcs::sim
