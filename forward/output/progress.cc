#include "output/progress.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ostream>

namespace vs {
namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Three significant figures or so, without exponent notation for everyday forces.
std::string kilonewtons(double force_N) {
  const double kN = force_N / 1000.0;
  const double a = std::abs(kN);
  if (a >= 100.0) return fmt::format("{:.0f}", kN);
  if (a >= 10.0) return fmt::format("{:.1f}", kN);
  if (a >= 1.0) return fmt::format("{:.2f}", kN);
  return fmt::format("{:.3f}", kN);
}

}  // namespace

ProgressPrinter::ProgressPrinter(const Options& options, std::ostream& out, Clock clock)
    : options_(options), out_(out), clock_(clock ? std::move(clock) : Clock(steady_seconds)) {
  start_s_ = clock_();
  last_print_s_ = start_s_;
}

void ProgressPrinter::update(const StepRecord& record) {
  if (options_.quiet) return;
  const double now = clock_();
  if (now - last_print_s_ >= options_.interval_s) {
    print(record, now);
  } else {
    pending_ = record;
  }
}

void ProgressPrinter::finish() {
  if (options_.quiet || !pending_) return;
  print(*pending_, clock_());
}

std::string ProgressPrinter::format_line(const StepRecord& r, double elapsed_s) const {
  std::string travel;
  if (options_.total_travel_mm > 0.0) {
    const double percent = 100.0 * r.punch_travel_mm / options_.total_travel_mm;
    travel = fmt::format("{:.2f}/{:.2f} mm ({:.0f}%)", r.punch_travel_mm, options_.total_travel_mm,
                         std::floor(percent));
  } else {
    travel = fmt::format("{:.2f} mm", r.punch_travel_mm);
  }
  std::string line =
      fmt::format("step {}  travel {}  force {} kN  iters {}  elapsed {:.1f} s", r.step, travel,
                  kilonewtons(r.punch_force_N), r.iterations, elapsed_s);
  // Time left, extrapolated linearly in punch travel (steps get no cheaper later in a run, so it
  // is an estimate, not a bound).
  if (options_.total_travel_mm > 0.0 && r.punch_travel_mm > 0.0 &&
      r.punch_travel_mm < options_.total_travel_mm) {
    const double eta_s =
        elapsed_s * (options_.total_travel_mm - r.punch_travel_mm) / r.punch_travel_mm;
    line += fmt::format("  ETA {:.1f} s", eta_s);
  }
  return line;
}

void ProgressPrinter::print(const StepRecord& record, double now) {
  out_ << format_line(record, now - start_s_) << '\n' << std::flush;
  last_print_s_ = now;
  pending_.reset();
}

}  // namespace vs
