#include "rackopt/fe/edge_loads.hpp"

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

namespace rackopt::fe {

std::vector<NodeLoad> edge_traction_loads(const Mesh2D& mesh, const std::string& set_name,
                                          const std::function<Point2(Point2)>& traction) {
  const std::vector<int>& members = mesh.node_set(set_name);
  const std::set<int> in_set(members.begin(), members.end());
  // A boundary edge belongs to exactly one triangle.
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle6& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) uses[std::minmax(t[k], t[(k + 1) % 3])]++;
  }
  static const double gauss_s[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gauss_w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  std::map<int, Point2> force;
  for (const Triangle6& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], m = t[3 + k], b = t[(k + 1) % 3];
      if (in_set.count(a) == 0 || in_set.count(m) == 0 || in_set.count(b) == 0) continue;
      if (uses[std::minmax(a, b)] != 1) continue;
      const Point2 &pa = mesh.nodes[a], &pm = mesh.nodes[m], &pb = mesh.nodes[b];
      for (int g = 0; g < 3; ++g) {
        const double s = gauss_s[g];
        const double na = 0.5 * s * (s - 1), nb = 0.5 * s * (s + 1), nm = 1 - s * s;
        const double dna = s - 0.5, dnb = s + 0.5, dnm = -2 * s;
        const Point2 x{na * pa.x + nm * pm.x + nb * pb.x, na * pa.y + nm * pm.y + nb * pb.y};
        const double jac = std::hypot(dna * pa.x + dnm * pm.x + dnb * pb.x, dna * pa.y + dnm * pm.y + dnb * pb.y);
        const Point2 tr = traction(x);
        const double w = gauss_w[g] * jac;
        for (const auto& [node, shape] : {std::pair{a, na}, std::pair{m, nm}, std::pair{b, nb}}) {
          force[node].x += w * shape * tr.x;
          force[node].y += w * shape * tr.y;
        }
      }
    }
  }
  if (force.empty()) throw std::invalid_argument("node set " + set_name + " holds no boundary edge to load");
  std::vector<NodeLoad> loads;
  for (const auto& [node, f] : force) loads.push_back({node, f.x, f.y});
  return loads;
}

}  // namespace rackopt::fe
