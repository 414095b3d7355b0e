#include "output/progress.h"

#include <gtest/gtest.h>

#include <sstream>

#include "test_data.h"

namespace vs {
namespace {

struct FakeClock {
  double now = 100.0;
  ProgressPrinter::Clock clock() {
    return [this] { return now; };
  }
};

TEST(Progress, LineShowsStepTravelForceIterationsAndTime) {
  std::ostringstream out;
  FakeClock t;
  ProgressPrinter p({30.0, 1.0, false}, out, t.clock());
  StepRecord r = test::step_record(120, 18.4, 41234.0, 0.9);
  r.iterations = 4;
  EXPECT_EQ(p.format_line(r, 0.94),
            "step 120  travel 18.40/30.00 mm (61%)  force 41.2 kN  iters 4  elapsed 0.9 s  ETA "
            "0.6 s");  // 0.94 s x (30 - 18.4) / 18.4 left
  ProgressPrinter no_total({0.0, 1.0, false}, out, t.clock());
  EXPECT_EQ(no_total.format_line(r, 2.0),
            "step 120  travel 18.40 mm  force 41.2 kN  iters 4  elapsed 2.0 s");
}

TEST(Progress, AtMostOneLinePerIntervalAndAlwaysTheLast) {
  std::ostringstream out;
  FakeClock t;
  ProgressPrinter p({10.0, 1.0, false}, out, t.clock());
  const double times[] = {100.1, 100.5, 101.2, 101.5, 102.0, 102.3, 102.4};
  int step = 0;
  for (double time : times) {
    t.now = time;
    ++step;
    p.update(test::step_record(step, 0.5 * step, 10.0, 1.0));
  }
  p.finish();
  const std::vector<std::string> lines = test::lines(out.str());
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("step 3 ", 0), 0u);  // first line after 1 s
  EXPECT_EQ(lines[1].rfind("step 6 ", 0), 0u);  // 102.3 - 101.2 >= 1
  EXPECT_EQ(lines[2].rfind("step 7 ", 0), 0u);  // the last, from finish()
}

TEST(Progress, FinishDoesNotRepeatAPrintedLine) {
  std::ostringstream out;
  FakeClock t;
  ProgressPrinter p({10.0, 1.0, false}, out, t.clock());
  t.now = 102.0;
  p.update(test::step_record(1, 1.0, 10.0, 1.0));
  p.finish();
  EXPECT_EQ(test::lines(out.str()).size(), 1u);
}

TEST(Progress, QuietPrintsNothing) {
  std::ostringstream out;
  FakeClock t;
  ProgressPrinter p({10.0, 1.0, true}, out, t.clock());
  t.now = 105.0;
  p.update(test::step_record(1, 1.0, 10.0, 1.0));
  p.finish();
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace vs
