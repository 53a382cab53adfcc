#include "rackopt/fe/mesh2d.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

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

namespace {

// The six quadratic shape functions at barycentric coordinates l (node order of Triangle6).
std::array<double, 6> quadratic_shapes(const std::array<double, 3>& l) {
  return {l[0] * (2 * l[0] - 1), l[1] * (2 * l[1] - 1), l[2] * (2 * l[2] - 1),
          4 * l[0] * l[1],       4 * l[1] * l[2],       4 * l[2] * l[0]};
}

}  // namespace

MeshLocation Mesh2D::locate(Point2 p) const {
  // The triangle whose smallest barycentric coordinate is largest: the one
  // holding p, or for a point on a shared edge either of the two.
  MeshLocation best;
  double best_min = -std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const Triangle6& t = triangles[e];
    const Point2 &a = nodes[t[0]], &b = nodes[t[1]], &c = nodes[t[2]];
    const double twice_area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (twice_area == 0) continue;
    const double l1 = ((c.x - b.x) * (p.y - b.y) - (p.x - b.x) * (c.y - b.y)) / twice_area;
    const double l2 = ((a.x - c.x) * (p.y - c.y) - (p.x - c.x) * (a.y - c.y)) / twice_area;
    const std::array<double, 3> l{l1, l2, 1 - l1 - l2};
    const double smallest = std::min({l[0], l[1], l[2]});
    if (smallest > best_min) {
      best_min = smallest;
      best = {static_cast<int>(e), l};
      if (smallest >= 0) break;
    }
  }
  if (best.triangle < 0 || best_min < -1e-9) {
    std::ostringstream s;
    s << "point (" << p.x * 1e3 << ", " << p.y * 1e3 << ") mm is outside the mesh";
    throw std::out_of_range(s.str());
  }
  return best;
}

Point2 Mesh2D::interpolate(const std::vector<Point2>& field, Point2 p) const {
  if (field.size() != nodes.size()) {
    throw std::invalid_argument("interpolate: the field has " + std::to_string(field.size()) + " values, the mesh " +
                                std::to_string(nodes.size()) + " nodes");
  }
  const MeshLocation at = locate(p);
  const std::array<double, 6> n = quadratic_shapes(at.barycentric);
  Point2 v;
  for (int k = 0; k < 6; ++k) {
    v.x += n[k] * field[triangles[at.triangle][k]].x;
    v.y += n[k] * field[triangles[at.triangle][k]].y;
  }
  return v;
}

double Mesh2D::interpolate(const std::vector<double>& field, Point2 p) const {
  std::vector<Point2> as_points(field.size());
  for (std::size_t i = 0; i < field.size(); ++i) as_points[i].x = field[i];
  return interpolate(as_points, p).x;
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
