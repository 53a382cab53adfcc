// Distributed loads turned into the consistent nodal forces of quadratic
// edges. A point load on a 2-D continuum has a logarithmically infinite
// displacement under it, so the FE reference loads surfaces by tractions
// (or spreads a load over a patch) and reads displacements where they are
// finite.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

// Consistent nodal forces (N per metre of thickness) of the traction
// `traction`(x, y) (Pa: force per unit area of the boundary, the body's unit
// thickness times edge length) on every boundary edge of `mesh` whose three
// nodes all belong to node set `set`: f_i = integral of N_i t ds over the
// edge, by 3-point Gauss (exact for a traction up to cubic along a straight
// edge). One entry per node that gets a force. Throws std::invalid_argument
// when the set has no boundary edge.
std::vector<NodeLoad> edge_traction_loads(const Mesh2D& mesh, const std::string& set,
                                          const std::function<Point2(Point2)>& traction);

}  // namespace rackopt::fe
