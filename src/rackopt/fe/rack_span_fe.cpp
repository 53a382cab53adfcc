#include "rackopt/fe/rack_span_fe.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rackopt::fe {
namespace {

bool same_point(Point2 a, Point2 b, double tol) { return std::hypot(a.x - b.x, a.y - b.y) <= tol; }

// A polygon under construction: each vertex with the name of the edge that
// leaves it.
struct OutlineBuilder {
  Polygon2D p;
  double tol = 0;
  void add(Point2 v, const std::string& edge, const std::string& vertex = "") {
    if (!p.vertices.empty() && same_point(p.vertices.back(), v, tol)) {
      p.edge_names.back() = edge;  // the same point again: only its edge changes
      if (!vertex.empty()) p.vertex_names.back() = vertex;
      return;
    }
    p.vertices.push_back(v);
    p.edge_names.push_back(edge);
    p.vertex_names.push_back(vertex);
  }
};

// An end face at x from y_from to y_to (either direction) with the hinge
// patch about y_axis: the patch edges named `name`, the axis vertex
// `name`_AXIS. The vertex at y_from is assumed added already.
void end_face(OutlineBuilder& b, double x, double y_from, double y_to, double y_axis, double c,
              const std::string& name) {
  const double dir = y_to > y_from ? 1 : -1;
  b.add({x, y_axis - dir * c}, name);
  b.add({x, y_axis}, name, name + "_AXIS");
  b.add({x, y_axis + dir * c}, "");
  b.add({x, y_to}, "");
}

// The top chain of a rack_segment_outline polygon (vertex 2 to the last:
// from its right end along the teeth to its left end), appended; edge names
// kept or, when `anonymous`, dropped; points closer than `min_spacing` to
// the last kept one skipped (coarse root rounds on the far teeth).
void append_top_chain(OutlineBuilder& b, const Polygon2D& seg, bool anonymous, double min_spacing) {
  const std::size_t n = seg.vertices.size();
  for (std::size_t i = 2; i < n; ++i) {
    const Point2 v = seg.vertices[i];
    const bool last = i + 1 == n;
    if (!last && min_spacing > 0 && !b.p.vertices.empty() && same_point(b.p.vertices.back(), v, min_spacing)) continue;
    b.add(v, anonymous || last ? std::string() : seg.edge_names[i]);
  }
}

Polygon2D shifted(Polygon2D p, double dx) {
  for (Point2& v : p.vertices) v.x += dx;
  return p;
}

}  // namespace

HingeConstraints hinge_constraints(const Mesh2D& mesh, const std::string& patch_set, const std::string& axis_set,
                                   bool hold_x) {
  const std::vector<int>& patch = mesh.node_set(patch_set);
  const std::vector<int>& axis = mesh.node_set(axis_set);
  if (axis.size() != 1) throw std::invalid_argument("hinge " + patch_set + ": the axis set must be one node");
  const int a = axis.front();
  const Point2 pa = mesh.nodes[a];
  int top = -1;
  double y_min = pa.y, y_max = pa.y;
  for (int n : patch) {
    y_min = std::min(y_min, mesh.nodes[n].y);
    y_max = std::max(y_max, mesh.nodes[n].y);
    if (top < 0 || mesh.nodes[n].y > mesh.nodes[top].y) top = n;
  }
  if (top < 0 || !(mesh.nodes[top].y > pa.y)) {
    throw std::invalid_argument("hinge " + patch_set + ": no patch node above the axis node");
  }
  for (int n : patch) {
    if (std::abs(mesh.nodes[n].x - pa.x) > 1e-9 * (y_max - y_min)) {
      throw std::invalid_argument("hinge " + patch_set + ": the patch is not on one vertical line");
    }
  }
  HingeConstraints h;
  std::vector<int> nodes = patch;
  if (std::find(nodes.begin(), nodes.end(), a) == nodes.end()) nodes.push_back(a);
  for (int n : nodes) h.supports.push_back({n, 2, 0.0});
  if (hold_x) h.supports.push_back({a, 1, 0.0});
  const double yt = mesh.nodes[top].y;
  for (int n : nodes) {
    if (n == a || n == top) continue;
    const double w = (mesh.nodes[n].y - pa.y) / (yt - pa.y);
    // u_n - (1 - w) u_A - w u_T = 0: u_n is the dependent one.
    h.equations.push_back(NodeEquation{{{n, 1, 1.0}, {a, 1, -(1 - w)}, {top, 1, -w}}});
  }
  return h;
}

Polygon2D hinged_beam_outline(double length, double depth, double patch_half_height, double load_from,
                              double load_to) {
  const double c = patch_half_height, h = depth / 2;
  if (!(length > 0) || !(depth > 0) || !(c > 0) || !(c < h) || !(0 < load_from && load_from < load_to && load_to < length)) {
    throw std::invalid_argument("hinged_beam_outline: need length, depth > 0, 0 < patch < depth/2, 0 < from < to < length");
  }
  OutlineBuilder b;
  b.tol = 1e-12 * length;
  b.add({0, -h}, "BOTTOM");
  b.add({length, -h}, "");
  end_face(b, length, -h, h, 0, c, "HINGE_R");
  b.p.edge_names.back() = "TOP";
  b.add({load_to, h}, "LOAD");
  b.add({load_from, h}, "TOP");
  b.add({0, h}, "");
  end_face(b, 0, h, -h, 0, c, "HINGE_L");
  // The last end_face vertex is (0, -h) again: the outline closes on the first.
  b.p.vertices.pop_back();
  b.p.edge_names.pop_back();
  b.p.vertex_names.pop_back();
  b.p.edge_names.back() = "";
  return b.p;
}

SpanRackOutline rack_span_outline(const Drive& drive, const MeshGeometry& geometry, const MeshPlacement& placement,
                                  int segment, double depth, double patch_half_height, double far_spacing) {
  const double l = drive.rack.span, p = geometry.rack.pitch;
  const double offset = drive.rack.tooth_offset >= 0 ? drive.rack.tooth_offset : 0.5 * p;
  const double y_root = -geometry.rack.dedendum, y_base = y_root - depth;
  SpanRackOutline out;
  out.x_left = segment * l;
  out.x_right = out.x_left + l;
  out.y_axis = y_root - depth / 2;
  if (!(patch_half_height > 0) || !(patch_half_height < depth / 2)) {
    throw std::invalid_argument("rack_span_outline: the hinge patch must be shorter than the body depth");
  }
  // Complete tooth cells [offset + (j - 1/2) p, offset + (j + 1/2) p] on the span.
  const double tol = 1e-9;
  const int j_first = static_cast<int>(std::ceil((out.x_left - offset) / p + 0.5 - tol));
  const int j_last = static_cast<int>(std::floor((out.x_right - offset) / p - 0.5 + tol));
  const int first = placement.first_rack_tooth, last = first + placement.rack_teeth - 1;
  if (first < j_first || last > j_last) {
    throw std::invalid_argument("rack on its supports: the teeth in mesh and one each side (rack teeth " +
                                std::to_string(first) + ".." + std::to_string(last) + ") must lie on the span's teeth " +
                                std::to_string(j_first) + ".." + std::to_string(j_last) +
                                ": the travel is too near a hinge");
  }
  out.teeth = j_last - j_first + 1;
  const auto cell_left = [&](int j) { return offset + (j - 0.5) * p; };

  OutlineBuilder b;
  b.tol = 1e-9 * p;
  b.add({out.x_left, y_base}, "BASE");
  b.add({out.x_right, y_base}, "");
  end_face(b, out.x_right, y_base, y_root, out.y_axis, patch_half_height, "HINGE_R");
  if (last < j_last) {
    const Polygon2D right = shifted(rack_segment_outline(geometry, j_last - last, depth, drive.rack.root_radius).outer,
                                    cell_left(last + 1));
    b.add({right.vertices[2].x, y_root}, "");
    append_top_chain(b, right, true, far_spacing);
  }
  append_top_chain(b, placement.rack.outer, false, 0);
  if (first > j_first) {
    const Polygon2D left =
        shifted(rack_segment_outline(geometry, first - j_first, depth, drive.rack.root_radius).outer, cell_left(j_first));
    append_top_chain(b, left, true, far_spacing);
  }
  b.add({out.x_left, y_root}, "");
  end_face(b, out.x_left, y_root, y_base, out.y_axis, patch_half_height, "HINGE_L");
  b.p.vertices.pop_back();  // (x_left, y_base): the first vertex
  b.p.edge_names.pop_back();
  b.p.vertex_names.pop_back();
  b.p.edge_names.back() = "";
  out.outline.outer = b.p;
  return out;
}

}  // namespace rackopt::fe

namespace rackopt::fe {

double fe_rack_body_depth(const Drive& drive, const FeOptions& options) {
  double depth = options.rack_body_depth;
  if (depth <= 0) depth = drive.rack.body_height > 0 ? drive.rack.body_height : 2 * drive.rack.section.neutral_axis_depth;
  if (!(depth > 0)) throw std::invalid_argument("the rack has no body depth (rack.body_height or its section)");
  return depth;
}

double fe_contact_width(const Drive& drive) {
  const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
  return std::min(drive.pinion.face_width, b_rack);
}

Drive rack_on_supports_drive(const Drive& drive, const FeOptions& options) {
  Drive d = drive;
  const double w = fe_contact_width(drive), h = fe_rack_body_depth(drive, options);
  d.effects.rack_span = RackSpanModel::kCoupled;
  d.rack.section.area = w * h;
  d.rack.section.second_moment = w * h * h * h / 12;
  d.rack.section.shear_area = w * h / 1.2;
  d.rack.section.neutral_axis_depth = h / 2;
  return d;
}

SpanRackMesh mesh_span_rack(const Drive& drive, const MeshGeometry& geometry, const MeshPlacement& placement,
                            int segment, double depth, double body_size, double far_spacing,
                            const std::vector<Refinement>& refinements, double patch_fraction) {
  if (!(patch_fraction > 0 && patch_fraction < 0.5)) {
    throw std::invalid_argument("mesh_span_rack: the hinge patch fraction must lie in (0, 0.5)");
  }
  const double c = patch_fraction * depth;
  SpanRackMesh out;
  out.geometry = rack_span_outline(drive, geometry, placement, segment, depth, c, far_spacing);
  std::vector<Refinement> refs = refinements;
  refs.push_back({{out.geometry.x_left, out.geometry.y_axis}, 3 * c, c / 2});
  refs.push_back({{out.geometry.x_right, out.geometry.y_axis}, 3 * c, c / 2});
  out.mesh = mesh_polygon_with_holes(out.geometry.outline.outer, {}, std::min(body_size, depth / 6), refs);
  const bool right_pin = drive.rack.supports == Supports::kPinPin;
  for (const auto& [name, pin] : {std::pair<std::string, bool>{"HINGE_L", true}, {"HINGE_R", right_pin}}) {
    const HingeConstraints h = hinge_constraints(out.mesh, name, name + "_AXIS", pin);
    out.hinges.supports.insert(out.hinges.supports.end(), h.supports.begin(), h.supports.end());
    out.hinges.equations.insert(out.hinges.equations.end(), h.equations.begin(), h.equations.end());
  }
  return out;
}

}  // namespace rackopt::fe
