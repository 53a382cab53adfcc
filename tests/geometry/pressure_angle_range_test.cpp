// The feasible pressure-angle range printed by rackopt check.
#include "rackopt/geometry/pressure_angle_range.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {
namespace {

using geometry_test::deg;
using geometry_test::standard_drive;

std::string code_at(Drive d, double angle) {
  d.pinion.pressure_angle = angle;
  try {
    build_mesh_geometry(d);
    return "";
  } catch (const DesignError& e) {
    return e.code();
  }
}

TEST(PressureAngleRange, EndsAreWhereTheGeometryGivesOutWithThatReason) {
  const Drive d = standard_drive(20, 0.004, 20.0, 0.0, 0.38);
  const PressureAngleRange r = feasible_pressure_angles(d);
  ASSERT_TRUE(r.found);
  EXPECT_LT(r.lower, deg(20));
  EXPECT_GT(r.upper, deg(20));
  EXPECT_EQ(code_at(d, r.lower), "");
  EXPECT_EQ(code_at(d, r.upper), "");
  EXPECT_EQ(code_at(d, r.lower - deg(0.002)), r.lower_limit);
  EXPECT_EQ(code_at(d, r.upper + deg(0.002)), r.upper_limit);
  EXPECT_FALSE(r.lower_limit.empty());
  EXPECT_FALSE(r.upper_limit.empty());
}

// The upper end for a round-tipped cutter is where its tip flat closes:
// pi/4 - h_a0* tan a - rho* (1 - sin a)/cos a = 0 (solved here by bisection).
TEST(PressureAngleRange, UpperEndMatchesTheClosedCutterTipFlat) {
  const Drive d = standard_drive(20, 0.004, 20.0, 0.0, 0.38);
  auto flat = [](double a) { return M_PI / 4 - 1.25 * std::tan(a) - 0.38 * (1 - std::sin(a)) / std::cos(a); };
  double lo = deg(10), hi = deg(40);
  for (int i = 0; i < 80; ++i) (flat(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const PressureAngleRange r = feasible_pressure_angles(d);
  EXPECT_EQ(r.upper_limit, "cutter_tip_radius");
  EXPECT_NEAR(r.upper, lo, deg(0.002));
  EXPECT_NEAR(r.upper / deg(1), 23.156, 0.01);  // with rho* = 0.38, h_a0* = 1.25
}

TEST(PressureAngleRange, InfeasibleDriveHasNoRange) {
  Drive d = standard_drive(20, 0.004, 20.0, 0.0, 0.38);
  d.pinion.pressure_angle = deg(30);  // beyond the cutter's limit
  EXPECT_FALSE(feasible_pressure_angles(d).found);
}

}  // namespace
}  // namespace rackopt
