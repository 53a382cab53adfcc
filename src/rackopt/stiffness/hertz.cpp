#include "rackopt/stiffness/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

void check_material(const Material& m) {
  if (!(m.youngs_modulus > 0.0) || !std::isfinite(m.youngs_modulus)) {
    throw InputError({}, "material.youngs_modulus", "Young's modulus of '" + m.name + "' must be positive");
  }
  if (!(m.poisson_ratio > -1.0 && m.poisson_ratio <= 0.5)) {
    throw InputError({}, "material.poisson_ratio", "Poisson ratio of '" + m.name + "' outside (-1, 0.5]");
  }
}

// Approach of one body's point at distance h [m per N/(pi b)] (Weber & Banaschek).
double body_term(const Material& m, double h, double a, ElasticPlane plane) {
  const double nu = m.poisson_ratio;
  if (plane == ElasticPlane::kStress) return (2.0 * std::log(2.0 * h / a) - nu) / m.youngs_modulus;
  return (1.0 - nu * nu) / m.youngs_modulus * (2.0 * std::log(2.0 * h / a) - nu / (1.0 - nu));
}

}  // namespace

double effective_modulus(const Material& a, const Material& b) {
  check_material(a);
  check_material(b);
  const double inv = (1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                     (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus;
  return 1.0 / inv;
}

double hertz_linear_compliance(double e_star, double face_width) {
  if (!(e_star > 0.0) || !(face_width > 0.0)) {
    throw InputError({}, "face_width", "Hertz compliance needs positive E* and face width");
  }
  return 2.0 / (std::numbers::pi * face_width * e_star);
}

double hertz_weber_banaschek_compliance(const Material& a, const Material& b, double face_width,
                                        double force, double effective_radius, double h1,
                                        double h2, ElasticPlane plane) {
  const double e_star_strain = effective_modulus(a, b);  // also checks both materials
  const double e_star = plane == ElasticPlane::kStrain
                            ? e_star_strain
                            : 1.0 / (1.0 / a.youngs_modulus + 1.0 / b.youngs_modulus);
  if (!(face_width > 0.0) || !(effective_radius > 0.0) || !(h1 > 0.0) || !(h2 > 0.0) ||
      !std::isfinite(force)) {
    throw InputError({}, "hertz",
                     "Weber-Banaschek needs positive face width, effective radius and h1, h2");
  }
  const double f = std::max(force, 1.0 * face_width);  // floor: 1 N/m of face width
  const double half_width =
      std::sqrt(4.0 * f * effective_radius / (std::numbers::pi * face_width * e_star));
  const double bracket = body_term(a, h1, half_width, plane) + body_term(b, h2, half_width, plane);
  if (!(bracket > 0.0)) {
    throw DesignError("hertz_out_of_range",
                      "Weber-Banaschek contact half-width " + std::to_string(half_width * 1e3) +
                          " mm is too large for tooth half-thicknesses " +
                          std::to_string(h1 * 1e3) + " / " + std::to_string(h2 * 1e3) + " mm");
  }
  return bracket / (std::numbers::pi * face_width);
}

}  // namespace rackopt
