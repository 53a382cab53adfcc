// Rack tooth (straight-sided trapezoid cantilever), docs/models/tooth.md.
//
// References computed here: GSL QAGS (adaptive Gauss-Kronrod) of the energy
// densities written directly from 5.1 (M = F[cos a0 (y_c - y) - sin a0 w_c],
// I = (2/3) w^3 b, A = 2 w b, shear factor 1.2), and the prismatic cantilever
// textbook values (F L^3/(3EI), 1.2 F L/(GA), F L/(EA)).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "stiffness_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/rack_tooth.hpp"

namespace rackopt {
namespace {

using test::deg;
using test::kPi;
using test::qags;

struct RackCase {
  MeshGeometry g;
  RackSpec rack;
};

// Module m, flank angle a0, rack addendum 1.0 m, dedendum 1.25 m, w_f = pi m/4
// + dedendum tan a0 (docs/models/tooth.md); pinion z = 20 for the contact height.
RackCase make(double m, double a0, double x = 0.0, double clearance = 0.0) {
  RackCase s;
  s.g.pressure_angle = a0;
  s.g.clearance = clearance;
  s.g.profile_shift_length = x * m;
  s.g.pinion.pitch_radius = 10 * m;
  s.g.rack.pitch = kPi * m;
  s.g.rack.addendum = 1.0 * m;
  s.g.rack.dedendum = 1.25 * m;
  s.g.rack.half_thickness_at_datum = kPi * m / 4;
  s.g.rack.half_thickness_at_root = kPi * m / 4 + 1.25 * m * std::tan(a0);
  s.rack.material.youngs_modulus = 206e9;
  s.rack.material.poisson_ratio = 0.29;
  return s;
}

// Energies of the trapezoid by quadrature, optionally with a pit (ws, hs) in
// [lo, hi] (exact 9.1 section written out again here).
ToothCompliance reference(const RackCase& s, double b, double yc, double ws = 0, double hs = 0,
                          double lo = 0, double hi = 0) {
  const double a0 = s.g.pressure_angle, wf = s.g.rack.half_thickness_at_root;
  const double E = s.rack.material.youngs_modulus, G = s.rack.material.shear_modulus();
  const double wc = wf - yc * std::tan(a0);
  auto section = [&](double y, double& A, double& I, double& e) {
    const double w = wf - y * std::tan(a0);
    A = 2 * w * b;
    I = 2.0 / 3.0 * w * w * w * b;
    e = 0;
    if (y > lo && y < hi) {
      A -= ws * hs;
      e = -ws * hs * (w - hs / 2) / A;
      I -= ws * (w * w * w - std::pow(w - hs, 3)) / 3 + A * e * e;
    }
  };
  auto bend = [&](double y) {
    double A, I, e;
    section(y, A, I, e);
    const double M = std::cos(a0) * (yc - y) - std::sin(a0) * (wc - e);
    return M * M / (E * I);
  };
  auto shear = [&](double y) { double A, I, e; section(y, A, I, e); return 1.2 * std::pow(std::cos(a0), 2) / (G * A); };
  auto axial = [&](double y) { double A, I, e; section(y, A, I, e); return std::pow(std::sin(a0), 2) / (E * A); };
  ToothCompliance c;
  for (auto [a, z] : {std::pair{0.0, std::min(lo, yc)}, std::pair{std::min(lo, yc), std::min(hi, yc)},
                      std::pair{std::min(hi, yc), yc}}) {
    if (z <= a) continue;
    c.bending += qags(bend, a, z, 1e-13);
    c.shear += qags(shear, a, z, 1e-13);
    c.axial += qags(axial, a, z, 1e-13);
  }
  return c;
}

TEST(RackTooth, ClosedFormsMatchQuadrature) {
  // docs/models/tooth.md: closed forms agree with quadrature "to 5 significant
  // figures"; we demand 1e-9 (they are exact).
  for (double a0 : {14.0, 20.0, 25.0, 5.5}) {
    const RackCase s = make(0.02, deg(a0));
    const RackToothCompliance tooth(s.g, s.rack, 0.08, Numerics{});
    for (double yc : {0.005, 0.020, 0.030, 0.045}) {
      SCOPED_TRACE(::testing::Message() << "a0 " << a0 << " y_c " << yc);
      const ToothCompliance got = tooth.at_height(yc), ref = reference(s, 0.08, yc);
      EXPECT_NEAR(got.bending, ref.bending, 1e-9 * ref.bending);
      EXPECT_NEAR(got.shear, ref.shear, 1e-9 * ref.shear);
      EXPECT_NEAR(got.axial, ref.axial, 1e-9 * ref.axial);
    }
  }
}

TEST(RackTooth, SmallAngleBranchMatchesQuadratureAndIsContinuousAt5Degrees) {
  for (double a0 : {0.5, 3.0, 4.999, 5.001}) {
    const RackCase s = make(0.01, deg(a0));
    const RackToothCompliance tooth(s.g, s.rack, 0.05, Numerics{});
    const ToothCompliance got = tooth.at_height(0.02), ref = reference(s, 0.05, 0.02);
    EXPECT_NEAR(got.bending, ref.bending, 1e-9 * ref.bending) << a0;
    EXPECT_NEAR(got.total(), ref.total(), 1e-9 * ref.total()) << a0;
  }
}

TEST(RackTooth, ZeroAngleLimitIsThePrismaticCantilever) {
  // a0 -> 0: rectangle of half-thickness w_f = pi m/4: bending y^3/(2 E b w_f^3)
  // (= F L^3/(3EI) with I = (2/3) w_f^3 b, docs/models/tooth.md), shear
  // 1.2 L/(G 2 w_f b), axial 0 (no axial component at a0 = 0).
  const double m = 0.01, b = 0.05, yc = 0.02;
  const RackCase s = make(m, 0.0);
  const double E = 206e9, G = s.rack.material.shear_modulus(), wf = kPi * m / 4;
  const ToothCompliance c = RackToothCompliance(s.g, s.rack, b, Numerics{}).at_height(yc);
  EXPECT_NEAR(c.bending, yc * yc * yc / (2 * E * b * wf * wf * wf), 1e-12 * c.bending);
  EXPECT_NEAR(c.shear, 1.2 * yc / (G * 2 * wf * b), 1e-12 * c.shear);
  EXPECT_EQ(c.axial, 0.0);
  // And it is approached smoothly: at 1e-4 rad within 1e-3 relative.
  const RackCase t = make(m, 1e-4);
  const ToothCompliance d = RackToothCompliance(t.g, t.rack, b, Numerics{}).at_height(yc);
  EXPECT_NEAR(d.bending, c.bending, 1e-3 * c.bending);
  EXPECT_NEAR(d.shear, c.shear, 1e-3 * c.shear);
}

TEST(RackTooth, ContactHeightFollowsThePathOfContact) {
  // docs/models/geometry.md: at the pitch point s_P = r sin a0 the contact is at
  // the datum shifted by x m + Delta; at s_A = s_P + ((x - h_a2*) m + Delta)/sin a0
  // it is at the rack tip (dedendum + addendum above the root).
  const double m = 0.01, a0 = deg(20), x = 0.3, delta = 0.002;
  const RackCase s = make(m, a0, x, delta);
  const RackToothCompliance tooth(s.g, s.rack, 0.05, Numerics{});
  const double r = 10 * m, sP = r * std::sin(a0), sA = sP + ((x - 1.0) * m + delta) / std::sin(a0);
  EXPECT_NEAR(tooth.contact_height(sP), 1.25 * m + x * m + delta, 1e-15);
  EXPECT_NEAR(tooth.contact_height(sA), 2.25 * m, 1e-15);
  EXPECT_DOUBLE_EQ(tooth.at(sA).total(), tooth.at_height(2.25 * m).total());
  // Same height as the geometry module's own function (kept in step by this check).
  for (double sv : {0.0, sA, sP, 0.07}) {
    EXPECT_NEAR(tooth.contact_height(sv), s.g.rack.dedendum + s.g.contact_height_above_datum(sv), 1e-15);
  }
  // Monotone: the lower the pinion contact (larger s), the lower on the rack.
  double last = 1.0;
  for (double sv = sA; sv < sA + 0.05; sv += 0.005) {
    const double c = tooth.at(sv).total();
    EXPECT_LT(c, last);
    last = c;
  }
}

TEST(RackTooth, SpallBandWithReducedSection) {
  const double m = 0.02, b = 0.1;
  const RackCase s = make(m, deg(20));
  const RackToothCompliance tooth(s.g, s.rack, b, Numerics{});
  const double yc = 0.035;
  const ToothCompliance clean = tooth.at_height(yc);
  // Band below the contact: quadrature reference with the 9.1 section.
  const SpallBand band{0.010, 0.025, 0.02, 0.004};
  const ToothCompliance got = tooth.at_height(yc, &band);
  const ToothCompliance ref = reference(s, b, yc, band.width, band.depth, band.low, band.high);
  EXPECT_NEAR(got.total(), ref.total(), 1e-9 * ref.total());
  EXPECT_GT(got.total(), clean.total());
  // Band above the contact: no effect.
  const SpallBand above{0.036, 0.044, 0.02, 0.004};
  EXPECT_NEAR(tooth.at_height(yc, &above).total(), clean.total(), 1e-12 * clean.total());
  // The spalling paper's sizes (depth 2, width 5 mm, lengths 5/10/15 mm): monotone in length.
  double last = clean.total();
  for (double len : {0.005, 0.010, 0.015}) {
    const SpallBand sb{0.012, 0.012 + len, 0.005, 0.002};
    const double c = tooth.at_height(yc, &sb).total();
    EXPECT_GT(c, last);
    last = c;
  }
}

TEST(RackTooth, SpallErrorsAndSwitch) {
  const double m = 0.02, b = 0.1;
  const RackCase s = make(m, deg(20));
  const RackToothCompliance tooth(s.g, s.rack, b, Numerics{});
  auto code = [&](SpallBand band) {
    try {
      tooth.at_height(0.03, &band);
    } catch (const DesignError& e) {
      return e.code();
    }
    return std::string("none");
  };
  const double w_top = s.g.rack.half_thickness_at_root - 0.04 * std::tan(deg(20));
  EXPECT_EQ(code({0.03, 0.04, 0.005, 2 * w_top}), "spall_too_deep");
  EXPECT_EQ(code({0.03, 0.04, 0.005, 1.9 * w_top}), "none");
  EXPECT_EQ(code({0.01, 0.02, 0.1001, 0.002}), "spall_too_wide");
  EXPECT_EQ(code({0.04, 0.046, 0.005, 0.002}), "spall_off_profile");  // tooth height 45 mm
  EXPECT_EQ(code({-0.001, 0.01, 0.005, 0.002}), "spall_off_profile");
  EXPECT_EQ(RackToothCompliance(s.g, s.rack, b, Numerics{}, false).at(0.05).total(), 0.0);
}

TEST(RackTooth, HardCasesFiniteAndPositive) {
  for (double a0 : {12.0, 30.0}) {
    for (double b : {0.005, 0.5}) {
      for (double x : {-0.5, 1.0}) {
        const RackCase s = make(0.01, deg(a0), x);
        const RackToothCompliance tooth(s.g, s.rack, b, Numerics{});
        for (double yc : {1e-6, 0.01, 0.0225}) {  // root, mid, tip
          const ToothCompliance c = tooth.at_height(yc);
          EXPECT_TRUE(std::isfinite(c.total()));
          EXPECT_GT(c.bending, 0.0);
          EXPECT_GT(c.shear, 0.0);
          EXPECT_GT(c.axial, 0.0);
        }
        EXPECT_EQ(tooth.at_height(-0.01).total(), 0.0);  // at/below the root line: nothing bends
      }
    }
  }
}

}  // namespace
}  // namespace rackopt
