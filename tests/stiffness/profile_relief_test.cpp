// Profile relief mapped onto the line of action: each of the four zones
// starts and ends where docs/models/transmission_error.md says, linear and
// parabolic shapes, and no relief means zero everywhere.
#include "rackopt/stiffness/profile_relief.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {
namespace {

Drive drive() {
  Drive d;
  d.pinion.teeth = 22;
  d.pinion.module = 0.01;
  d.pinion.pressure_angle = 20 * M_PI / 180;
  d.pinion.bore_radius = 0.05;
  return d;
}

TEST(ProfileReliefShape, LinearAndParabolic) {
  ProfileRelief r{20e-6, 4e-3, ProfileRelief::Shape::kLinear};
  EXPECT_EQ(relief_profile(r, -1e-3), 0.0);
  EXPECT_EQ(relief_profile(r, 0.0), 0.0);
  EXPECT_NEAR(relief_profile(r, 1e-3), 5e-6, 1e-18);
  EXPECT_NEAR(relief_profile(r, 4e-3), 20e-6, 1e-18);
  EXPECT_NEAR(relief_profile(r, 9e-3), 20e-6, 1e-18);
  r.shape = ProfileRelief::Shape::kParabolic;
  EXPECT_NEAR(relief_profile(r, 1e-3), 20e-6 / 16, 1e-18);
  EXPECT_NEAR(relief_profile(r, 2e-3), 5e-6, 1e-18);
  r.amount = 0;
  EXPECT_EQ(relief_profile(r, 2e-3), 0.0);
}

TEST(ReliefOnPath, NoReliefIsZeroAndInactive) {
  const Drive d = drive();
  const ReliefOnPath r(d, build_mesh_geometry(d));
  EXPECT_FALSE(r.any());
  EXPECT_EQ(r.at(0.03), 0.0);
}

TEST(ReliefOnPath, ZonesSitAtTheirFlankEnds) {
  Drive base = drive();
  const MeshGeometry g = build_mesh_geometry(base);
  const ContactPath& p = g.path;
  const double L = 3e-3, C = 15e-6;
  const ProfileRelief rel{C, L, ProfileRelief::Shape::kLinear};
  struct Case {
    const char* name;
    ProfileRelief* slot;
    double full_at;   // s where the relief is the full amount
    double zero_at;   // s where it starts
  };
  Drive d = base;
  const Case cases[] = {
      {"pinion tip", &d.pinion.tip_relief, p.s_end, p.s_end - L},
      {"rack root", &d.rack.root_relief, p.s_end, p.s_end - L},
      {"pinion root", &d.pinion.root_relief, p.s_start, p.s_start + L},
      {"rack tip", &d.rack.tip_relief, p.s_rack_tip, p.s_rack_tip + L},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    d = base;  // the slots point into d
    ProfileRelief* slot = c.slot;
    *slot = rel;
    const ReliefOnPath r(d, g);
    ASSERT_TRUE(r.any());
    EXPECT_NEAR(r.at(c.full_at), C, 1e-18);
    EXPECT_NEAR(r.at(c.zero_at), 0.0, 1e-18);
    EXPECT_NEAR(r.at(0.5 * (c.full_at + c.zero_at)), 0.5 * C, 1e-17);
    EXPECT_EQ(r.at(c.zero_at + (c.zero_at - c.full_at)), 0.0);  // beyond the zone, away from the end
    *slot = ProfileRelief{};
  }
  // Pinion tip and rack root add up.
  d = base;
  d.pinion.tip_relief = rel;
  d.rack.root_relief = rel;
  EXPECT_NEAR(ReliefOnPath(d, g).at(p.s_end), 2 * C, 1e-18);
}

}  // namespace
}  // namespace rackopt
