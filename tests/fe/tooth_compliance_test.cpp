// Single-tooth compliances by FE (tooth_compliance_fe.hpp) on a small design
// at level 0: the invariants (finite, positive, rising towards the tip), the
// geometry of the load and read points, and the analytic model beside it
// held to a loose sanity bound only (docs/models/fe_reference.md has the
// measured ratios; tightening the comparison is further work).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fe_test_helpers.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

using testing::gantry;  // z 20, m 4 mm, 20 deg: the smallest shipped design

std::vector<double> path_points(const MeshGeometry& g) {
  const double lo = std::max(g.path.s_start, g.path.s_form), hi = g.path.s_end;
  return {lo + 0.05 * (hi - lo), 0.5 * (lo + hi), hi - 0.05 * (hi - lo)};
}

void print(const char* who, const ToothComplianceFe& r) {
  std::printf("%s s = %.3f mm: FE %.4g m/N, analytic %.4g m/N, FE/analytic %.3f (%d elements, %.2f s)\n", who,
              r.s * 1e3, r.compliance, r.analytic, r.compliance / r.analytic, r.elements, r.seconds);
}

TEST(FeToothCompliance, PinionRisesTowardsTheTipAndLoadsAlongTheLineOfAction) {
  const Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  double previous = 0;
  for (double s : path_points(g)) {
    const ToothComplianceFe r = fe_tooth_compliance(d, ToothMember::kPinion, s);
    print("pinion", r);
    ASSERT_TRUE(std::isfinite(r.compliance));
    EXPECT_GT(r.compliance, previous) << "s = " << s;  // previous = 0 first: positive
    previous = r.compliance;
    EXPECT_GT(r.compliance / r.analytic, 0.3);
    EXPECT_LT(r.compliance / r.analytic, 3.0);
    // The load point is the involute point at radius sqrt(r_b^2 + s^2); the
    // load line through it is tangent to the base circle and is read on the
    // tooth's centre line (x = 0), below the load point.
    EXPECT_NEAR(std::hypot(r.load_point.x, r.load_point.y), g.pinion_contact_radius(s), 1e-12);
    EXPECT_NEAR(r.read_point.x, 0, 1e-15);
    const double dx = r.read_point.x - r.load_point.x, dy = r.read_point.y - r.load_point.y;
    EXPECT_NEAR(std::abs(r.load_point.x * dy - r.load_point.y * dx) / std::hypot(dx, dy), g.pinion.base_radius, 1e-9);
    EXPECT_LT(dx, 0);  // from the +x flank into the tooth
    EXPECT_GT(r.hertz_half_width, 0);
    EXPECT_GT(r.elements, 0);
  }
}

TEST(FeToothCompliance, RackRisesAsTheContactGoesUpItsTooth) {
  const Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  const std::vector<double> s = path_points(g);
  double previous = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.size(); ++i) {  // s up = contact down the rack flank: the compliance falls
    const double si = s[i];
    const ToothComplianceFe r = fe_tooth_compliance(d, ToothMember::kRack, si);
    print("rack", r);
    ASSERT_TRUE(std::isfinite(r.compliance));
    EXPECT_GT(r.compliance, 0);
    EXPECT_LT(r.compliance, previous) << "s = " << si;
    previous = r.compliance;
    EXPECT_NEAR(r.load_point.y, g.contact_height_above_datum(si), 1e-15);
    // The middle tooth's centre line; the segment reaches 3 body depths beyond it.
    ASSERT_EQ(r.rack_teeth % 2, 1);
    EXPECT_NEAR(r.read_point.x, 0.5 * r.rack_teeth * g.rack.pitch, 1e-15);
    EXPECT_GE((r.rack_teeth / 2) * g.rack.pitch, 3 * d.rack.body_height);
    EXPECT_LT(r.read_point.y, r.load_point.y);
    // The analytic rack is the clamped tooth plus its FE-calibrated
    // foundation (docs/models/rack_foundation.md): within the law's 3 %.
    EXPECT_NEAR(r.compliance / r.analytic, 1.0, 0.03);
    // The clamped tooth alone is far stiffer: the body only adds.
    Drive clamped = d;
    clamped.effects.rack_foundation = false;
    EXPECT_GT(r.compliance, 1.3 * analytic_tooth_compliance(clamped, ToothMember::kRack, si));
  }
}

TEST(FeToothCompliance, DeeperRackBodyIsMoreCompliant) {
  // options.rack_body_depth is used: a body twice as deep under the same
  // tooth (held at its base, long enough in both cases) gives way more.
  const Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  const double s = path_points(g).front();
  FeOptions deep;
  deep.rack_body_depth = 2 * d.rack.body_height;
  const double shallow_c = fe_tooth_compliance(d, ToothMember::kRack, s).compliance;
  const double deep_c = fe_tooth_compliance(d, ToothMember::kRack, s, deep).compliance;
  std::printf("rack body %.1f mm: %.4g m/N, %.1f mm: %.4g m/N\n", d.rack.body_height * 1e3, shallow_c,
              deep.rack_body_depth * 1e3, deep_c);
  EXPECT_GT(deep_c, 1.02 * shallow_c);
}

TEST(FeToothCompliance, ContactsOffThePathAndBadOptionsAreErrors) {
  const Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  for (ToothMember m : {ToothMember::kPinion, ToothMember::kRack}) {
    EXPECT_THROW(fe_tooth_compliance(d, m, g.path.s_end * 1.01), std::invalid_argument);
    EXPECT_THROW(fe_tooth_compliance(d, m, g.path.s_start - 0.01 * g.path.base_pitch), std::invalid_argument);
    EXPECT_THROW(fe_tooth_compliance(d, m, std::nan("")), std::invalid_argument);
    FeOptions bad;
    bad.level = 7;
    EXPECT_THROW(fe_tooth_compliance(d, m, g.path.s_pitch, bad), std::invalid_argument);
  }
  Drive no_load = d;
  no_load.load.force = 0;
  EXPECT_THROW(fe_tooth_compliance(no_load, ToothMember::kRack, g.path.s_pitch), std::invalid_argument);
}

// A path kept as the paper's geometric one starts below the pinion's base
// circle: the rack tooth there is still loaded (its flank is straight), the
// pinion, with no involute to load, is refused before any FE work.
TEST(FeToothCompliance, BelowTheBaseCircleTheRackIsSolvedAndThePinionRefused) {
  const Drive d = test_support::load_shipped_problem("rack_railway_paper.yaml");
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_LT(g.path.s_start, 0);
  const double s = 0.5 * g.path.s_start;
  EXPECT_FALSE(pinion_contact_on_involute(g, s));
  EXPECT_TRUE(pinion_contact_on_involute(g, g.path.s_end));
  EXPECT_THROW(fe_tooth_compliance(d, ToothMember::kPinion, s), std::invalid_argument);
  const ToothComplianceFe r = fe_tooth_compliance(d, ToothMember::kRack, s);
  print("rack below the base circle", r);
  EXPECT_TRUE(std::isfinite(r.compliance));
  EXPECT_GT(r.compliance, 0);
  // The patch is sized with the floor radius m / 10, not the (negative) s.
  EXPECT_EQ(patch_curvature_radius(s, d.pinion.module), 0.1 * d.pinion.module);
  EXPECT_GT(r.hertz_half_width, 0);
}

}  // namespace
}  // namespace rackopt::fe
