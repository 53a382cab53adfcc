#include "rackopt/fe/mesh2d.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rackopt::fe {

const std::vector<int>& Mesh2D::node_set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it == node_sets.end()) {
    std::string known;
    for (const auto& [n, s] : node_sets) known += (known.empty() ? "" : ", ") + n;
    throw std::out_of_range("mesh has no node set '" + name + "' (it has: " + (known.empty() ? "none" : known) + ")");
  }
  return it->second;
}

int Mesh2D::nearest_node(Point2 p) const {
  if (nodes.empty()) throw std::out_of_range("nearest_node: the mesh has no nodes");
  int best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double dx = nodes[i].x - p.x, dy = nodes[i].y - p.y;
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best_d2 = d2;
      best = static_cast<int>(i);
    }
  }
  return best;
}

double Mesh2D::area() const {
  double a = 0;
  for (const Triangle6& t : triangles) {
    const Point2 &p0 = nodes[t[0]], &p1 = nodes[t[1]], &p2 = nodes[t[2]];
    a += 0.5 * ((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y));
  }
  return a;
}

double Mesh2D::largest_edge() const {
  double h = 0;
  for (const Triangle6& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const Point2 &a = nodes[t[k]], &b = nodes[t[(k + 1) % 3]];
      h = std::max(h, std::hypot(b.x - a.x, b.y - a.y));
    }
  }
  return h;
}

void check_set_name(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 60 && std::isalpha(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) {
    throw std::invalid_argument("node set name '" + name +
                                "' is not allowed: a letter, then letters, digits or '_', at most 60 characters");
  }
}

}  // namespace rackopt::fe
