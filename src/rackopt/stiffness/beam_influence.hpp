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
// callers validate). All are continuous in x and xi, and the pairs obey
// Maxwell-Betti: bending_deflection_per_couple(x, xi) ==
// bending_rotation_per_force(xi, x) analytically.
#pragma once

namespace rackopt::hinged_beam {

// E I * v(x) for a unit upward force at xi (Roark / Gere: P b x (l^2 - b^2 - x^2) / (6 E I l)
// for x <= xi, b = l - xi; symmetric in (x, xi)).
double bending_deflection_per_force(double x, double xi, double l);

// E I * v(x) for a unit counterclockwise couple at xi.
double bending_deflection_per_couple(double x, double xi, double l);

// E I * psi(x) for a unit upward force at xi (= dv/dx of the force case).
double bending_rotation_per_force(double x, double xi, double l);

// E I * psi(x) for a unit counterclockwise couple at xi:
// (3 x^2 + 3 xi^2 - 6 l max(x, xi) + 2 l^2) / (6 l); symmetric.
double bending_rotation_per_couple(double x, double xi, double l);

// kappa G A * v(x) for a unit upward force at xi: the shear strain V/(kappa G A)
// integrated from the left hinge, min(x,xi) (l - max(x,xi)) / l. The shear
// force of a single force integrates to zero over the span, so the section
// rotation is unchanged (the matching rotation-per-force shear term is 0).
double shear_deflection_per_force(double x, double xi, double l);

// kappa G A * psi(x) for a unit counterclockwise couple anywhere on the span:
// 1 / l at every x. A couple M is balanced by the hinge reactions -/+ M/l, so
// the shear force is M/l everywhere; the shear strain M/(l kappa G A) would
// lift the right hinge, so a rigid rotation by the same amount brings it back:
// v is unchanged (deflection-per-couple shear term is 0) and every section
// rotates by 1/(l kappa G A) per unit couple.
double shear_rotation_per_couple(double l);

// E A * u(x) for a unit force along +x at xi when both hinges fix u (pin-pin,
// statically indeterminate axially): min(x,xi) (l - max(x,xi)) / l.
double axial_displacement_pin_pin(double x, double xi, double l);

// E A * u(x) for a unit force along +x at xi when only the left hinge fixes u
// (pin-roller): min(x, xi).
double axial_displacement_pin_roller(double x, double xi);

}  // namespace rackopt::hinged_beam
