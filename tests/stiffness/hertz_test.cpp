// Hertzian contact compliance (docs/models/tooth.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/hertz.hpp"

namespace rackopt {
namespace {

Material steel(double E, double nu) {
  Material m;
  m.name = "steel";
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  return m;
}

TEST(Hertz, LinearStiffnessRailwayPaper) {
  // docs/models/tooth.md: k_h = pi E b/(4(1 - nu^2)) = 10.87 GN/m for b = 60 mm,
  // E = 210 GPa, nu = 0.3 (the rack railway paper).
  const Material s = steel(210e9, 0.3);
  const double k = 1.0 / hertz_linear_compliance(effective_modulus(s, s), 0.060);
  EXPECT_NEAR(k, 10.87e9, 0.005e9);
  EXPECT_NEAR(k, std::numbers::pi * 210e9 * 0.06 / (4 * (1 - 0.09)), 1e-6 * k);
}

TEST(Hertz, EffectiveModulusWearPaper) {
  // docs/models/tooth.md: E1 = 209, E2 = 202 GPa, nu = 0.271 / 0.3 -> E* = 111.9 GPa.
  EXPECT_NEAR(effective_modulus(steel(209e9, 0.271), steel(202e9, 0.3)), 111.9e9, 0.05e9);
  EXPECT_THROW(effective_modulus(steel(0, 0.3), steel(202e9, 0.3)), InputError);
  EXPECT_THROW(hertz_linear_compliance(111.9e9, 0.0), InputError);
}

TEST(Hertz, WeberBanaschekMatchesTheSameMaterialFormula) {
  // docs/models/tooth.md (same material): delta = 2F(1-nu^2)/(pi E b)[ln(2h1/a) +
  // ln(2h2/a) - nu/(1-nu)], a = sqrt(4 F R'/(pi b E*)), E* = E/(2(1-nu^2)).
  const double E = 210e9, nu = 0.3, b = 0.06, F = 2e5, R = 0.085, h1 = 0.025, h2 = 0.03;
  const double e_star = E / (2 * (1 - nu * nu));
  const double a = std::sqrt(4 * F * R / (std::numbers::pi * b * e_star));
  const double delta = 2 * F * (1 - nu * nu) / (std::numbers::pi * E * b) *
                       (std::log(2 * h1 / a) + std::log(2 * h2 / a) - nu / (1 - nu));
  const Material s = steel(E, nu);
  EXPECT_NEAR(hertz_weber_banaschek_compliance(s, s, b, F, R, h1, h2, ElasticPlane::kStrain), delta / F,
              1e-12 * delta / F);
}

TEST(Hertz, WeberBanaschekPlaneStressIsThePlaneStrainLawWithTheEquivalentConstants) {
  // A plane-strain solution turns into the plane-stress one under
  // E -> E (1 + 2 nu)/(1 + nu)^2, nu -> nu/(1 + nu): the two forms must agree
  // under that substitution, and plane stress (no lateral support) must be
  // the more compliant of the two at the same E and nu.
  const double E = 210e9, nu = 0.3, b = 0.05, F = 4e4, R = 0.05, h1 = 0.012, h2 = 0.015;
  const Material s = steel(E, nu);
  const Material equiv = steel(E * (1 + 2 * nu) / ((1 + nu) * (1 + nu)), nu / (1 + nu));
  const double stress = hertz_weber_banaschek_compliance(s, s, b, F, R, h1, h2, ElasticPlane::kStress);
  EXPECT_NEAR(hertz_weber_banaschek_compliance(equiv, equiv, b, F, R, h1, h2, ElasticPlane::kStrain), stress,
              1e-12 * stress);
  EXPECT_GT(stress, hertz_weber_banaschek_compliance(s, s, b, F, R, h1, h2, ElasticPlane::kStrain));
  // Closed form of the plane-stress law, equal materials: E* = E/2.
  const double a = std::sqrt(4 * F * R / (std::numbers::pi * b * E / 2));
  const double delta = F / (std::numbers::pi * b * E) * (2 * std::log(2 * h1 / a) + 2 * std::log(2 * h2 / a) - 2 * nu);
  EXPECT_NEAR(stress, delta / F, 1e-12 * delta / F);
  // The secant falls with the force as ln F: doubling F takes 2 ln 2 /(pi b E)... per body, halved by the sqrt.
  const double twice = hertz_weber_banaschek_compliance(s, s, b, 2 * F, R, h1, h2);
  EXPECT_NEAR(stress - twice, 2 * std::log(2.0) / (std::numbers::pi * b * E), 1e-9 * stress);
}

TEST(Hertz, WeberBanaschekProperties) {
  const Material s = steel(210e9, 0.3);
  const double b = 0.06;
  const double c = hertz_weber_banaschek_compliance(s, s, b, 1e5, 0.1, 0.02, 0.02);
  EXPECT_TRUE(std::isfinite(c));
  EXPECT_GT(c, 0.0);
  // Stiffer (smaller compliance) for a larger effective radius (wider contact).
  EXPECT_LT(hertz_weber_banaschek_compliance(s, s, b, 1e5, 0.3, 0.02, 0.02), c);
  // Secant compliance falls with load (log law): stiffening contact.
  EXPECT_LT(hertz_weber_banaschek_compliance(s, s, b, 1e6, 0.1, 0.02, 0.02), c);
  // Tiny and zero loads stay finite; zero equals the documented floor (1 N/m x b).
  const double tiny = hertz_weber_banaschek_compliance(s, s, b, 1e-12, 0.1, 0.02, 0.02);
  const double zero = hertz_weber_banaschek_compliance(s, s, b, 0.0, 0.1, 0.02, 0.02);
  EXPECT_TRUE(std::isfinite(tiny));
  EXPECT_TRUE(std::isfinite(zero));
  EXPECT_EQ(tiny, zero);
  EXPECT_EQ(zero, hertz_weber_banaschek_compliance(s, s, b, 1.0 * b, 0.1, 0.02, 0.02));
  // Same order as the linear law at a working load (docs/models/tooth.md: Hertz share ~10%).
  const double lin = hertz_linear_compliance(effective_modulus(s, s), b);
  EXPECT_GT(c / lin, 0.3);
  EXPECT_LT(c / lin, 10.0);
  EXPECT_THROW(hertz_weber_banaschek_compliance(s, s, b, 1e5, 0.0, 0.02, 0.02), InputError);
  EXPECT_THROW(hertz_weber_banaschek_compliance(s, s, b, 1e5, 0.1, 0.0, 0.02), InputError);
  // Absurd load: contact half-width beyond the tooth: out of model, not NaN.
  EXPECT_THROW(hertz_weber_banaschek_compliance(s, s, b, 1e12, 0.5, 0.001, 0.001), DesignError);
}

}  // namespace
}  // namespace rackopt
