// The reason a run gives when a thickness leaves the limits: folding above them; below them
// fracture, or the sub-thickness-mesh instability when elements are shorter than the thickness
// (issue 16: such a run said "necked through (fracture)" although it was the instability it had
// warned about).
#include <gtest/gtest.h>

#include <string>

#include "stepping/step_driver_options.h"

namespace vs {
namespace {

TEST(ThicknessLimitReason, SaysWhichOfFoldingFractureAndSubThicknessMesh) {
  const StepDriverOptions options;  // limits 0.05 and 3 x h0
  EXPECT_EQ(thickness_limit_reason(3.5, 1.0, options, 2.0, "elements"),
            "the mesh is folding onto itself");
  EXPECT_EQ(thickness_limit_reason(0.04, 1.0, options, 2.0, "elements"),
            "the sheet has necked through (fracture)");
  EXPECT_EQ(thickness_limit_reason(0.04, 1.0, options, 1.0, "elements"),
            "the sheet has necked through (fracture)");  // elements as long as h0: resolved
  EXPECT_EQ(thickness_limit_reason(0.04, 1.0, options, 0.3, "divisions"),
            "the sub-thickness-mesh instability, not a resolved neck (elements as short as "
            "0.3 mm, shorter than the thickness 1 mm; use fewer divisions)");
  // Thickening with a fine mesh is still folding.
  EXPECT_EQ(thickness_limit_reason(3.5, 1.0, options, 0.3, "elements"),
            "the mesh is folding onto itself");
}

}  // namespace
}  // namespace vs
