#include "rackopt/fe/hertz_patch.hpp"

#include <cmath>
#include <stdexcept>

#include "rackopt/fe/edge_loads.hpp"

namespace rackopt::fe {

double hertz_half_width(double force_per_width, double relative_radius, double effective_modulus) {
  if (!(force_per_width > 0) || !(relative_radius > 0) || !(effective_modulus > 0)) {
    throw std::invalid_argument("hertz_half_width: force, radius and modulus must be positive");
  }
  return std::sqrt(4 * force_per_width * relative_radius / (M_PI * effective_modulus));
}

std::vector<NodeLoad> hertz_patch_loads(const Mesh2D& mesh, const std::string& set, Point2 centre, Point2 direction,
                                        double half_width, double force) {
  if (!(half_width > 0)) throw std::invalid_argument("hertz_patch_loads: the half-width must be positive");
  const double norm = std::hypot(direction.x, direction.y);
  const Point2 n{direction.x / norm, direction.y / norm};
  std::vector<NodeLoad> loads = edge_traction_loads(mesh, set, [&](Point2 p) {
    const double d2 = ((p.x - centre.x) * (p.x - centre.x) + (p.y - centre.y) * (p.y - centre.y)) / (half_width * half_width);
    const double pressure = d2 < 1 ? std::sqrt(1 - d2) : 0.0;  // p0 drops out in the scaling
    return Point2{pressure * n.x, pressure * n.y};
  });
  double resultant = 0;
  for (const NodeLoad& l : loads) resultant += l.fx * n.x + l.fy * n.y;
  if (!(resultant > 0)) {
    throw std::invalid_argument("hertz_patch_loads: no edge of node set " + set + " lies within the patch");
  }
  std::vector<NodeLoad> out;
  for (const NodeLoad& l : loads) {
    if (l.fx != 0 || l.fy != 0) out.push_back({l.node, l.fx * force / resultant, l.fy * force / resultant});
  }
  return out;
}

}  // namespace rackopt::fe
