// Generic cantilever energy integrator and tooth slice sections against
// textbook closed forms (Timoshenko & Gere, Mechanics of Materials: tip
// deflection of a prismatic cantilever F L^3/(3EI), shear F L kappa/(GA),
// axial F L/(EA); end moment M: rotation M L/(EI)).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/cantilever_energy.hpp"

namespace rackopt {
namespace {

TEST(GaussLegendre, IntegratesPolynomialsExactlyUpToDegree2nMinus1) {
  // integral_0^2 x^7 dx = 2^8/8 = 32 (exact for n = 4: degree 7 = 2*4 - 1).
  const GaussLegendreRule rule(4);
  EXPECT_NEAR(rule.integrate([](double x) { return std::pow(x, 7); }, 0.0, 2.0), 32.0, 1e-12);
  // integral_0^pi sin = 2 (GSL's 20-point rule reaches 1e-15).
  const GaussLegendreRule rule20(20);
  EXPECT_NEAR(rule20.integrate([](double x) { return std::sin(x); }, 0.0, std::numbers::pi), 2.0,
              1e-14);
  EXPECT_THROW(GaussLegendreRule(0), InputError);
}

TEST(Cantilever, PrismaticInclinedLoadMatchesTextbookClosedForms) {
  const double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu));
  const double L = 0.04, hx = 0.01, b = 0.06;  // 40 mm long, 20 mm thick, 60 mm wide
  const double A = 2 * hx * b, I = 2.0 / 3.0 * hx * hx * hx * b;  // b (2hx)^3 / 12
  const CantileverMaterial mat{E, G, 1.2};
  const GaussLegendreRule rule(8);
  const std::array<double, 2> stations{0.0, L};
  for (double angle_deg : {0.0, 20.0, 45.0, 70.0}) {
    const double th = angle_deg * std::numbers::pi / 180;
    CantileverLoad load{L, 0.0, std::cos(th), std::sin(th)};
    const ToothCompliance c = cantilever_compliance(
        [&](double) { return tooth_slice_section(hx, b); }, load, mat, stations, rule);
    // Components split along / across the axis; each acts through its own
    // textbook deflection, projected back on the load direction (x cos^2 or sin^2).
    EXPECT_NEAR(c.bending, std::pow(std::cos(th), 2) * L * L * L / (3 * E * I), 1e-12 * c.bending + 1e-25);
    EXPECT_NEAR(c.shear, std::pow(std::cos(th), 2) * 1.2 * L / (G * A), 1e-12 * c.shear + 1e-25);
    EXPECT_NEAR(c.axial, std::pow(std::sin(th), 2) * L / (E * A), 1e-12 * c.axial + 1e-25);
  }
}

TEST(Cantilever, OffsetAxialForceAddsEndMomentTerms) {
  // Axial force sin(th) at lateral offset e: end moment -sin(th) e. Energy of
  // M(u) = cos(th)(L-u) - sin(th) e over [0, L]:
  // [cos^2 L^3/3 - cos sin e L^2 + sin^2 e^2 L]/(EI) (superposition of tip force and end couple).
  const double E = 200e9, G = 80e9, L = 0.05, hx = 0.008, b = 0.03, e = 0.006;
  const double I = 2.0 / 3.0 * hx * hx * hx * b;
  const double th = 0.4, c = std::cos(th), s = std::sin(th);
  const CantileverMaterial mat{E, G, 1.2};
  const std::array<double, 3> stations{0.0, 0.02, L};  // split must not matter
  const ToothCompliance got = cantilever_compliance(
      [&](double) { return tooth_slice_section(hx, b); }, CantileverLoad{L, e, c, s}, mat,
      stations, GaussLegendreRule(4));
  const double expected = (c * c * L * L * L / 3 - c * s * e * L * L + s * s * e * e * L) / (E * I);
  EXPECT_NEAR(got.bending, expected, 1e-12 * expected);
}

TEST(ToothSlice, PittedSectionMatchesBruteForceStripIntegration) {
  // Brute force: sum thin strips across the thickness xi in [-hx, hx]; the
  // strip width is b, or b - ws inside the pit xi in [hx - hs, hx].
  const double hx = 0.012, b = 0.1;
  for (const auto& [ws, hs] : {std::array<double, 2>{0.005, 0.002}, std::array<double, 2>{0.05, 0.01},
                               std::array<double, 2>{0.1, 0.02}}) {
    const int n = 20000;
    double A = 0, S = 0, J = 0;  // area, first and second moment about the centre line
    // A strip that straddles the pit edge is cut in two at the edge.
    auto add = [&](double x0, double x1, double width) {
      if (!(x1 > x0)) return;
      const double d = x1 - x0, xm = 0.5 * (x0 + x1);
      A += width * d;
      S += width * xm * d;
      J += width * (xm * xm * d + d * d * d / 12);
    };
    const double edge = hx - hs;
    for (int i = 0; i < n; ++i) {
      const double x0 = -hx + i * 2 * hx / n, x1 = -hx + (i + 1) * 2 * hx / n;
      add(x0, std::min(x1, edge), b);
      add(std::max(x0, edge), x1, b - ws);
    }
    const double e = S / A, I = J - A * e * e;
    const CantileverSection sec = tooth_slice_section(hx, b, ws, hs);
    EXPECT_NEAR(sec.area, A, 1e-9 * A);
    EXPECT_NEAR(sec.centroid_offset, e, 1e-9 * hx);
    EXPECT_NEAR(sec.second_moment, I, 1e-8 * I);
    EXPECT_LT(sec.centroid_offset, 0.0);  // material removed from the loaded (+) side
  }
  // No pit: the rectangle.
  const CantileverSection plain = tooth_slice_section(hx, b);
  EXPECT_DOUBLE_EQ(plain.area, 2 * hx * b);
  EXPECT_DOUBLE_EQ(plain.second_moment, b * std::pow(2 * hx, 3) / 12);
  EXPECT_EQ(plain.centroid_offset, 0.0);
}

}  // namespace
}  // namespace rackopt
