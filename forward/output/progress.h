// Progress lines for long runs, on stderr so stdout keeps only the summary:
//   step 120  travel 18.40/30.00 mm (61%)  force 41.2 kN  iters 4  elapsed 0.9 s
// Plain lines (no carriage-return bars) so CI logs stay readable, at most one per interval, and
// always the last step when the run ends (finish()).
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>

#include "run/run_result.h"

namespace vs {

class ProgressPrinter {
 public:
  // Seconds since an arbitrary fixed origin; injectable so tests need no sleeping.
  using Clock = std::function<double()>;

  struct Options {
    double total_travel_mm = 0.0;  // for "travel x/total mm (p%)"; <= 0 omits total and percent
    double interval_s = 1.0;       // minimum time between two lines
    bool quiet = false;            // print nothing
  };

  // `out` must outlive the printer. The default clock is std::chrono::steady_clock.
  ProgressPrinter(const Options& options, std::ostream& out, Clock clock = {});

  // After every converged step: prints if `interval_s` has passed since the last line (or since
  // construction, for the first line).
  void update(const StepRecord& record);

  // At the end of the run: prints the last step if its line was held back by the interval.
  void finish();

  // The line for `record` after `elapsed_s` seconds (no newline).
  std::string format_line(const StepRecord& record, double elapsed_s) const;

 private:
  void print(const StepRecord& record, double now);

  Options options_;
  std::ostream& out_;
  Clock clock_;
  double start_s_ = 0.0;
  double last_print_s_ = 0.0;
  std::optional<StepRecord> pending_;  // last step not yet printed
};

}  // namespace vs
