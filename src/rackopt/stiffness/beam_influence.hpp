// Textbook influence functions of a prismatic beam on two hinges at x = 0 and
// x = l (simply supported: v(0) = v(l) = 0, no end moments). Building blocks
// of the rack body model (rack_span.hpp); docs/models/rack_span.md
// has the derivations.
//
// Sign convention: x along the beam, v up, u along +x, rotations and couples
// counterclockwise (+z). "Rotation" is the rotation psi of the cross-section;
// in Euler-Bernoulli theory psi = dv/dx, in Timoshenko theory it is not.
//
// Each function returns the response for unit stiffness, so callers multiply
// by the matching flexibility:
//   bending_*  -> times 1/(E I)          (Euler-Bernoulli)
//   shear_*    -> times 1/(kappa G A)    (Timoshenko shear correction)
//   axial_*    -> times 1/(E A)
// x is where the response is read, xi where the unit load acts; both must lie
// in [0, l] and l > 0 (not checked here: these are hot-path helpers, the
// callers validate; defined here so that the rack body's influence
// coefficients, several per curve sample, inline them). All are continuous
// in x and xi, and the pairs obey Maxwell-Betti: bending_deflection_per_couple(x, xi) ==
// bending_rotation_per_force(xi, x) analytically.
#pragma once

#include <algorithm>

namespace rackopt::hinged_beam {

// E I * v(x) for a unit upward force at xi (Roark / Gere: P b x (l^2 - b^2 - x^2) / (6 E I l)
// for x <= xi, b = l - xi; symmetric in (x, xi)).
inline double bending_deflection_per_force(double x, double xi, double l) {
  // Written with (lo, hi) so the result is bitwise symmetric in (x, xi).
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) * (2.0 * l * hi - hi * hi - lo * lo) / (6.0 * l);
}

// E I * v(x) for a unit counterclockwise couple at xi.
inline double bending_deflection_per_couple(double x, double xi, double l) {
  // d/dxi of the force case (a couple is the limit of a force dipole).
  if (x <= xi) return x * (x * x + 3.0 * xi * xi - 6.0 * l * xi + 2.0 * l * l) / (6.0 * l);
  return (l - x) * (2.0 * l * x - x * x - 3.0 * xi * xi) / (6.0 * l);
}

// E I * psi(x) for a unit upward force at xi (= dv/dx of the force case).
inline double bending_rotation_per_force(double x, double xi, double l) {
  // d/dx of the force case.
  if (x <= xi) return (l - xi) * (2.0 * l * xi - xi * xi - 3.0 * x * x) / (6.0 * l);
  return xi * (3.0 * x * x + xi * xi - 6.0 * l * x + 2.0 * l * l) / (6.0 * l);
}

// E I * psi(x) for a unit counterclockwise couple at xi:
// (3 x^2 + 3 xi^2 - 6 l max(x, xi) + 2 l^2) / (6 l); symmetric.
inline double bending_rotation_per_couple(double x, double xi, double l) {
  const double hi = std::max(x, xi);
  return (3.0 * x * x + 3.0 * xi * xi - 6.0 * l * hi + 2.0 * l * l) / (6.0 * l);
}

// kappa G A * v(x) for a unit upward force at xi: the shear strain V/(kappa G A)
// integrated from the left hinge, min(x,xi) (l - max(x,xi)) / l. The shear
// force of a single force integrates to zero over the span, so the section
// rotation is unchanged (the matching rotation-per-force shear term is 0).
inline double shear_deflection_per_force(double x, double xi, double l) {
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) / l;
}

// kappa G A * psi(x) for a unit counterclockwise couple anywhere on the span:
// 1 / l at every x. A couple M is balanced by the hinge reactions -/+ M/l, so
// the shear force is M/l everywhere; the shear strain M/(l kappa G A) would
// lift the right hinge, so a rigid rotation by the same amount brings it back:
// v is unchanged (deflection-per-couple shear term is 0) and every section
// rotates by 1/(l kappa G A) per unit couple.
inline double shear_rotation_per_couple(double l) {
  return 1.0 / l;
}

// E A * u(x) for a unit force along +x at xi when both hinges fix u (pin-pin,
// statically indeterminate axially): min(x,xi) (l - max(x,xi)) / l.
inline double axial_displacement_pin_pin(double x, double xi, double l) {
  const double lo = std::min(x, xi);
  const double hi = std::max(x, xi);
  return lo * (l - hi) / l;
}

// E A * u(x) for a unit force along +x at xi when only the left hinge fixes u
// (pin-roller): min(x, xi).
inline double axial_displacement_pin_roller(double x, double xi) {
  return std::min(x, xi);
}

}  // namespace rackopt::hinged_beam
