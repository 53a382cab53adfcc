// Influence functions of a simply supported prismatic beam; derivations in
// docs/models/rack_span.md ("Influence functions").
#include "rackopt/stiffness/beam_influence.hpp"

#include <algorithm>

namespace rackopt::hinged_beam {

double bending_deflection_per_force(double x, double xi, double l) {
  // Written with (lo, hi) so the result is bitwise symmetric in (x, xi).
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) * (2.0 * l * hi - hi * hi - lo * lo) / (6.0 * l);
}

double bending_deflection_per_couple(double x, double xi, double l) {
  // d/dxi of the force case (a couple is the limit of a force dipole).
  if (x <= xi) return x * (x * x + 3.0 * xi * xi - 6.0 * l * xi + 2.0 * l * l) / (6.0 * l);
  return (l - x) * (2.0 * l * x - x * x - 3.0 * xi * xi) / (6.0 * l);
}

double bending_rotation_per_force(double x, double xi, double l) {
  // d/dx of the force case.
  if (x <= xi) return (l - xi) * (2.0 * l * xi - xi * xi - 3.0 * x * x) / (6.0 * l);
  return xi * (3.0 * x * x + xi * xi - 6.0 * l * x + 2.0 * l * l) / (6.0 * l);
}

double bending_rotation_per_couple(double x, double xi, double l) {
  const double hi = std::max(x, xi);
  return (3.0 * x * x + 3.0 * xi * xi - 6.0 * l * hi + 2.0 * l * l) / (6.0 * l);
}

double shear_deflection_per_force(double x, double xi, double l) {
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) / l;
}

double shear_rotation_per_couple(double l) { return 1.0 / l; }

double axial_displacement_pin_pin(double x, double xi, double l) {
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) / l;
}

double axial_displacement_pin_roller(double x, double xi) { return std::min(x, xi); }

}  // namespace rackopt::hinged_beam
