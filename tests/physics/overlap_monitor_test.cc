// The run's record of a sheet overlapping a second tool (contact/overlap_monitor.h): the contact
// tolerance, the first occurrence and the largest overlap, and the two cases (through a tool,
// ironing lag) kept apart.
#include "contact/overlap_monitor.h"

#include <gtest/gtest.h>

#include <string>

namespace vs {
namespace {

TEST(OverlapMonitor, OverlapsWithinTheContactToleranceAreIgnored) {
  OverlapMonitor m(1.0);  // tolerance 0.02 mm
  EXPECT_DOUBLE_EQ(m.tolerance_mm(), 0.02);
  m.note(
      10.0, 0.02, "die", "punch", [] { return std::string("initial radius 50 mm"); }, false);
  m.note(
      11.0, 0.019, "die", "punch", [] { return std::string("initial radius 50 mm"); }, true);
  EXPECT_FALSE(m.through_seen());
  EXPECT_FALSE(m.lag_seen());
  EXPECT_TRUE(m.warnings().empty());
}

TEST(OverlapMonitor, KeepsTheFirstOccurrenceAndTheLargestOverlap) {
  OverlapMonitor m(0.5);  // tolerance 0.01 mm
  m.note(
      30.0, 0.011, "die", "punch", [] { return std::string("initial radius 40 mm"); }, false);
  m.note(
      31.0, 0.05, "punch", "die", [] { return std::string("initial radius 45 mm"); }, false);
  m.note(
      32.0, 0.03, "die", "punch", [] { return std::string("initial radius 41 mm"); }, false);
  ASSERT_TRUE(m.through_seen());
  EXPECT_FALSE(m.lag_seen());
  EXPECT_DOUBLE_EQ(m.largest_through_mm(), 0.05);
  const std::vector<std::string> w = m.warnings();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0],
            "from punch travel 30.00 mm the sheet is squeezed between tools 'die' and 'punch' "
            "(node at initial radius 40 mm overlaps the second tool by 0.011 mm, up to 0.05 mm "
            "later, more than the ironing constraint allows): results beyond that travel are not "
            "trustworthy");
}

TEST(OverlapMonitor, IroningLagIsReportedApartFromASheetThroughATool) {
  OverlapMonitor m(1.0);
  m.note(
      37.0, 0.039, "die", "punch", [] { return std::string("initial position (32.8, 39.7) mm"); },
      true);
  m.note(
      37.2, 0.058, "die", "punch", [] { return std::string("initial position (33.1, 39.9) mm"); },
      true);
  EXPECT_FALSE(m.through_seen());
  ASSERT_TRUE(m.lag_seen());
  EXPECT_DOUBLE_EQ(m.largest_lag_mm(), 0.058);
  std::vector<std::string> w = m.warnings();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("from punch travel 37.00 mm the ironing between tools 'die' and 'punch' "
                      "lags the narrowing clearance"),
            std::string::npos);
  EXPECT_NE(w[0].find("by 0.039 mm, up to 0.058 mm later"), std::string::npos);
  m.note(
      40.0, 0.1, "punch", "die", [] { return std::string("initial position (1, 2) mm"); }, false);
  w = m.warnings();
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("not trustworthy"), std::string::npos);
  EXPECT_NE(w[1].find("lags the narrowing clearance"), std::string::npos);
}

}  // namespace
}  // namespace vs
