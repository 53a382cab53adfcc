// The backlash metrics against the flank geometry: the rack's tooth space
// on the pitch line (datum) is pi m / 2 wide, and the pinion moved a
// clearance Delta away from the rack meets it at a datum line Delta lower,
// where each flank of the space has moved Delta tan a0 outwards.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics_test_support.hpp"
#include "rackopt/metrics/metric_registry.hpp"

namespace rackopt {
namespace {

using test::eval;
using test::problem;

TEST(BacklashMetric, TwoFlankShiftsOfTheClearanceOnThePitchLineAndTheirNormalPart) {
  for (const char* name : {"rack_railway", "gantry_axis", "ship_lift"}) {
    SCOPED_TRACE(name);
    Drive d = problem(name);
    const double a0 = d.pinion.pressure_angle;
    for (double clearance : {0.0, 0.1e-3, 1.5e-3}) {
      d.mounting.clearance = clearance;
      const metrics::MetricValues v = eval(d, {"backlash", "normal_backlash"});
      ASSERT_TRUE(v.all_ok());
      // Each flank of a straight-sided rack tooth moves clearance x tan a0
      // along the pitch line when the datum drops by the clearance.
      const double per_flank = clearance * std::sin(a0) / std::cos(a0);
      EXPECT_NEAR(v.values[0].value, 2 * per_flank, 1e-15);
      // The gap between the back flanks measured along their normal: the
      // tangential gap projected on the line of action.
      EXPECT_NEAR(v.values[1].value, 2 * clearance * std::sin(a0), 1e-15);
    }
  }
}

TEST(BacklashMetric, DeclaredAsGeometryInMetresAndSmooth) {
  for (const char* name : {"backlash", "normal_backlash"}) {
    const metrics::MetricDefinition& d = metrics::find_metric(name);
    EXPECT_EQ(d.unit, "m");
    EXPECT_EQ(d.kind, QuantityKind::kLength);
    EXPECT_EQ(d.display_unit, "mm");
    EXPECT_EQ(d.models, (metrics::ModelSet{metrics::Model::kGeometry}));
    EXPECT_TRUE(d.smooth);
  }
}

}  // namespace
}  // namespace rackopt
