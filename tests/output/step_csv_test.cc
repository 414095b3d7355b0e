#include "output/step_csv.h"

#include <gtest/gtest.h>

#include "output/load_travel_stream.h"
#include "output/number_format.h"
#include "test_data.h"

namespace vs {
namespace {

TEST(NumberFormat, NineSignificantDigitsAndPlainNonFinite) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(1.0 / 3.0), "0.333333333");
  EXPECT_EQ(format_number(12345.0), "12345");
  EXPECT_EQ(format_number(1e-8), "1e-08");
  EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_number(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(LoadTravelCsv, HeaderNamesEveryStepFieldWithUnits) {
  EXPECT_EQ(load_travel_csv_header(),
            "step,time_s,punch_travel_mm,punch_force_N,iterations,residual_norm,update_norm,"
            "contact_nodes,cutbacks,min_thickness_mm,thinnest_r0_mm,thinnest_r_mm,volume_mm3,"
            "rim_draw_in_mm");
}

TEST(LoadTravelCsv, RowHasOneCellPerHeaderColumn) {
  StepRecord r = test::step_record(7, 1.25, 41234.5, 0.875);
  r.cutbacks = 2;
  EXPECT_EQ(load_travel_csv_row(r),
            "7,1.25,1.25,41234.5,3,1e-08,2e-07,7,2,0.875,5,5.5,7853.98,0.07");
  const std::vector<std::string> lines =
      test::lines(load_travel_csv({r, test::step_record(8, 1.5, 1.0, 0.8)}));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], load_travel_csv_header());
  EXPECT_EQ(lines[1], load_travel_csv_row(r));
}

TEST(ThinnestPointCsv, OneRowPerStep) {
  const std::vector<std::string> lines =
      test::lines(thinnest_point_csv({test::step_record(1, 0.5, 10.0, 0.99)}, 1.1));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "punch_travel_mm,min_thickness_mm,thinning_percent,thinnest_r0_mm,thinnest_r_mm");
  // 100 (1 - 0.99 / 1.1) = 10 %.
  EXPECT_EQ(lines[1], "0.5,0.99,10,5,5.5");
}

TEST(LoadTravelStream, EveryRowIsOnDiskBeforeTheNextStep) {
  const auto path = test::scratch_folder() / "load_travel.csv";
  LoadTravelStream stream(path.string());
  EXPECT_EQ(test::lines(test::read_file(path)).size(), 1u);  // header already flushed
  const StepRecord a = test::step_record(1, 0.5, 100.0, 0.99);
  const StepRecord b = test::step_record(2, 1.0, 200.0, 0.98);
  stream.append(a);
  stream.append(b);
  // Read while the stream is still open, as after a crash.
  const std::string on_disk = test::read_file(path);
  EXPECT_EQ(on_disk, load_travel_csv({a, b}));
  EXPECT_EQ(stream.rows_written(), 2);
}

TEST(LoadTravelStream, UnwritablePathIsAnInputError) {
  const auto path = test::scratch_folder() / "missing_folder" / "load_travel.csv";
  EXPECT_THROW(LoadTravelStream stream(path.string()), InputError);
}

}  // namespace
}  // namespace vs
