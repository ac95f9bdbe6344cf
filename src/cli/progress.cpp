#include "cli/progress.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <utility>

namespace adcs::sim::cli {

std::string format_wall(double s) {
  char buf[48];
  if (!std::isfinite(s) || s < 0.0) return "?";
  if (s < 60.0) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else if (s < 3600.0) {
    const long v = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", v / 60, v % 60);
  } else {
    const double h = std::floor(s / 3600.0);
    std::snprintf(buf, sizeof buf, "%.0f h %02ld min", h,
                  std::lround(std::floor((s - 3600.0 * h) / 60.0)));
  }
  return buf;
}

ProgressReporter::ProgressReporter(std::ostream& err, std::string label, bool requested,
                                   bool terminal, Clock clock)
    : err_(err), label_(std::move(label)), requested_(requested), terminal_(terminal),
      clock_(std::move(clock)) {
  wall0_ = now();
}

ProgressReporter::~ProgressReporter() {
  if (open_line_) {
    err_ << '\n';
    err_.flush();
  }
}

double ProgressReporter::now() const {
  if (clock_) return clock_();
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void ProgressReporter::update(double t0, double t, double t_end) {
  if (!enabled()) return;
  const double w = now();
  if (!have_t_ || t0 != loop_t0_ || t_end != loop_t_end_ || t < t_) {
    // A new loop: it started at construction (the first) or when the previous one last reported.
    loop_t0_ = t0;
    loop_t_end_ = t_end;
    loop_wall0_ = have_t_ ? last_update_ : wall0_;
    have_t_ = true;
  }
  t_ = t;
  last_update_ = w;
  const double elapsed = w - wall0_;
  if (elapsed < (requested_ ? kIntervalS : kAutoAfterS) || w - last_emit_ < kIntervalS) return;
  last_emit_ = w;
  const double span = t_end - t0;
  const double frac = span > 0.0 ? (t - t0) / span : 1.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.6g / %.6g s (%.1f%%), wall ", t, t_end, 100.0 * frac);
  std::string text = buf;
  text += format_wall(elapsed) + ", ETA ";
  text += frac > 0.0 ? format_wall((w - loop_wall0_) * (1.0 - frac) / frac) : std::string("?");
  emit(text, false);
}

void ProgressReporter::finish() {
  if (!(requested_ || shown_)) return;
  std::string text = "done";
  if (have_t_) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", t = %.6g / %.6g s", t_, loop_t_end_);
    text += buf;
  }
  text += ", wall " + format_wall(now() - wall0_);
  emit(text, true);
}

void ProgressReporter::emit(const std::string& text, bool final_line) {
  const std::string line = "adcs-sim: " + label_ + ": " + text;
  if (terminal_) {
    err_ << '\r' << line;
    if (line.size() < last_len_) err_ << std::string(last_len_ - line.size(), ' ');
    last_len_ = line.size();
    open_line_ = !final_line;
    if (final_line) err_ << '\n';
  } else {
    err_ << line << '\n';
  }
  err_.flush();
  shown_ = true;
}

}  // namespace adcs::sim::cli
