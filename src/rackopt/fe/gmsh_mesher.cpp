#include "rackopt/fe/gmsh_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <gmsh.h>

namespace rackopt::fe {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

// Initializes Gmsh quietly and finalizes it on every way out.
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);  // no gmshrc: the result must not depend on the user's files
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("rackopt_fe");
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

constexpr int kTriangle6 = 9;  // Gmsh's element type number of the 6-node triangle

// Full precision: std::to_string's 6 decimals would turn 1e-7 m into 0.
std::string num(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

std::string last_gmsh_error() {
  std::string e;
  try {
    gmsh::logger::getLastError(e);
  } catch (...) {
  }
  return e;
}

Mesh2D mesh_in_session(const Polygon2D& outer, const std::vector<Polygon2D>& holes, double target_size,
                       const std::vector<Refinement>& refinements) {
  // Physical groups carry the set names: one per name, of edges or vertices.
  std::map<std::string, std::vector<int>> edge_groups, vertex_groups;
  std::vector<int> loops;
  const auto add_loop = [&](const Polygon2D& polygon) {
    const std::size_t n = polygon.vertices.size();
    std::vector<int> points, lines;
    for (const Point2& v : polygon.vertices) points.push_back(gmsh::model::geo::addPoint(v.x, v.y, 0, target_size));
    for (std::size_t i = 0; i < n; ++i) lines.push_back(gmsh::model::geo::addLine(points[i], points[(i + 1) % n]));
    loops.push_back(gmsh::model::geo::addCurveLoop(lines));
    for (std::size_t i = 0; i < n && i < polygon.edge_names.size(); ++i) {
      if (!polygon.edge_names[i].empty()) edge_groups[polygon.edge_names[i]].push_back(lines[i]);
    }
    for (std::size_t i = 0; i < n && i < polygon.vertex_names.size(); ++i) {
      if (!polygon.vertex_names[i].empty()) vertex_groups[polygon.vertex_names[i]].push_back(points[i]);
    }
  };
  add_loop(outer);
  for (const Polygon2D& hole : holes) add_loop(hole);
  const int surface = gmsh::model::geo::addPlaneSurface(loops);
  gmsh::model::geo::synchronize();
  std::map<std::string, std::pair<int, int>> groups;  // name -> (dim, tag)
  for (const auto& [name, tags] : edge_groups) groups[name] = {1, gmsh::model::addPhysicalGroup(1, tags)};
  for (const auto& [name, tags] : vertex_groups) {
    if (groups.count(name) != 0) throw std::invalid_argument("node set '" + name + "' names both an edge and a vertex");
    groups[name] = {0, gmsh::model::addPhysicalGroup(0, tags)};
  }
  gmsh::model::addPhysicalGroup(2, {surface});

  // Size field: the target everywhere, the minimum with each refinement disc.
  if (!refinements.empty()) {
    std::vector<double> fields;
    const int base = gmsh::model::mesh::field::add("MathEval");
    gmsh::model::mesh::field::setString(base, "F", num(target_size));
    fields.push_back(base);
    for (const Refinement& r : refinements) {
      const int f = gmsh::model::mesh::field::add("MathEval");
      // size + (target - size) * clamp((distance - radius) / radius, 0, 1)
      const std::string d = "Sqrt((x-(" + num(r.center.x) + "))^2+(y-(" + num(r.center.y) + "))^2)";
      const std::string s = num(r.size), t = num(target_size), rad = num(r.radius);
      gmsh::model::mesh::field::setString(
          f, "F", s + "+(" + t + "-" + s + ")*Min(1,Max(0,(" + d + "-" + rad + ")/" + rad + "))");
      fields.push_back(f);
    }
    const int m = gmsh::model::mesh::field::add("Min");
    gmsh::model::mesh::field::setNumbers(m, "FieldsList", fields);
    gmsh::model::mesh::field::setAsBackgroundMesh(m);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  }
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  // The interior takes the target size, not sizes spread in from the boundary:
  // an outline of many short chords (a gear's fillets and flanks) would
  // otherwise fill the whole body with elements as small as its shortest chord.
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", target_size);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay: well-shaped triangles
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::option::setNumber("Mesh.SecondOrderLinear", 1);  // mid-side nodes on straight chords
  gmsh::model::mesh::generate(2);

  std::vector<std::size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(kTriangle6, element_tags, element_nodes, surface);
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, Point2> where;
  for (std::size_t i = 0; i < node_tags.size(); ++i) where[node_tags[i]] = {coords[3 * i], coords[3 * i + 1]};

  Mesh2D mesh;
  std::unordered_map<std::size_t, int> index;  // Gmsh node tag -> our node index, in first-use order
  const auto node_index = [&](std::size_t tag) {
    const auto [it, added] = index.emplace(tag, static_cast<int>(mesh.nodes.size()));
    if (added) mesh.nodes.push_back(where.at(tag));
    return it->second;
  };
  for (std::size_t e = 0; e < element_tags.size(); ++e) {
    Triangle6 t{};
    for (int k = 0; k < 6; ++k) t[k] = node_index(element_nodes[6 * e + k]);
    const Point2 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]];
    if ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y) < 0) t = {t[0], t[2], t[1], t[5], t[4], t[3]};
    mesh.triangles.push_back(t);
  }
  for (const auto& [name, group] : groups) {
    std::vector<std::size_t> tags;
    std::vector<double> xyz;
    gmsh::model::mesh::getNodesForPhysicalGroup(group.first, group.second, tags, xyz);
    std::vector<int>& set = mesh.node_sets[name];
    for (std::size_t tag : tags) {
      const auto it = index.find(tag);
      if (it != index.end()) set.push_back(it->second);
    }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  return mesh;
}

}  // namespace

Mesh2D mesh_polygon(const Polygon2D& polygon, double target_size, const std::vector<Refinement>& refinements) {
  return mesh_polygon_with_holes(polygon, {}, target_size, refinements);
}

Mesh2D mesh_polygon_with_holes(const Polygon2D& outer, const std::vector<Polygon2D>& holes, double target_size,
                               const std::vector<Refinement>& refinements) {
  if (!(target_size > 0) || !std::isfinite(target_size)) {
    throw std::invalid_argument("mesh_polygon: the target element size must be positive");
  }
  for (const Refinement& r : refinements) {
    if (!(r.size > 0) || !(r.radius > 0)) throw std::invalid_argument("mesh_polygon: a refinement needs a positive size and radius");
  }
  std::vector<const Polygon2D*> all{&outer};
  for (const Polygon2D& hole : holes) all.push_back(&hole);
  for (const Polygon2D* polygon : all) {
    if (polygon->vertices.size() < 3) throw std::invalid_argument("mesh_polygon: a polygon needs at least 3 vertices");
    for (const auto* names : {&polygon->edge_names, &polygon->vertex_names}) {
      for (const std::string& name : *names) {
        if (!name.empty()) check_set_name(name);
      }
    }
  }
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  try {
    const GmshSession session;
    Mesh2D mesh = mesh_in_session(outer, holes, target_size, refinements);
    if (mesh.triangles.empty()) throw std::runtime_error("Gmsh made no triangles");
    return mesh;
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("Gmsh failed to mesh the polygon: ") + e.what());
  } catch (...) {  // Gmsh 4.8 may throw a bare string or int
    const std::string why = last_gmsh_error();
    throw std::runtime_error("Gmsh failed to mesh the polygon" + (why.empty() ? std::string() : ": " + why));
  }
}

Mesh2D mesh_rectangle(double x0, double y0, double length, double height, double target_size,
                      const std::vector<Refinement>& refinements) {
  if (!(length > 0) || !(height > 0)) throw std::invalid_argument("mesh_rectangle: length and height must be positive");
  Polygon2D p;
  p.vertices = {{x0, y0}, {x0 + length, y0}, {x0 + length, y0 + height}, {x0, y0 + height}};
  p.edge_names = {"BOTTOM", "RIGHT", "TOP", "LEFT"};
  p.vertex_names = {"BOTTOM_LEFT", "BOTTOM_RIGHT", "TOP_RIGHT", "TOP_LEFT"};
  return mesh_polygon(p, target_size, refinements);
}

}  // namespace rackopt::fe
