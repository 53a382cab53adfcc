// Pinion tooth compliance (docs/models/tooth.md).
//
// Reference values are computed here independently of the implementation:
// the tooth is rebuilt in Cartesian coordinates from the textbook involute
// (half tooth angle at radius r: theta(r) = alpha_2 - inv(arccos(r_b/r)), so
// h_x = r sin theta, y = r cos theta; load angle alpha_1 = alpha_k - theta_k),
// and the three energies are integrated along the centre line with GSL QAGS
// (adaptive Gauss-Kronrod), not with the alpha-parametrised Gauss-Legendre
// sums of the implementation.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "stiffness_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"
#include "rackopt/stiffness/pinion_tooth.hpp"
#include "rackopt/stiffness/rack_tooth.hpp"

namespace rackopt {
namespace {

using test::deg;
using test::inv;
using test::kPi;
using test::qags;

// Hand-filled geometry from the docs/models/geometry.md, docs/models/tooth.md formulas (the
// geometry module is not used so that these tests stand alone).
MeshGeometry make_geometry(const PinionSpec& p) {
  MeshGeometry g;
  const double m = p.module, z = p.teeth, a0 = p.pressure_angle, x = p.profile_shift;
  g.pressure_angle = a0;
  g.profile_shift_length = x * m;
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

PinionSpec spec(int z, double m, double a0_deg, double ha, double hf, double x, double b) {
  PinionSpec p;
  p.teeth = z;
  p.module = m;
  p.pressure_angle = deg(a0_deg);
  p.addendum_coef = ha;
  p.dedendum_coef = hf;
  p.profile_shift = x;
  p.face_width = b;
  p.tip_radius_coef = 0.2;
  p.material.youngs_modulus = 210e9;
  p.material.poisson_ratio = 0.3;
  return p;
}

// Start of the involute used in these tests: the larger of the base and root circles.
double s_lowest(const MeshGeometry& g) {
  const double r0 = std::max(g.pinion.base_radius, g.pinion.root_radius);
  return std::sqrt(r0 * r0 - std::pow(g.pinion.base_radius, 2));
}

// Independent Cartesian evaluation (see file comment). include_segment: the
// constant-thickness r_b sin(alpha_2) segment below the base circle.
ToothCompliance cartesian(const MeshGeometry& g, const PinionSpec& p, double s, bool include_segment) {
  const double rb = g.pinion.base_radius, a2 = g.pinion.half_base_angle, rf = g.pinion.root_radius;
  const double E = p.material.youngs_modulus, G = p.material.shear_modulus(), b = p.face_width;
  auto theta = [&](double r) { return a2 - inv(std::acos(std::min(rb / r, 1.0))); };
  const double rc = std::hypot(rb, s), ac = std::acos(rb / rc);
  const double yc = rc * std::cos(theta(rc)), hc = rc * std::sin(theta(rc)), a1 = ac - theta(rc);
  const double h1 = rb * std::sin(a2), y_base = rb * std::cos(a2);
  auto half_thickness = [&](double y) {
    if (y <= y_base) return h1;
    double lo = rb, hi = rc * 1.001 + 1e-3;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (mid * std::cos(theta(mid)) < y ? lo : hi) = mid;
    }
    const double r = 0.5 * (lo + hi);
    return r * std::sin(theta(r));
  };
  auto moment = [&](double y) { return std::cos(a1) * (yc - y) - std::sin(a1) * hc; };
  auto bend = [&](double y) { const double h = half_thickness(y); return std::pow(moment(y), 2) / (E * 2.0 / 3.0 * h * h * h * b); };
  auto shear = [&](double y) { return 1.2 * std::pow(std::cos(a1), 2) / (G * 2 * half_thickness(y) * b); };
  auto axial = [&](double y) { return std::pow(std::sin(a1), 2) / (E * 2 * half_thickness(y) * b); };
  ToothCompliance c;
  const double y_inv_root = rf > rb ? rf * std::cos(theta(rf)) : y_base;
  c.bending = qags(bend, y_inv_root, yc, 1e-12);
  c.shear = qags(shear, y_inv_root, yc, 1e-12);
  c.axial = qags(axial, y_inv_root, yc, 1e-12);
  if (include_segment && rf < rb) {
    const double y_root = std::sqrt(rf * rf - h1 * h1);
    c.bending += qags(bend, y_root, y_base, 1e-12);
    c.shear += qags(shear, y_root, y_base, 1e-12);
    c.axial += qags(axial, y_root, y_base, 1e-12);
  }
  return c;
}

void expect_close(const ToothCompliance& got, const ToothCompliance& ref, double rel) {
  EXPECT_NEAR(got.bending, ref.bending, rel * ref.bending);
  EXPECT_NEAR(got.shear, ref.shear, rel * ref.shear);
  EXPECT_NEAR(got.axial, ref.axial, rel * ref.axial + 1e-30);
}

TEST(PinionTooth, AlphaIntegralsMatchCartesianRootBelowBaseCircle) {
  // The rack railway paper's pinion (docs/models/geometry.md): m = 31.831 mm, z = 22, 14 deg,
  // h_a* = 0.9, h_a0* = 1.066 -> r_f = 316.21 < r_b = 339.74 mm.
  const PinionSpec p = spec(22, 0.031831, 14, 0.9, 1.066, 0.0, 0.06);
  const MeshGeometry g = make_geometry(p);
  ASSERT_LT(g.pinion.root_radius, g.pinion.base_radius);
  Numerics n;
  n.quadrature_order = 16;
  const PinionToothCompliance tooth(g, p, Effects{}, n);
  for (double f : {0.02, 0.3, 0.6, 0.9, 1.0}) {
    const double s = g.path.s_end * f;
    SCOPED_TRACE(s);
    expect_close(tooth.at(s), cartesian(g, p, s, true), 1e-7);
  }
}

TEST(PinionTooth, AlphaIntegralsMatchCartesianRootAboveBaseCircle) {
  // z = 60, 20 deg, standard 1 / 1.25: r_f = 28.75 m > r_b = 28.19 m.
  const PinionSpec p = spec(60, 0.01, 20, 1.0, 1.25, 0.0, 0.05);
  const MeshGeometry g = make_geometry(p);
  ASSERT_GT(g.pinion.root_radius, g.pinion.base_radius);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  const double s0 = s_lowest(g);
  for (double f : {0.05, 0.5, 1.0}) {
    const double s = s0 + f * (g.path.s_end - s0);
    SCOPED_TRACE(s);
    expect_close(tooth.at(s), cartesian(g, p, s, false), 1e-7);
  }
}

TEST(PinionTooth, RootSegmentClosedFormMatchesNumericalIntegration) {
  // The 2.4 closed form is the difference "segment on" - "segment off";
  // compare it with QAGS over the straight segment alone.
  for (double x : {0.0, -0.3}) {
    const PinionSpec p = spec(18, 0.005, 20, 1.0, 1.25, x, 0.03);
    const MeshGeometry g = make_geometry(p);
    ASSERT_LT(g.pinion.root_radius, g.pinion.base_radius);
    Effects on, off;
    off.root_segment = false;
    const PinionToothCompliance with(g, p, on, Numerics{}), without(g, p, off, Numerics{});
    for (double s : {0.3 * g.path.s_end, g.path.s_end}) {
      const ToothCompliance a = with.at(s), b = without.at(s);
      const ToothCompliance full = cartesian(g, p, s, true), inv_only = cartesian(g, p, s, false);
      EXPECT_NEAR(a.bending - b.bending, full.bending - inv_only.bending, 1e-9 * full.bending);
      EXPECT_NEAR(a.shear - b.shear, full.shear - inv_only.shear, 1e-9 * full.shear);
      EXPECT_NEAR(a.axial - b.axial, full.axial - inv_only.axial, 1e-9 * full.axial + 1e-30);
      EXPECT_GT(a.bending - b.bending, 0.0);
    }
  }
}

TEST(PinionTooth, ComplianceGrowsTowardsTheTip) {
  // Monotone from the point where the load angle alpha_1 = s/r_b - alpha_2
  // turns positive. Below it (only reachable near the base circle with
  // interference ignored, e.g. the rack railway paper's pinion for s < 25 mm) the tilted load's
  // axial part adds to the moment and the compliance falls slightly as the
  // contact rises; the Cartesian reference above reproduces that too.
  for (const PinionSpec& p : {spec(22, 0.031831, 14, 0.9, 1.066, 0.0, 0.06),
                              spec(60, 0.01, 20, 1.0, 1.25, 0.0, 0.05),
                              spec(17, 0.02, 20, 1.0, 1.25, 0.0, 0.1)}) {
    const MeshGeometry g = make_geometry(p);
    const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
    const double s0 = std::max(s_lowest(g), g.pinion.base_radius * g.pinion.half_base_angle);
    double last_b = 0, last_t = 0;
    for (int i = 1; i <= 40; ++i) {
      const ToothCompliance c = tooth.at(s0 + (g.path.s_end - s0) * i / 40.0);
      EXPECT_GT(c.bending, last_b);
      EXPECT_GT(c.total(), last_t);
      last_b = c.bending;
      last_t = c.total();
    }
  }
}

TEST(PinionTooth, QuadratureOrderConvergesToAdaptive) {
  const PinionSpec p = spec(22, 0.031831, 14, 0.9, 1.066, 0.0, 0.06);
  const MeshGeometry g = make_geometry(p);
  Numerics adaptive;
  adaptive.adaptive_quadrature = true;
  const PinionToothCompliance ref(g, p, Effects{}, adaptive);
  for (double s : {0.1 * g.path.s_end, g.path.s_end}) {
    const double exact = ref.at(s).total();
    double last_err = 1.0;
    for (int order : {4, 8, 12}) {
      Numerics n;
      n.quadrature_order = order;
      const double err = std::fabs(PinionToothCompliance(g, p, Effects{}, n).at(s).total() - exact) / exact;
      EXPECT_LE(err, last_err) << "order " << order;
      last_err = err;
    }
    // From order 16 the involute integrals are tabulated per tooth instead of
    // integrated per contact: at rounding level against QAGS for every order,
    // so there is no convergence in the order left to check.
    for (int order : {16, 32}) {
      Numerics n;
      n.quadrature_order = order;
      const double err = std::fabs(PinionToothCompliance(g, p, Effects{}, n).at(s).total() - exact) / exact;
      EXPECT_LT(err, 1e-12) << "order " << order;
    }
  }
}

TEST(PinionTooth, SwitchesAndClamping) {
  const PinionSpec p = spec(22, 0.031831, 14, 0.9, 1.066, 0.0, 0.06);
  const MeshGeometry g = make_geometry(p);
  Effects off;
  off.pinion_tooth = false;
  EXPECT_EQ(PinionToothCompliance(g, p, off, Numerics{}).at(0.1).total(), 0.0);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  // s <= 0 (interference ignored) is evaluated at the base circle.
  EXPECT_EQ(tooth.at(-0.02).total(), tooth.at(0.0).total());
  EXPECT_GT(tooth.at(0.0).bending, 0.0);  // the root segment still bends
  EXPECT_THROW(tooth.at(g.path.s_end * 1.01), InputError);
  EXPECT_NO_THROW(tooth.at(g.path.s_end));
}

// ---- spalls (docs/models/tooth.md) -------------------------------------------------

// The spalling paper's pinion (docs/models/sources.md: z = 17, x = 0, 20 deg, h_a* = 1); module 20 mm
// and face 100 mm chosen here so that the 2 mm deep seed spall fits the tooth:
// r = 170, r_b = 159.75, r_f = 145, r_a = 190 mm.
PinionSpec spalling_paper() { return spec(17, 0.020, 20, 1.0, 1.25, 0.0, 0.100); }

TEST(PinionToothSpall, OnlyTheBandBetweenContactAndRootCounts) {
  const PinionSpec p = spalling_paper();
  const MeshGeometry g = make_geometry(p);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  const double rb = g.pinion.base_radius;
  auto s_at = [&](double r) { return std::sqrt(r * r - rb * rb); };
  const double s = s_at(0.175);  // contact at r = 175 mm
  const ToothCompliance clean = tooth.at(s);
  const SpallBand above{0.178, 0.186, 0.005, 0.002};
  EXPECT_DOUBLE_EQ(tooth.at(s, &above).total(), clean.total());
  const SpallBand below{0.165, 0.170, 0.005, 0.002};
  // Total and shear rise. (Bending alone may move either way by a hair: the
  // centroid shift also lengthens the counter-moment arm h - e_s of the
  // axial part, docs/models/tooth.md.)
  EXPECT_GT(tooth.at(s, &below).total(), clean.total() * (1 + 1e-6));
  EXPECT_GT(tooth.at(s, &below).shear, clean.shear);
  // A band straddling the contact acts like its part below the contact.
  const SpallBand straddle{0.165, 0.185, 0.005, 0.002}, cut{0.165, 0.175, 0.005, 0.002};
  EXPECT_NEAR(tooth.at(s, &straddle).total(), tooth.at(s, &cut).total(), 1e-12 * clean.total());
  // Zero width or depth: no effect.
  const SpallBand none{0.165, 0.170, 0.0, 0.002};
  EXPECT_EQ(tooth.at(s, &none).total(), clean.total());
}

TEST(PinionToothSpall, SpallingPaperLengthsIncreaseComplianceMonotonically) {
  // The spalling paper's spall: depth 2 mm, width 5 mm, lengths 5/10/15 mm (docs/models/sources.md),
  // lower edge at r = 162 mm, contact at the tip.
  const PinionSpec p = spalling_paper();
  const MeshGeometry g = make_geometry(p);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  const double s = g.path.s_end;
  double last = tooth.at(s).total();
  for (double len : {0.005, 0.010, 0.015}) {
    const SpallBand band{0.162, 0.162 + len, 0.005, 0.002};
    const double c = tooth.at(s, &band).total();
    EXPECT_GT(c, last) << "length " << len;
    last = c;
  }
  // Small effect expected: a 5 mm wide pit on a 100 mm face.
  EXPECT_LT(last / tooth.at(s).total() - 1.0, 0.05);
}

TEST(PinionToothSpall, PittedBandMatchesCartesianWithReducedSection) {
  // Independent check of the band integral: the same Cartesian centre-line
  // integration with the reduced section written out here (docs/models/tooth.md):
  // A = 2hb - hs ws, e = -ws hs (h - hs/2)/A, I = (2/3)h^3 b - ws[h^3 - (h-hs)^3]/3 - A e^2,
  // lever (yc - y) cos a1 - (hc - e) sin a1.
  const PinionSpec p = spalling_paper();
  const MeshGeometry g = make_geometry(p);
  Numerics n;
  n.adaptive_quadrature = true;
  const PinionToothCompliance tooth(g, p, Effects{}, n);
  const double rb = g.pinion.base_radius, a2 = g.pinion.half_base_angle;
  const double E = 210e9, G = p.material.shear_modulus(), b = p.face_width, ws = 0.02, hs = 0.004;
  const double r_lo = 0.163, r_hi = 0.172, rc = 0.185, s = std::sqrt(rc * rc - rb * rb);
  auto theta = [&](double r) { return a2 - inv(std::acos(rb / r)); };
  const double ac = std::acos(rb / rc), yc = rc * std::cos(theta(rc)), hc = rc * std::sin(theta(rc));
  const double a1 = ac - theta(rc);
  auto r_of_y = [&](double y) {
    double lo = rb, hi = rc;
    for (int i = 0; i < 200; ++i) { const double mid = 0.5 * (lo + hi); (mid * std::cos(theta(mid)) < y ? lo : hi) = mid; }
    return 0.5 * (lo + hi);
  };
  auto density_difference = [&](double y) {  // pitted minus clean, bending+shear+axial
    const double r = r_of_y(y), h = r * std::sin(theta(r));
    const double A = 2 * h * b - hs * ws, e = -ws * hs * (h - hs / 2) / A;
    const double I = 2.0 / 3.0 * h * h * h * b - ws * (h * h * h - std::pow(h - hs, 3)) / 3 - A * e * e;
    const double Mp = std::cos(a1) * (yc - y) - (hc - e) * std::sin(a1), M0 = std::cos(a1) * (yc - y) - hc * std::sin(a1);
    const double I0 = 2.0 / 3.0 * h * h * h * b, A0 = 2 * h * b;
    const double kc = 1.2 * std::pow(std::cos(a1), 2) / G + std::pow(std::sin(a1), 2) / E;
    return Mp * Mp / (E * I) - M0 * M0 / (E * I0) + kc * (1 / A - 1 / A0);
  };
  const double y_lo = r_lo * std::cos(theta(r_lo)), y_hi = r_hi * std::cos(theta(r_hi));
  const SpallBand band{r_lo, r_hi, ws, hs};
  const double expected = qags(density_difference, y_lo, y_hi, 1e-12);
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(tooth.at(s, &band).total() - tooth.at(s).total(), expected, 1e-7 * expected);
  // Fixed order 16 agrees with the adaptive reference.
  const PinionToothCompliance fixed(g, p, Effects{}, Numerics{});
  EXPECT_NEAR(fixed.at(s, &band).total(), tooth.at(s, &band).total(), 1e-9 * tooth.at(s, &band).total());
}

TEST(PinionToothSpall, BandReachingIntoTheRootSegment) {
  // r_f = 145 < r_b = 159.75 mm: a band extending below the base circle also
  // weakens the straight segment; the result grows continuously as the lower
  // edge moves down from r_b.
  const PinionSpec p = spalling_paper();
  const MeshGeometry g = make_geometry(p);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  const double rb = g.pinion.base_radius, s = g.path.s_end;
  const SpallBand at_base{rb, 0.168, 0.005, 0.002}, just_below{rb - 1e-9, 0.168, 0.005, 0.002},
      deep{0.150, 0.168, 0.005, 0.002};
  const double c0 = tooth.at(s, &at_base).total();
  EXPECT_NEAR(tooth.at(s, &just_below).total(), c0, 1e-9 * c0);
  EXPECT_GT(tooth.at(s, &deep).total(), c0);
}

TEST(PinionToothSpall, ImpossibleBandsAreDesignErrors) {
  const PinionSpec p = spalling_paper();
  const MeshGeometry g = make_geometry(p);
  const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
  const double s = g.path.s_end;
  auto code = [&](SpallBand band) {
    try {
      tooth.at(s, &band);
    } catch (const DesignError& e) {
      return e.code();
    }
    return std::string("none");
  };
  // Full tooth thickness at the tip edge r = 186 mm: 2 h_x, from the tooth itself.
  const double thick = 2 * tooth.half_thickness_at_radius(0.186);
  EXPECT_EQ(code({0.180, 0.186, 0.005, thick * 1.0001}), "spall_too_deep");
  EXPECT_EQ(code({0.180, 0.186, 0.005, thick * 0.9}), "none");
  EXPECT_EQ(code({0.165, 0.170, 0.1001, 0.002}), "spall_too_wide");
  EXPECT_EQ(code({0.165, 0.170, 0.100, 0.002}), "none");  // full width, partial depth: allowed
  EXPECT_EQ(code({0.185, 0.195, 0.005, 0.002}), "spall_off_profile");  // above r_a = 190
  EXPECT_EQ(code({0.140, 0.150, 0.005, 0.002}), "spall_off_profile");  // below r_f = 145
  EXPECT_THROW(tooth.validate({0.17, 0.16, 0.005, 0.002}), InputError);
  // Independent thickness check: h_x at r = 186 mm from theta(r).
  const double rb = g.pinion.base_radius, a2 = g.pinion.half_base_angle;
  EXPECT_NEAR(thick / 2, 0.186 * std::sin(a2 - inv(std::acos(rb / 0.186))), 1e-12);
}

// ---- hard cases ---------------------------------------------------------------

TEST(PinionTooth, HardCasesFiniteAndPositive) {
  struct Case { int z; double a0, x, b; };
  for (const Case& k : {Case{8, 20, 0.0, 0.005}, Case{8, 20, -0.5, 0.5}, Case{150, 20, 0.0, 0.05},
                        Case{20, 12, 0.0, 0.05}, Case{20, 30, 0.0, 0.05}, Case{20, 20, 1.0, 0.5},
                        Case{30, 20, -0.5, 0.005}, Case{150, 30, 1.0, 0.5}, Case{8, 30, 0.0, 0.005},
                        Case{8, 12, 0.0, 0.5}}) {
    SCOPED_TRACE(::testing::Message() << "z " << k.z << " a0 " << k.a0 << " x " << k.x << " b " << k.b);
    const PinionSpec p = spec(k.z, 0.01, k.a0, 1.0, 1.25, k.x, k.b);
    const MeshGeometry g = make_geometry(p);
    const PinionToothCompliance tooth(g, p, Effects{}, Numerics{});
    // Start of the active profile: just above the larger of r_b and r_f.
    for (double s : {s_lowest(g) + 1e-6, 0.5 * (s_lowest(g) + g.path.s_end), g.path.s_end}) {
      const ToothCompliance c = tooth.at(s);
      EXPECT_TRUE(std::isfinite(c.total()));
      EXPECT_GT(c.bending, 0.0);
      EXPECT_GT(c.shear, 0.0);
      EXPECT_GE(c.axial, 0.0);
    }
  }
}

}  // namespace
}  // namespace rackopt

// ---- with the real geometry module ---------------------------------------------

namespace rackopt {
namespace {

TEST(ToothModelsOnBuiltGeometry, StartAndTipOfActiveProfileFiniteAndPositive) {
  // The same hard cases through build_mesh_geometry, evaluated exactly at
  // path.s_start and path.s_end. Designs the geometry rejects (DesignError)
  // are skipped: they never reach the stiffness models.
  struct Case { int z; double a0, x, b; };
  int evaluated = 0;
  for (const Case& k : {Case{8, 20, 0.0, 0.005}, Case{8, 20, -0.5, 0.5}, Case{150, 20, 0.0, 0.05},
                        Case{20, 12, 0.0, 0.05}, Case{20, 30, 0.0, 0.05}, Case{20, 20, 1.0, 0.5},
                        Case{30, 20, -0.5, 0.005}, Case{150, 30, 1.0, 0.5}, Case{17, 20, 0.0, 0.1}}) {
    for (bool interference : {true, false}) {
      SCOPED_TRACE(::testing::Message() << "z " << k.z << " a0 " << k.a0 << " x " << k.x
                                        << " b " << k.b << " limit " << interference);
      Drive d;
      d.pinion = spec(k.z, 0.01, k.a0, 1.0, 1.25, k.x, k.b);
      d.pinion.tip_radius_coef = 0.2;
      d.pinion.bore_radius = 0.4 * (d.pinion.module * k.z / 2 - 1.25 * d.pinion.module);
      d.effects.interference_limit = interference;
      MeshGeometry g;
      try {
        g = build_mesh_geometry(d);
      } catch (const DesignError&) {
        continue;
      }
      const PinionToothCompliance tooth(g, d.pinion, d.effects, d.numerics);
      const FilletFoundationCompliance fillet(g, d.pinion);
      const RackToothCompliance rack(g, d.rack, k.b, d.numerics);
      for (double s : {g.path.s_start, g.path.s_end}) {
        const ToothCompliance c = tooth.at(s), r = rack.at(s);
        const double f = fillet.at(s, k.b);
        EXPECT_TRUE(std::isfinite(c.total() + r.total() + f));
        EXPECT_GT(c.bending, 0.0);
        EXPECT_GT(c.shear, 0.0);
        EXPECT_GT(f, 0.0);
        EXPECT_GE(r.total(), 0.0);  // zero only when the contact is on the rack root line
      }
      ++evaluated;
    }
  }
  EXPECT_GE(evaluated, 10);
}

}  // namespace
}  // namespace rackopt
