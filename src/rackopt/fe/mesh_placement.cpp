#include "rackopt/fe/mesh_placement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt::fe {
namespace {

Point2 rotate(Point2 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {p.x * c - p.y * s, p.x * s + p.y * c};
}

// The vertices [a, b] whose edges a..b-1 carry `name` (one run).
std::pair<std::size_t, std::size_t> run_of(const Polygon2D& p, const std::string& name) {
  std::size_t a = p.edge_names.size(), b = 0;
  for (std::size_t i = 0; i < p.edge_names.size(); ++i) {
    if (p.edge_names[i] != name) continue;
    a = std::min(a, i);
    b = std::max(b, i + 1);
  }
  if (a >= p.edge_names.size() || b >= p.vertices.size()) {
    throw std::logic_error("mesh placement: outline has no single run of edges " + name);
  }
  for (std::size_t i = a; i < b; ++i) {
    if (p.edge_names[i] != name) throw std::logic_error("mesh placement: edges " + name + " are not one run");
  }
  return {a, b};
}

// Parameters strictly between lo and hi (lo < hi), at `c` (when inside) and
// graded away from it: spacing `fine` at c growing by `growth` times the
// distance, at most `coarse`. Ascending.
std::vector<double> graded(double lo, double hi, double c, const PlacementSpacing& sp) {
  std::vector<double> out;
  // The contact is a vertex unless it is an end already (a contact at the
  // form circle or the tip); a contact just inside an end makes a short edge.
  const double same = 1e-9 * (hi - lo);
  if (c > lo + same && c < hi - same) out.push_back(c);
  for (int dir : {-1, 1}) {
    double d = 0;
    for (int n = 0; n < 100000; ++n) {
      d += std::min(sp.outline, sp.contact + sp.growth * d);
      const double t = c + dir * d;
      const double step_here = std::min(sp.outline, sp.contact + sp.growth * d);
      if (t <= lo + 0.3 * step_here || t >= hi - 0.3 * step_here) break;
      if (dir < 0 && c - lo < 0.3 * sp.contact) break;
      if (dir > 0 && hi - c < 0.3 * sp.contact) break;
      out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Replaces the interior vertices of the run [a, b] by `points` (in order from a to b).
void replace_run(Polygon2D& p, std::size_t a, std::size_t b, const std::vector<Point2>& points,
                 const std::string& name) {
  p.vertices.erase(p.vertices.begin() + static_cast<std::ptrdiff_t>(a + 1),
                   p.vertices.begin() + static_cast<std::ptrdiff_t>(b));
  p.edge_names.erase(p.edge_names.begin() + static_cast<std::ptrdiff_t>(a + 1),
                     p.edge_names.begin() + static_cast<std::ptrdiff_t>(b));
  p.vertices.insert(p.vertices.begin() + static_cast<std::ptrdiff_t>(a + 1), points.begin(), points.end());
  p.edge_names.insert(p.edge_names.begin() + static_cast<std::ptrdiff_t>(a + 1), points.size(), name);
}

void transform(Polygon2D& p, double angle, Point2 shift) {
  for (Point2& v : p.vertices) {
    const Point2 q = rotate(v, angle);
    v = {q.x + shift.x, q.y + shift.y};
  }
}

}  // namespace

double distance_to_polygon(const Polygon2D& polygon, Point2 p) {
  double best = INFINITY;
  const std::size_t n = polygon.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 a = polygon.vertices[i], b = polygon.vertices[(i + 1) % n];
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
  }
  return best;
}

bool inside_polygon(const Polygon2D& polygon, Point2 p) {
  bool in = false;
  const std::size_t n = polygon.vertices.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2 a = polygon.vertices[i], b = polygon.vertices[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

MeshPlacement place_mesh(const Drive& drive, const MeshStiffnessModel& model, double travel,
                         const PlacementSpacing& spacing, double rack_body_depth, bool neighbours,
                         int rack_side_teeth) {
  if (!(spacing.outline > 0) || !(spacing.contact > 0) || spacing.contact > spacing.outline ||
      !(spacing.growth > 0) || !std::isfinite(spacing.outline)) {
    throw std::invalid_argument("place_mesh: spacings must be positive, contact <= outline, growth > 0");
  }
  if (!(rack_body_depth > 0) || !std::isfinite(rack_body_depth)) {
    throw std::invalid_argument("place_mesh: the rack body depth must be positive");
  }
  const MeshGeometry& geo = model.geometry();
  const PinionSpec& pin = drive.pinion;
  const MeshState state = model.at(travel);
  if (state.pairs.empty()) throw std::runtime_error("place_mesh: no pair in mesh at this travel");
  const int z = pin.teeth;
  const double a0 = pin.pressure_angle, r = geo.pinion.pitch_radius, rb = geo.pinion.base_radius;
  const double lift = geo.profile_shift_length + geo.clearance;  // x m + Delta
  const double sP = geo.path.s_pitch;

  MeshPlacement out;
  out.travel = travel;
  out.pinion_centre = {travel, r + lift};
  out.loa_direction = {std::cos(a0), -std::sin(a0)};
  out.rack_body_depth = rack_body_depth;
  out.bore_radius = pin.bore_radius > 0 ? pin.bore_radius : 0.5 * geo.pinion.root_radius;
  const auto contact_at = [&](double s) {
    return Point2{travel + (s - sP) * out.loa_direction.x, lift + (s - sP) * out.loa_direction.y};
  };
  const auto mod_z = [z](int j) { return ((j % z) + z) % z; };

  int j_lo = state.pairs.front().rack_tooth, j_hi = j_lo;
  for (const PairState& p : state.pairs) {
    j_lo = std::min(j_lo, p.rack_tooth);
    j_hi = std::max(j_hi, p.rack_tooth);
  }
  const int side_teeth = rack_side_teeth > 0 ? rack_side_teeth : rack_teeth_each_side(rack_body_depth, geo.rack.pitch);
  out.first_rack_tooth = j_lo - side_teeth;
  out.rack_teeth = j_hi - j_lo + 1 + 2 * side_teeth;
  const double pitch = geo.rack.pitch;
  const double offset = drive.rack.tooth_offset >= 0 ? drive.rack.tooth_offset : 0.5 * pitch;
  // Segment tooth k has its centre at (k + 1/2) p in the outline, at offset + (first + k) p here.
  out.rack_shift = offset + out.first_rack_tooth * pitch - 0.5 * pitch;

  for (const PairState& p : state.pairs) {
    FlankContact c;
    c.rack_tooth = p.rack_tooth;
    c.pinion_tooth = p.pinion_tooth;
    c.s = p.s;
    c.contact = contact_at(p.s);
    c.pinion_set = "T" + std::to_string(p.pinion_tooth) + "_FLANK_L";
    c.rack_set = "T" + std::to_string(p.rack_tooth - out.first_rack_tooth) + "_FLANK_L";
    out.contacts.push_back(c);
  }

  // The pinion turn that puts the first pair's involute point at its contact:
  // tooth k's counter-clockwise flank at radius R lies at polar angle
  // pi/2 + 2 pi k / z + (half angle at R) in the outline's frame.
  {
    const FlankContact& c = out.contacts.front();
    const double R = std::hypot(c.contact.x - out.pinion_centre.x, c.contact.y - out.pinion_centre.y);
    const double beta = std::atan2(c.contact.y - out.pinion_centre.y, c.contact.x - out.pinion_centre.x);
    const double phi = beta - (M_PI / 2 + 2 * M_PI * c.pinion_tooth / z + involute_half_angle(pin, R));
    out.pinion_rotation = std::remainder(phi, 2 * M_PI);
  }

  // Outlines in their own frames, the loaded flanks redrawn with a vertex at
  // each contact.
  // The pinion's teeth in and next to the mesh at spacing.outline, the
  // others at spacing.far (their shape matters little here).
  for (int j = j_lo - 1; j <= j_hi + 1; ++j) {
    if (std::find(out.focus_pinion_teeth.begin(), out.focus_pinion_teeth.end(), mod_z(j)) == out.focus_pinion_teeth.end()) {
      out.focus_pinion_teeth.push_back(mod_z(j));
    }
  }
  out.pinion = pinion_body_outline(pin, geo, out.bore_radius, spacing.outline, out.focus_pinion_teeth,
                                   std::max(spacing.far, spacing.outline));
  out.rack = rack_segment_outline(geo, out.rack_teeth, rack_body_depth, drive.rack.root_radius);
  for (const FlankContact& c : out.contacts) {
    // Pinion: along the involute by arc length from the base circle, L = s^2 / (2 r_b).
    Polygon2D& P = out.pinion.outer;
    const auto [a, b] = run_of(P, c.pinion_set);
    const auto arc_of = [&](Point2 v) { return (v.x * v.x + v.y * v.y - rb * rb) / (2 * rb); };
    const double La = arc_of(P.vertices[a]), Lb = arc_of(P.vertices[b]);
    const double Lc = c.s * c.s / (2 * rb);
    const double turn = 2 * M_PI * c.pinion_tooth / z;
    std::vector<double> Ls = graded(std::min(La, Lb), std::max(La, Lb), Lc, spacing);
    if (La > Lb) std::reverse(Ls.begin(), Ls.end());
    std::vector<Point2> pts;
    for (double L : Ls) {
      const ToothPoint q = involute_point(pin, std::sqrt(rb * rb + 2 * rb * L));
      pts.push_back(rotate({-q.x, q.y}, turn));
    }
    replace_run(P, a, b, pts, c.pinion_set);
    // Rack: the straight flank from its tip end to its root end.
    Polygon2D& Q = out.rack.outer;
    const auto [ra, rb_] = run_of(Q, c.rack_set);
    const Point2 tip = Q.vertices[ra], root = Q.vertices[rb_];
    const double len = std::hypot(root.x - tip.x, root.y - tip.y);
    const Point2 local{c.contact.x - out.rack_shift, c.contact.y};
    const double dc = std::hypot(local.x - tip.x, local.y - tip.y);
    std::vector<Point2> rpts;
    for (double d : graded(0, len, dc, spacing)) {
      rpts.push_back(d == dc ? local : Point2{tip.x + (root.x - tip.x) * d / len, tip.y + (root.y - tip.y) * d / len});
    }
    replace_run(Q, ra, rb_, rpts, c.rack_set);
  }
  transform(out.pinion.outer, out.pinion_rotation, out.pinion_centre);
  for (Polygon2D& h : out.pinion.holes) transform(h, out.pinion_rotation, out.pinion_centre);
  transform(out.rack.outer, 0, {out.rack_shift, 0});

  if (neighbours) {
    for (int j : {j_lo - 1, j_hi + 1}) {
      FlankContact c;
      c.rack_tooth = j;
      c.pinion_tooth = mod_z(j);
      c.s = state.pairs.front().s + (j - state.pairs.front().rack_tooth) * geo.path.base_pitch;
      c.theoretical = false;
      c.contact = contact_at(c.s);
      c.pinion_set = "T" + std::to_string(c.pinion_tooth) + "_FLANK_L";
      c.rack_set = "T" + std::to_string(j - out.first_rack_tooth) + "_FLANK_L";
      out.contacts.push_back(c);
    }
  }
  return out;
}

}  // namespace rackopt::fe
