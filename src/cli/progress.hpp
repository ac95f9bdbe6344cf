#pragma once
// Progress lines of adcs-sim on stderr: simulated time, wall time, ETA.
//
// Shown when --progress is given (from the first second on, at most one line a second, and
// always a final line), or when stderr is a terminal and the run lasts longer than
// kAutoAfterS (then a final line only if a line was shown). On a terminal the line is
// rewritten in place ('\r'); otherwise each update is one line ('\n'). stdout is never touched.
#include <functional>
#include <iosfwd>
#include <string>

namespace adcs::sim::cli {

class ProgressReporter {
 public:
  //! Monotonic wall clock in seconds (injectable for tests).
  using Clock = std::function<double()>;
  static constexpr double kIntervalS = 1.0;   //!< at most one line per interval
  static constexpr double kAutoAfterS = 3.0;  //!< terminal without --progress: first line after

  //! `label` prefixes every line ("adcs-sim: <label>: ..."). `requested`: --progress given.
  //! `terminal`: err is a terminal. Neither: the reporter prints nothing.
  ProgressReporter(std::ostream& err, std::string label, bool requested, bool terminal,
                   Clock clock = {});
  ~ProgressReporter();  // ends a pending in-place line with '\n' (e.g. the run failed)
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  bool enabled() const noexcept { return requested_ || terminal_; }
  //! The progress sink: the loop runs from t0 to t_end and has reached t [s].
  void update(double t0, double t, double t_end);
  //! The final line (see above); call once when the run succeeded.
  void finish();

 private:
  double now() const;
  void emit(const std::string& text, bool final_line);

  std::ostream& err_;
  std::string label_;
  bool requested_, terminal_;
  Clock clock_;
  double wall0_ = 0.0;         // construction
  double last_emit_ = -1e300;  // wall time of the last line
  bool shown_ = false;         // a line was written
  bool open_line_ = false;     // terminal: an in-place line is pending
  std::size_t last_len_ = 0;   // its length (to blank a longer previous line)
  bool have_t_ = false;        // a loop reported
  double loop_t0_ = 0.0, loop_t_end_ = 0.0, t_ = 0.0;  // the current loop and its time
  double loop_wall0_ = 0.0, last_update_ = 0.0;         // its wall start; the last update
};

//! "12.3 s", "4 min 05 s", "2 h 03 min": a duration for humans.
std::string format_wall(double seconds);

}  // namespace adcs::sim::cli
