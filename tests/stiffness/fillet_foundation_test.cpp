// Fillet-foundation compliance, Sainsot, Velex & Duverger (2004), docs/models/tooth.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stiffness_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"

namespace rackopt {
namespace {

using test::deg;
using test::inv;
using test::kPi;

// Hand-filled geometry (docs/models/geometry.md, docs/models/tooth.md); theta_f with the TOOL addendum
// h_a0* = dedendum_coef and cutter tip radius rho* = tip_radius_coef.
MeshGeometry fillet_geometry(const PinionSpec& p) {
  MeshGeometry g;
  const double m = p.module, z = p.teeth, a0 = p.pressure_angle, x = p.profile_shift;
  g.pressure_angle = a0;
  g.pinion.pitch_radius = m * z / 2;
  g.pinion.base_radius = g.pinion.pitch_radius * std::cos(a0);
  g.pinion.tip_radius = g.pinion.pitch_radius + (p.addendum_coef + x) * m;
  g.pinion.root_radius = g.pinion.pitch_radius - (p.dedendum_coef - x) * m;
  g.pinion.half_base_angle = kPi / (2 * z) + inv(a0) + 2 * x * std::tan(a0) / z;
  const double rho = p.tip_radius_coef;
  g.pinion.root_angle =
      (kPi / 2 + 2 * (p.dedendum_coef - rho) * std::tan(a0) + 2 * rho / std::cos(a0)) / z;
  g.path.s_end = std::sqrt(std::pow(g.pinion.tip_radius, 2) - std::pow(g.pinion.base_radius, 2));
  g.path.s_pitch = g.pinion.pitch_radius * std::sin(a0);
  return g;
}

// The rack railway paper's pinion (docs/models/geometry.md): m = 31.831 mm, z = 22, 14 deg, h_a* = 0.9,
// c* = 0.166 -> h_a0* = 1.066, rho* = c*/(1 - sin a0) = 0.21897, face 60 mm,
// E = 210 GPa. Bore radius 150 mm is our choice (not in the seed): h_f = 2.108.
PinionSpec railway_paper() {
  PinionSpec p;
  p.teeth = 22;
  p.module = 0.031831;
  p.pressure_angle = deg(14);
  p.addendum_coef = 0.9;
  p.dedendum_coef = 1.066;
  p.tip_radius_coef = 0.166 / (1 - std::sin(deg(14)));
  p.face_width = 0.060;
  p.bore_radius = 0.150;
  p.material.youngs_modulus = 210e9;
  p.material.poisson_ratio = 0.3;
  return p;
}

TEST(SainsotCoefficients, MatchHandEvaluatedTable) {
  // X = A/t^2 + B h^2 + C h/t + D/t + E h + F with the docs/models/tooth.md rows,
  // evaluated by hand (python, term by term), e.g. L*(2, 0.1) =
  // -0.005574 - 0.0079944 - 0.004603 + 0.047702 + 0.0542 + 6.8045 = 6.8882306.
  struct Point { double h, t, L, M, P, Q; };
  for (const Point& q : {Point{2.0, 0.1, 6.8882306, 1.139793, 2.7267556, 0.4962556},
                         Point{3.5, 0.05, 6.93186465, 1.27914, 5.0717936, 0.389641425},
                         Point{1.4, 0.12, 6.871718494, 1.05273025, 2.1013261, 0.5582941384}}) {
    const SainsotCoefficients c = sainsot_coefficients(q.h, q.t);
    EXPECT_NEAR(c.L, q.L, 1e-8);
    EXPECT_NEAR(c.M, q.M, 1e-8);
    EXPECT_NEAR(c.P, q.P, 1e-8);
    EXPECT_NEAR(c.Q, q.Q, 1e-8);
  }
}

TEST(FilletFoundation, UfIsWhereTheLineOfActionCrossesTheCentreLine) {
  // Geometry built independently: contact C at radius r_c, polar angle
  // theta_c = alpha_2 - inv(alpha_c) from the tooth centre line; the LOA is
  // tangent to the base circle at T, polar angle theta_c - alpha_c (the
  // involute normal at C). Intersect line CT with the centre line x = 0.
  const PinionSpec p = railway_paper();
  const MeshGeometry g = fillet_geometry(p);
  const FilletFoundationCompliance f(g, p);
  const double rb = g.pinion.base_radius, a2 = g.pinion.half_base_angle;
  for (double frac : {0.05, 0.5, 1.0}) {
    const double s = frac * g.path.s_end;
    const double rc = std::hypot(rb, s), ac = std::acos(rb / rc), thc = a2 - inv(ac);
    const double xC = rc * std::sin(thc), yC = rc * std::cos(thc);
    const double xT = rb * std::sin(thc - ac), yT = rb * std::cos(thc - ac);
    const double y_cross = yC + (0 - xC) * (yT - yC) / (xT - xC);
    EXPECT_NEAR(f.u_f(s), y_cross - g.pinion.root_radius, 1e-12) << "s = " << s;
  }
}

TEST(FilletFoundation, FormulaWithHandCoefficientsAndFaceWidthScaling) {
  // theta_f = 0.1111149 rad (3.1 formula, the rack railway paper), h_f = 316.2092/150.
  const PinionSpec p = railway_paper();
  const MeshGeometry g = fillet_geometry(p);
  const FilletFoundationCompliance f(g, p);
  EXPECT_NEAR(f.theta_f(), 0.11111488, 1e-8);
  EXPECT_NEAR(f.h_f(), 0.316209154 / 0.150, 1e-9);
  EXPECT_NEAR(f.root_thickness(), 2 * 0.316209154 * 0.11111488, 1e-9);
  EXPECT_FALSE(f.outside_fitted_range());
  const double s = g.path.s_pitch;
  const double a1 = s / g.pinion.base_radius - g.pinion.half_base_angle;
  const SainsotCoefficients c = sainsot_coefficients(f.h_f(), f.theta_f());
  const double u = f.u_f(s) / f.root_thickness();
  const double expected = std::pow(std::cos(a1), 2) / (210e9 * 0.06) *
                          (c.L * u * u + c.M * u + c.P * (1 + c.Q * std::pow(std::tan(a1), 2)));
  EXPECT_NEAR(f.at(s, 0.06), expected, 1e-12 * expected);
  // Effective face width (spall under the contact, docs/models/tooth.md): 1/b.
  EXPECT_NEAR(f.at(s, 0.03), 2 * f.at(s, 0.06), 1e-12 * expected);
  EXPECT_THROW(f.at(s, 0.0), InputError);
}

TEST(FilletFoundation, RailwayPaperOrderOfMagnitude) {
  // docs/models/tooth.md: "the rack railway paper: ... approx 3 GN/m foundation". With our chosen
  // bore (150 mm) the pitch-point value is 2.9 GN/m; accept 2-4.5 GN/m over the
  // middle of the path (the value depends on the bore and the contact).
  const PinionSpec p = railway_paper();
  const MeshGeometry g = fillet_geometry(p);
  const FilletFoundationCompliance f(g, p);
  const double k = 1.0 / f.at(g.path.s_pitch, p.face_width);
  EXPECT_GT(k, 2.0e9);
  EXPECT_LT(k, 4.5e9);
}

TEST(FilletFoundation, PositiveAlongThePathAndOutsideRangeFlag) {
  for (int z : {8, 17, 22, 60, 150}) {
    for (double a0 : {12.0, 20.0, 30.0}) {
      PinionSpec p = railway_paper();
      p.teeth = z;
      p.module = 0.01;
      p.pressure_angle = deg(a0);
      p.addendum_coef = 1.0;
      p.dedendum_coef = 1.25;
      p.tip_radius_coef = 0.2;  // below c*/(1 - sin a0) for every a0 here
      const MeshGeometry g0 = fillet_geometry(p);
      p.bore_radius = 0.5 * g0.pinion.root_radius;  // h_f = 2
      const FilletFoundationCompliance f(g0, p);
      EXPECT_EQ(f.outside_fitted_range(), f.theta_f() > 0.12 || f.theta_f() < 0.01);
      for (double frac : {0.0, 0.3, 0.7, 1.0}) {
        for (double b : {0.005, 0.5}) {
          const double c = f.at(frac * g0.path.s_end, b);
          EXPECT_TRUE(std::isfinite(c));
          EXPECT_GT(c, 0.0) << "z " << z << " a0 " << a0;
        }
      }
    }
  }
  // theta_f for z = 17 is about 0.15 rad: outside the fitted range (docs/models/tooth.md).
  PinionSpec p = railway_paper();
  p.teeth = 17;
  const MeshGeometry g = fillet_geometry(p);
  EXPECT_TRUE(FilletFoundationCompliance(g, p).outside_fitted_range());
}

TEST(FilletFoundation, BoreErrors) {
  PinionSpec p = railway_paper();
  const MeshGeometry g = fillet_geometry(p);
  p.bore_radius = 0.0;
  EXPECT_THROW(FilletFoundationCompliance(g, p), InputError);
  p.bore_radius = g.pinion.root_radius;
  try {
    FilletFoundationCompliance f(g, p);
    ADD_FAILURE() << "no error";
  } catch (const DesignError& e) {
    EXPECT_EQ(e.code(), "bore_outside_root");
  }
}

}  // namespace
}  // namespace rackopt
