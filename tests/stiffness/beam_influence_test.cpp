// Influence functions of a simply supported beam (beam_influence.hpp) against
//  * textbook closed forms (Gere & Goodno, Mechanics of Materials, App. G
//    "Deflections and slopes of simply supported beams"; Roark's Formulas for
//    Stress and Strain, Table 8.1, simply supported ends), written in the
//    forms the tables print (sign-adapted), not the forms the implementation uses;
//  * the unit-load (virtual work) method: flexibility = integral of
//    M_A M_B / EI (+ V_A V_B / kGA) over the span, with the moment and shear
//    diagrams from statics and the integral done by Simpson's rule on each
//    piece between load points (exact for the quadratic integrands).
// Sign convention of the header: v up, couples and rotations counterclockwise.
#include "rackopt/stiffness/beam_influence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hb = rackopt::hinged_beam;

namespace {

constexpr double kL = 2.4;  // span [m] used throughout (docs/models/rack_span.md)

// ---- unit-load method ------------------------------------------------------
// A unit load of one kind at xi: force (upward) or couple (counterclockwise).
enum class Kind { kForce, kCouple };

struct UnitLoad {
  Kind kind;
  double xi;
  // Left hinge reaction (upward) from moment equilibrium about the right hinge.
  double left_reaction(double l) const {
    return kind == Kind::kForce ? -(l - xi) / l : 1.0 / l;
  }
  // Sagging bending moment at x: sum over the part left of x of F (x - x_F)
  // minus the counterclockwise couples.
  double moment(double x, double l) const {
    double m = left_reaction(l) * x;
    if (x > xi) m += kind == Kind::kForce ? (x - xi) : -1.0;
    return m;
  }
  // Shear force at x: sum of the upward forces left of x.
  double shear(double x, double l) const {
    double v = left_reaction(l);
    if (x > xi && kind == Kind::kForce) v += 1.0;
    return v;
  }
};

// Integral over [0, l] of f, piecewise Simpson between the breakpoints (the
// integrands are polynomials of degree <= 2 between load points).
template <class F>
double piecewise_simpson(F f, double l, std::vector<double> breaks) {
  breaks.push_back(0.0);
  breaks.push_back(l);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (b <= a) continue;
    // Evaluate just inside the piece so the jump at a load point is not sampled.
    const double eps = 1e-12 * l;
    const double fa = f(a + eps), fm = f(0.5 * (a + b)), fb = f(b - eps);
    sum += (b - a) / 6.0 * (fa + 4.0 * fm + fb);
  }
  return sum;
}

// EI * (displacement conjugate to `response` at its point) per unit `load`.
double virtual_work_bending(const UnitLoad& response, const UnitLoad& load, double l) {
  return piecewise_simpson(
      [&](double x) { return response.moment(x, l) * load.moment(x, l); }, l,
      {response.xi, load.xi});
}
double virtual_work_shear(const UnitLoad& response, const UnitLoad& load, double l) {
  return piecewise_simpson(
      [&](double x) { return response.shear(x, l) * load.shear(x, l); }, l,
      {response.xi, load.xi});
}

const std::vector<double> kPoints = {0.0, 0.05, 0.3, 0.9, 1.2, 1.55, 2.0, 2.35, 2.4};

}  // namespace

// Gere App. G, case "load P at distance a": v = P b x (L^2 - b^2 - x^2)/(6 L EI)
// for x <= a and v = (P b/(6 L EI)) [(L/b)(x - a)^3 + (L^2 - b^2) x - x^3] for
// x >= a (deflection positive in the load direction).
TEST(BeamInfluence, PointForceDeflectionMatchesGere) {
  for (double a : {0.3, 0.9, 1.2, 2.0}) {
    const double b = kL - a;
    for (double x : kPoints) {
      const double expected =
          x <= a ? b * x * (kL * kL - b * b - x * x) / (6.0 * kL)
                 : b / (6.0 * kL) * ((kL / b) * std::pow(x - a, 3) + (kL * kL - b * b) * x - x * x * x);
      EXPECT_NEAR(hb::bending_deflection_per_force(x, a, kL), expected, 1e-14)
          << "x = " << x << ", a = " << a;
    }
  }
}

// Midspan load: delta = P L^3 / (48 EI) (every textbook).
TEST(BeamInfluence, MidspanForceDeflection) {
  EXPECT_NEAR(hb::bending_deflection_per_force(kL / 2, kL / 2, kL), kL * kL * kL / 48.0, 1e-14);
  const double l = 10.0;
  EXPECT_NEAR(hb::bending_deflection_per_force(l / 2, l / 2, l), l * l * l / 48.0, 1e-11);
}

// Gere App. G: end slopes under P at a: theta_A = P a b (L + b)/(6 L EI),
// theta_B = P a b (L + a)/(6 L EI) (both "downward" rotations: for an upward
// force the left end turns counterclockwise, the right end clockwise).
TEST(BeamInfluence, PointForceSupportRotationsMatchGere) {
  for (double a : {0.3, 1.2, 2.0}) {
    const double b = kL - a;
    EXPECT_NEAR(hb::bending_rotation_per_force(0.0, a, kL), a * b * (kL + b) / (6.0 * kL), 1e-14);
    EXPECT_NEAR(hb::bending_rotation_per_force(kL, a, kL), -a * b * (kL + a) / (6.0 * kL), 1e-14);
  }
}

// Gere App. G, case "couple M0 at distance a" (written for a counterclockwise
// couple and upward v): v = M0 x (x^2 + 3a^2 - 6 a L + 2 L^2)/(6 L EI) for
// x <= a, v = -M0 (L - x)(3a^2 - 2 L x + x^2)/(6 L EI) for x >= a;
// theta_A = -M0 (6 a L - 3a^2 - 2L^2)/(6 L EI), theta_B = M0 (3a^2 - L^2)/(6 L EI).
TEST(BeamInfluence, PointCoupleDeflectionAndSupportRotationsMatchGere) {
  for (double a : {0.3, 0.9, 1.2, 2.0}) {
    for (double x : kPoints) {
      const double expected =
          x <= a ? x * (x * x + 3 * a * a - 6 * a * kL + 2 * kL * kL) / (6 * kL)
                 : -(kL - x) * (3 * a * a - 2 * kL * x + x * x) / (6 * kL);
      EXPECT_NEAR(hb::bending_deflection_per_couple(x, a, kL), expected, 1e-14) << x << " " << a;
    }
    EXPECT_NEAR(hb::bending_rotation_per_couple(0.0, a, kL),
                -(6 * a * kL - 3 * a * a - 2 * kL * kL) / (6 * kL), 1e-14);
    EXPECT_NEAR(hb::bending_rotation_per_couple(kL, a, kL), (3 * a * a - kL * kL) / (6 * kL), 1e-14);
  }
}

// Couple at an end (a = 0), every table: rotation there M L/(3 EI), at the far
// end -M L/(6 EI), v = M x (L - x)(2L - x)/(6 L EI), midpoint M L^2/(16 EI).
// Couple at the centre: by antisymmetry each half is a simply supported beam
// of length L/2 with the end couple M/2 at the centre, so the end-couple case
// gives rotation under the couple (M/2)(L/2)/(3EI) = M L/(12 EI), end rotations -M L/(24 EI), v(L/2) = 0 and quarter points
// -/+ (M/2)(L/2)^2/(16 EI) = -/+ M L^2/(128 EI).
TEST(BeamInfluence, CoupleSpecialCases) {
  EXPECT_NEAR(hb::bending_rotation_per_couple(kL / 2, kL / 2, kL), kL / 12.0, 1e-14);
  EXPECT_NEAR(hb::bending_rotation_per_couple(0.0, kL / 2, kL), -kL / 24.0, 1e-14);
  EXPECT_NEAR(hb::bending_rotation_per_couple(kL, kL / 2, kL), -kL / 24.0, 1e-14);
  EXPECT_NEAR(hb::bending_deflection_per_couple(kL / 2, kL / 2, kL), 0.0, 1e-14);
  EXPECT_NEAR(hb::bending_deflection_per_couple(kL / 4, kL / 2, kL), -kL * kL / 128.0, 1e-14);
  EXPECT_NEAR(hb::bending_deflection_per_couple(3 * kL / 4, kL / 2, kL), kL * kL / 128.0, 1e-14);

  EXPECT_NEAR(hb::bending_rotation_per_couple(0.0, 0.0, kL), kL / 3.0, 1e-14);
  EXPECT_NEAR(hb::bending_rotation_per_couple(kL, 0.0, kL), -kL / 6.0, 1e-14);
  for (double x : kPoints) {
    EXPECT_NEAR(hb::bending_deflection_per_couple(x, 0.0, kL),
                x * (kL - x) * (2 * kL - x) / (6 * kL), 1e-14);
  }
}

// Rotation under a couple at a: M (3a^2 - 3 a L + L^2)/(3 L EI) (Roark 3e,
// docs/models/rack_span.md writes it as (a^3 + b^3)/(3 L^2)).
TEST(BeamInfluence, RotationUnderCouple) {
  for (double a : {0.0, 0.15, 0.6, 1.2, 1.8, 2.25, 2.4}) {
    const double b = kL - a;
    EXPECT_NEAR(hb::bending_rotation_per_couple(a, a, kL), (a * a * a + b * b * b) / (3 * kL * kL),
                1e-14);
  }
}

// All four bending functions and the two shear functions against the
// unit-load method, for every pair of points (including both hinges).
TEST(BeamInfluence, MatchesVirtualWorkEverywhere) {
  for (double x : kPoints) {
    for (double xi : kPoints) {
      const UnitLoad fx{Kind::kForce, x}, cx{Kind::kCouple, x};
      const UnitLoad fxi{Kind::kForce, xi}, cxi{Kind::kCouple, xi};
      EXPECT_NEAR(hb::bending_deflection_per_force(x, xi, kL), virtual_work_bending(fx, fxi, kL), 1e-12);
      EXPECT_NEAR(hb::bending_deflection_per_couple(x, xi, kL), virtual_work_bending(fx, cxi, kL), 1e-12);
      EXPECT_NEAR(hb::bending_rotation_per_force(x, xi, kL), virtual_work_bending(cx, fxi, kL), 1e-12);
      EXPECT_NEAR(hb::bending_rotation_per_couple(x, xi, kL), virtual_work_bending(cx, cxi, kL), 1e-12);
      EXPECT_NEAR(hb::shear_deflection_per_force(x, xi, kL), virtual_work_shear(fx, fxi, kL), 1e-12);
      // Force-couple shear cross terms vanish: the shear of a force integrates
      // to zero against the constant shear of a couple.
      EXPECT_NEAR(virtual_work_shear(fx, cxi, kL), 0.0, 1e-12);
      EXPECT_NEAR(hb::shear_rotation_per_couple(kL), virtual_work_shear(cx, cxi, kL), 1e-12);
    }
  }
}

// Maxwell-Betti: v at x per couple at xi == rotation at xi per force at x.
TEST(BeamInfluence, MaxwellBetti) {
  for (double x : kPoints) {
    for (double xi : kPoints) {
      EXPECT_NEAR(hb::bending_deflection_per_couple(x, xi, kL),
                  hb::bending_rotation_per_force(xi, x, kL), 1e-14);
      EXPECT_EQ(hb::bending_deflection_per_force(x, xi, kL), hb::bending_deflection_per_force(xi, x, kL));
      EXPECT_EQ(hb::bending_rotation_per_couple(x, xi, kL), hb::bending_rotation_per_couple(xi, x, kL));
    }
  }
}

// Axial bar: pin-pin is two springs EA/a and EA/(L - a) in parallel, so
// u(a) = a (L - a)/(L EA), linear on each side; pin-roller is one spring EA/a
// and everything right of the load moves with it.
TEST(BeamInfluence, AxialPinPinVersusPinRoller) {
  for (double a : {0.0, 0.3, 1.2, 2.0, 2.4}) {
    const double springs = a == 0.0 || a == kL ? 0.0 : 1.0 / (1.0 / a + 1.0 / (kL - a));
    EXPECT_NEAR(hb::axial_displacement_pin_pin(a, a, kL), springs, 1e-14);
    EXPECT_NEAR(hb::axial_displacement_pin_roller(a, a), a, 1e-14);
    for (double x : kPoints) {
      const double pin_pin = x <= a ? springs * (a > 0 ? x / a : 0.0)
                                    : springs * (kL - x) / (kL - a);
      EXPECT_NEAR(hb::axial_displacement_pin_pin(x, a, kL), pin_pin, 1e-14) << x << " " << a;
      EXPECT_NEAR(hb::axial_displacement_pin_roller(x, a), std::min(x, a), 1e-14);
    }
    // A roller at the right end can only make the bar softer.
    EXPECT_GE(hb::axial_displacement_pin_roller(a, a), hb::axial_displacement_pin_pin(a, a, kL));
  }
}
