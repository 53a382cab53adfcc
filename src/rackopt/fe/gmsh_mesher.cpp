#include "rackopt/fe/gmsh_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "rackopt/fe/gmsh_library.hpp"

namespace rackopt::fe {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

// A Gmsh failure inside a session: its message comes from Gmsh's logger.
struct GmshCallFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The C API with its error codes turned into exceptions carrying Gmsh's own
// last error message, and its arrays copied into vectors (and freed).
class Gmsh {
 private:
  template <class F, class... Args>
  static int invoke(F f, Args... args) {
    int ierr = 0;
    f(args..., &ierr);
    return ierr;
  }
  template <class F, class... Args>
  auto call(const char* what, F f, Args... args) {
    int ierr = 0;
    if constexpr (std::is_void_v<decltype(f(args..., &ierr))>) {
      f(args..., &ierr);
      check(ierr, what);
    } else {
      const auto r = f(args..., &ierr);
      check(ierr, what);
      return r;
    }
  }
  void check(int ierr, const char* what) {
    if (ierr == 0) return;
    std::string why;
    char* e = nullptr;
    int ierr2 = 0;
    a_.logger_get_last_error(&e, &ierr2);
    if (e) {
      why = e;
      a_.free(e);
    }
    throw GmshCallFailed(std::string(what) + (why.empty() ? " failed" : ": " + why));
  }
  template <class T>
  std::vector<T> take(T* p, std::size_t n) {
    std::vector<T> v(p, p + (p ? n : 0));
    if (p) a_.free(p);
    return v;
  }


 public:
  explicit Gmsh(const GmshApi& api) : a_(api) {}

  void initialize() { call("initialize", a_.initialize, 0, nullptr, 0); }
  void finalize() { call("finalize", a_.finalize); }
  void option(const char* name, double value) { call(name, a_.option_set_number, name, value); }
  void add_model(const char* name) { call("model/add", a_.model_add, name); }
  int add_point(double x, double y, double size) { return call("geo/addPoint", a_.geo_add_point, x, y, 0.0, size, -1); }
  int add_line(int from, int to) { return call("geo/addLine", a_.geo_add_line, from, to, -1); }
  int add_curve_loop(std::vector<int> curves) {
    return call("geo/addCurveLoop", a_.geo_add_curve_loop, curves.data(), curves.size(), -1, 0);
  }
  int add_plane_surface(std::vector<int> loops) {
    return call("geo/addPlaneSurface", a_.geo_add_plane_surface, loops.data(), loops.size(), -1);
  }
  void synchronize() { call("geo/synchronize", a_.geo_synchronize); }
  int add_physical_group(int dim, std::vector<int> tags) {
    return call("model/addPhysicalGroup", a_.add_physical_group, dim, tags.data(), tags.size(), -1);
  }
  int add_field(const char* type) { return call("field/add", a_.field_add, type, -1); }
  void field_string(int field, const char* option, const std::string& value) {
    call("field/setString", a_.field_set_string, field, option, value.c_str());
  }
  void field_numbers(int field, const char* option, std::vector<double> values) {
    call("field/setNumbers", a_.field_set_numbers, field, option, values.data(), values.size());
  }
  void background_field(int field) { call("field/setAsBackgroundMesh", a_.field_set_as_background_mesh, field); }
  void generate(int dim) { call("mesh/generate", a_.mesh_generate, dim); }
  // Elements of `type` on entity (2, surface): their tags and their node tags.
  void elements_by_type(int type, int surface, std::vector<std::size_t>& tags, std::vector<std::size_t>& nodes) {
    std::size_t *t = nullptr, *n = nullptr, nt = 0, nn = 0;
    const int ierr = invoke(a_.get_elements_by_type, type, &t, &nt, &n, &nn, surface, std::size_t{0}, std::size_t{1});
    tags = take(t, nt);
    nodes = take(n, nn);
    check(ierr, "mesh/getElementsByType");
  }
  // Every node of the model: tags and x, y, z triples.
  void nodes(std::vector<std::size_t>& tags, std::vector<double>& xyz) {
    std::size_t* t = nullptr;
    double *c = nullptr, *u = nullptr;
    std::size_t nt = 0, nc = 0, nu = 0;
    const int ierr = invoke(a_.get_nodes, &t, &nt, &c, &nc, &u, &nu, -1, -1, 0, 0);
    tags = take(t, nt);
    xyz = take(c, nc);
    take(u, nu);
    check(ierr, "mesh/getNodes");
  }
  std::vector<std::size_t> group_nodes(int dim, int tag) {
    std::size_t* t = nullptr;
    double* c = nullptr;
    std::size_t nt = 0, nc = 0;
    const int ierr = invoke(a_.get_nodes_for_physical_group, dim, tag, &t, &nt, &c, &nc);
    std::vector<std::size_t> tags = take(t, nt);
    take(c, nc);
    check(ierr, "mesh/getNodesForPhysicalGroup");
    return tags;
  }

  const GmshApi& a_;
};

// Initializes Gmsh quietly and finalizes it on every way out.
class GmshSession {
 public:
  explicit GmshSession(Gmsh& g) : g_(g) {
    g_.initialize();  // no gmshrc (readConfigFiles 0): the result must not depend on the user's files
    try {
      g_.option("General.Terminal", 0);
      g_.option("General.Verbosity", 1);
      g_.option("General.NumThreads", 1);
      g_.add_model("rackopt_fe");
    } catch (...) {
      finish();
      throw;
    }
  }
  ~GmshSession() { finish(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  void finish() noexcept {
    try {
      g_.finalize();
    } catch (...) {  // nothing to do about a failed finalize on the way out
    }
  }
  Gmsh& g_;
};

constexpr int kTriangle6 = 9;  // Gmsh's element type number of the 6-node triangle

// Full precision: std::to_string's 6 decimals would turn 1e-7 m into 0.
std::string num(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

Mesh2D mesh_in_session(Gmsh& g, const Polygon2D& outer, const std::vector<Polygon2D>& holes, double target_size,
                       const std::vector<Refinement>& refinements) {
  // Physical groups carry the set names: one per name, of edges or vertices.
  std::map<std::string, std::vector<int>> edge_groups, vertex_groups;
  std::vector<int> loops;
  const auto add_loop = [&](const Polygon2D& polygon) {
    const std::size_t n = polygon.vertices.size();
    std::vector<int> points, lines;
    for (const Point2& v : polygon.vertices) points.push_back(g.add_point(v.x, v.y, target_size));
    for (std::size_t i = 0; i < n; ++i) lines.push_back(g.add_line(points[i], points[(i + 1) % n]));
    loops.push_back(g.add_curve_loop(lines));
    for (std::size_t i = 0; i < n && i < polygon.edge_names.size(); ++i) {
      if (!polygon.edge_names[i].empty()) edge_groups[polygon.edge_names[i]].push_back(lines[i]);
    }
    for (std::size_t i = 0; i < n && i < polygon.vertex_names.size(); ++i) {
      if (!polygon.vertex_names[i].empty()) vertex_groups[polygon.vertex_names[i]].push_back(points[i]);
    }
  };
  add_loop(outer);
  for (const Polygon2D& hole : holes) add_loop(hole);
  const int surface = g.add_plane_surface(loops);
  g.synchronize();
  std::map<std::string, std::pair<int, int>> groups;  // name -> (dim, tag)
  for (const auto& [name, tags] : edge_groups) groups[name] = {1, g.add_physical_group(1, tags)};
  for (const auto& [name, tags] : vertex_groups) {
    if (groups.count(name) != 0) throw std::invalid_argument("node set '" + name + "' names both an edge and a vertex");
    groups[name] = {0, g.add_physical_group(0, tags)};
  }
  g.add_physical_group(2, {surface});

  // Size field: the target everywhere, the minimum with each refinement disc.
  if (!refinements.empty()) {
    std::vector<double> fields;
    const int base = g.add_field("MathEval");
    g.field_string(base, "F", num(target_size));
    fields.push_back(base);
    for (const Refinement& r : refinements) {
      const int f = g.add_field("MathEval");
      // size + (target - size) * clamp((distance - radius) / radius, 0, 1)
      const std::string d = "Sqrt((x-(" + num(r.center.x) + "))^2+(y-(" + num(r.center.y) + "))^2)";
      const std::string s = num(r.size), t = num(target_size), rad = num(r.radius);
      g.field_string(
          f, "F", s + "+(" + t + "-" + s + ")*Min(1,Max(0,(" + d + "-" + rad + ")/" + rad + "))");
      fields.push_back(f);
    }
    const int m = g.add_field("Min");
    g.field_numbers(m, "FieldsList", fields);
    g.background_field(m);
    g.option("Mesh.MeshSizeFromPoints", 0);
    g.option("Mesh.MeshSizeExtendFromBoundary", 0);
  }
  g.option("Mesh.MeshSizeFromCurvature", 0);
  // The interior takes the target size, not sizes spread in from the boundary:
  // an outline of many short chords (a gear's fillets and flanks) would
  // otherwise fill the whole body with elements as small as its shortest chord.
  g.option("Mesh.MeshSizeExtendFromBoundary", 0);
  g.option("Mesh.MeshSizeMax", target_size);
  g.option("Mesh.Algorithm", 6);  // Frontal-Delaunay: well-shaped triangles
  g.option("Mesh.ElementOrder", 2);
  g.option("Mesh.SecondOrderLinear", 1);  // mid-side nodes on straight chords
  g.generate(2);

  std::vector<std::size_t> element_tags, element_nodes;
  g.elements_by_type(kTriangle6, surface, element_tags, element_nodes);
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;
  g.nodes(node_tags, coords);
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
    const std::vector<std::size_t> tags = g.group_nodes(group.first, group.second);
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
  Gmsh g(gmsh_api());  // GmshNotFound when the library is missing
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  try {
    const GmshSession session(g);
    Mesh2D mesh = mesh_in_session(g, outer, holes, target_size, refinements);
    if (mesh.triangles.empty()) throw std::runtime_error("Gmsh made no triangles");
    return mesh;
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("Gmsh failed to mesh the polygon: ") + e.what());
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
