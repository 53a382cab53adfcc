// A contact force spread over its Hertz patch instead of a point: on a 2-D
// continuum a point load has a logarithmically infinite displacement under
// it, a Hertz pressure a finite one. Used by the FE single-tooth solves.
#pragma once

#include <string>
#include <vector>

#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

// Half-width of the 2-D Hertz contact of a cylinder of radius R on a flat
// (or two cylinders of relative radius R) under F' (N per metre of contact
// length): b_H = sqrt(4 F' R / (pi E*)), 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
// Throws std::invalid_argument for a non-positive argument.
double hertz_half_width(double force_per_width, double relative_radius, double effective_modulus);

// Consistent nodal forces of the elliptic pressure p(d) = p0 sqrt(1 - d^2/b^2)
// (d: distance from `centre`, b = half_width) acting along the unit vector
// `direction` on the boundary edges of node set `set` (edge_loads.hpp),
// scaled so that their resultant along `direction` is exactly `force`
// (N/m): the 3-point Gauss rule of edge_traction_loads is not exact for the
// square root, and the scaling keeps the load what the caller asked. The
// mesh should have several elements across 2 b. Throws
// std::invalid_argument when the patch catches no load (no edge of the set
// within b of the centre) or for a non-positive half-width.
std::vector<NodeLoad> hertz_patch_loads(const Mesh2D& mesh, const std::string& set, Point2 centre, Point2 direction,
                                        double half_width, double force);

}  // namespace rackopt::fe
