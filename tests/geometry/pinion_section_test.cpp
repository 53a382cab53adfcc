// Area of the generated pinion outline: the polygon of pinion_outline_area
// against an independent radial integration A = pi r_f^2 + 2 z Int theta(R) R dR
// of the tooth's half angle theta(R) (the involute's closed form above the form
// circle, the fillet's angle found by bisection below it).
#include "rackopt/geometry/pinion_section.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"
#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt {
namespace {

using geometry_test::deg;
using geometry_test::standard_drive;

// Half angle of the fillet at radius R (r_f <= R <= the fillet's top), by
// bisection on the round's normal angle phi (the radius grows as phi falls).
double fillet_half_angle(const PinionSpec& p, double R) {
  double lo = p.pressure_angle, hi = M_PI / 2;  // radius(lo) >= R >= radius(hi)
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    const ToothPoint q = fillet_point(p, mid);
    (std::hypot(q.x, q.y) > R ? lo : hi) = mid;
  }
  const ToothPoint q = fillet_point(p, 0.5 * (lo + hi));
  return std::atan2(q.x, q.y);
}

double simpson(double a, double b, int n, auto f) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return s * h / 3;
}

double radial_area(const PinionSpec& p, const MeshGeometry& g) {
  const PinionGeometry& pg = g.pinion;
  const double fillet = simpson(pg.root_radius, pg.form_radius, 4000,
                                [&](double R) { return fillet_half_angle(p, R) * R; });
  const double involute = simpson(pg.form_radius, pg.tip_radius, 4000,
                                  [&](double R) { return involute_half_angle(p, R) * R; });
  return M_PI * pg.root_radius * pg.root_radius + 2 * p.teeth * (fillet + involute);
}

void expect_area_matches(const Drive& d) {
  const MeshGeometry g = build_mesh_geometry(d);
  const double polygon = pinion_outline_area(d.pinion, g);
  const double radial = radial_area(d.pinion, g);
  EXPECT_NEAR(polygon / radial, 1.0, 2e-6) << "z " << d.pinion.teeth << " x " << d.pinion.profile_shift;
  // Between the root and the tip discs, and near the pitch disc.
  const double r = g.pinion.pitch_radius;
  EXPECT_GT(polygon, M_PI * g.pinion.root_radius * g.pinion.root_radius);
  EXPECT_LT(polygon, M_PI * g.pinion.tip_radius * g.pinion.tip_radius);
  EXPECT_NEAR(polygon / (M_PI * r * r), 1.0, 0.15);
}

TEST(PinionOutlineArea, AgreesWithRadialIntegrationOfTheToothThickness) {
  expect_area_matches(standard_drive(20, 0.010, 20.0));
  expect_area_matches(standard_drive(40, 0.004, 25.0));
  expect_area_matches(standard_drive(16, 0.063, 20.0, 0.5, 0.38));  // ship-lift proportions
  expect_area_matches(standard_drive(12, 0.010, 20.0, 0.3));
}

TEST(PinionOutlineArea, UndercutPinionUsesTheFilletBelowTheFormCircle) {
  const Drive d = standard_drive(13, 0.010, 20.0);
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_TRUE(g.pinion.undercut);
  expect_area_matches(d);
}

TEST(PinionOutlineArea, StandardPinionIsSlightlyBelowItsPitchDisc) {
  // Standard 1/1.25 teeth: the addendum band holds about half its area in
  // teeth, the deeper dedendum band about half in spaces, so the outline is
  // below the pitch disc by roughly pi (h_f - h_a) m z / 2 ... of order 1 %.
  const Drive d = standard_drive(40, 0.005, 20.0);
  const MeshGeometry g = build_mesh_geometry(d);
  const double r = g.pinion.pitch_radius;
  const double ratio = pinion_outline_area(d.pinion, g) / (M_PI * r * r);
  EXPECT_LT(ratio, 1.0);
  EXPECT_GT(ratio, 0.98);
}

}  // namespace
}  // namespace rackopt
