#include "rackopt/fe/gear_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt::fe {
namespace {

constexpr int kMinCurvePoints = 8;
constexpr int kMinBoreSides = 180;
// Away from the focus teeth of a graded mesh the shape matters little to the
// focus teeth: the curves may be as coarse as the size asks, the bore a 72-gon.
constexpr int kMinCoarseCurvePoints = 2;
constexpr int kMinCoarseBoreSides = 72;

// A tooth-frame outline piece with the set name of the edges it makes.
struct Piece {
  std::vector<ToothPoint> points;
  std::string name;
};

double length_of(const std::vector<ToothPoint>& pts) {
  double l = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) l += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  return l;
}

// Number of intervals for a curve of (estimated) length `length`.
int intervals_for(double length, double spacing, int min_intervals) {
  return std::max(min_intervals, static_cast<int>(std::ceil(length / spacing)));
}

std::vector<ToothPoint> arc(double radius, double from_angle, double to_angle, double spacing, int min_intervals) {
  const int n = intervals_for(radius * std::abs(to_angle - from_angle), spacing, min_intervals);
  std::vector<ToothPoint> pts;
  for (int i = 0; i <= n; ++i) {
    const double a = from_angle + (to_angle - from_angle) * i / n;
    pts.push_back({radius * std::sin(a), radius * std::cos(a)});
  }
  return pts;
}

// The fillet from the root (phi = pi/2) up while below the form circle, as
// pinion_section.cpp takes it: above the form circle the involute is the flank.
std::vector<ToothPoint> fillet(const PinionSpec& pinion, double form_radius, double spacing, int min_intervals) {
  const double a0 = pinion.pressure_angle;
  const auto sample = [&](int n) {
    std::vector<ToothPoint> pts;
    for (int i = 0; i <= n; ++i) {
      const ToothPoint p = fillet_point(pinion, M_PI / 2 - (M_PI / 2 - a0) * i / n);
      if (std::hypot(p.x, p.y) >= form_radius) break;
      pts.push_back(p);
    }
    return pts;
  };
  return sample(intervals_for(length_of(sample(64)), spacing, min_intervals));
}

std::vector<ToothPoint> involute(const PinionSpec& pinion, double from_radius, double to_radius, double spacing,
                                 int min_intervals) {
  const auto sample = [&](int n) {
    std::vector<ToothPoint> pts;
    for (int i = 0; i <= n; ++i) pts.push_back(involute_point(pinion, from_radius + (to_radius - from_radius) * i / n));
    return pts;
  };
  return sample(intervals_for(length_of(sample(64)), spacing, min_intervals));
}

// Appends the pieces' points to `polygon`, turned by `angle` counter-clockwise,
// naming each edge after the piece holding both its ends. A point closer than
// `merge` to the previous one (the joint of two pieces, a zero-length root arc
// of a full-round cutter) is not repeated: the edge leaving it then belongs
// to the later piece.
void append(Polygon2D& polygon, const std::vector<Piece>& pieces, double angle, double merge) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (const Piece& piece : pieces) {
    for (const ToothPoint& p : piece.points) {
      const Point2 q{p.x * c - p.y * s, p.x * s + p.y * c};
      if (!polygon.vertices.empty()) {
        const Point2& last = polygon.vertices.back();
        if (std::hypot(q.x - last.x, q.y - last.y) < merge) {
          polygon.edge_names.back() = piece.name;
          continue;
        }
      }
      polygon.vertices.push_back(q);
      polygon.edge_names.push_back(piece.name);
    }
  }
}

std::vector<ToothPoint> mirrored_reversed(const std::vector<ToothPoint>& pts) {
  std::vector<ToothPoint> out(pts.rbegin(), pts.rend());
  for (ToothPoint& p : out) p.x = -p.x;
  return out;
}

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

}  // namespace

double gear_element_size(double module, int level) {
  if (level < 0 || level > 6) throw std::invalid_argument("gear_element_size: the refinement level must be 0..6");
  if (!(module > 0) || !std::isfinite(module)) throw std::invalid_argument("gear_element_size: the module must be positive");
  return module / 6.0 / std::pow(2.0, level);
}

namespace {

// One pinion tooth in its frame, counter-clockwise: from the middle of the
// space on its +x side, over the tooth, to the middle of the space on its -x
// side, curves at `spacing`; the flank pieces named after tooth `k`.
std::vector<Piece> pinion_tooth_pieces(const PinionSpec& pinion, const PinionGeometry& g, double spacing, int k,
                                       int min_intervals = kMinCurvePoints) {
  const double half_pitch_angle = M_PI / pinion.teeth;
  const ToothPoint root = fillet_point(pinion, M_PI / 2);
  const std::vector<ToothPoint> root_arc = arc(g.root_radius, half_pitch_angle, std::atan2(root.x, root.y), spacing, min_intervals);
  std::vector<ToothPoint> fil = fillet(pinion, g.form_radius, spacing, min_intervals);
  const std::vector<ToothPoint> inv = involute(pinion, g.form_radius, g.tip_radius, spacing, min_intervals);
  fil.push_back(inv.front());  // the fillet's last chord ends on the form circle
  const ToothPoint tip = inv.back();
  const double tip_angle = std::atan2(tip.x, tip.y);
  const std::vector<ToothPoint> tip_arc = arc(g.tip_radius, tip_angle, -tip_angle, spacing, min_intervals);
  const std::string t = "T" + std::to_string(k);
  return {{root_arc, ""},
          {fil, ""},
          {inv, t + "_FLANK_R"},
          {tip_arc, ""},
          {mirrored_reversed(inv), t + "_FLANK_L"},
          {mirrored_reversed(fil), ""},
          {mirrored_reversed(root_arc), ""}};
}

void check_focus(const std::vector<int>& focus, int teeth, const char* who) {
  for (int k : focus) {
    if (k < 0 || k >= teeth) {
      throw std::invalid_argument(std::string(who) + ": focus tooth " + std::to_string(k) + " is not one of 0.." +
                                  std::to_string(teeth - 1));
    }
  }
}

bool contains(const std::vector<int>& v, int k) { return std::find(v.begin(), v.end(), k) != v.end(); }

// The coarse size of a graded mesh: coarse_factor times the level's size, at most the module.
double coarse_size(const MeshGrading& grading, double size, double module) {
  if (!(grading.coarse_factor >= 1) || !std::isfinite(grading.coarse_factor)) {
    throw std::invalid_argument("MeshGrading: coarse_factor must be >= 1");
  }
  return std::max(size, std::min(grading.coarse_factor * size, module));
}

}  // namespace

Refinement pinion_focus_disc(const PinionSpec& pinion, const MeshGeometry& geometry, int tooth, double size) {
  check_focus({tooth}, pinion.teeth, "pinion_focus_disc");
  const PinionGeometry& g = geometry.pinion;
  const double yc = 0.5 * (g.root_radius + g.tip_radius);
  double reach = 0;
  // The outline's shape, not its spacing, sets the reach: a fine sampling.
  for (const Piece& piece : pinion_tooth_pieces(pinion, g, 0.01 * pinion.module, tooth)) {
    for (const ToothPoint& p : piece.points) reach = std::max(reach, std::hypot(p.x, p.y - yc));
  }
  const double a = 2 * M_PI * tooth / pinion.teeth;
  return {{-yc * std::sin(a), yc * std::cos(a)}, reach, size};
}

Refinement rack_focus_disc(const MeshGeometry& geometry, int tooth, double size) {
  if (tooth < 0) throw std::invalid_argument("rack_focus_disc: the tooth index must be >= 0");
  const RackGeometry& r = geometry.rack;
  const double half_height = 0.5 * (r.addendum + r.dedendum);
  return {{(tooth + 0.5) * r.pitch, 0.5 * (r.addendum - r.dedendum)}, std::hypot(0.5 * r.pitch, half_height), size};
}

BodyOutline pinion_body_outline(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius,
                                double spacing, const std::vector<int>& focus_teeth, double other_spacing) {
  if (!(bore_radius >= 0) || !std::isfinite(bore_radius)) {
    throw std::invalid_argument("pinion_body_outline: the bore radius must be >= 0");
  }
  if (!(spacing > 0) || !std::isfinite(spacing) || !(other_spacing >= 0) || !std::isfinite(other_spacing)) {
    throw std::invalid_argument("pinion_body_outline: the point spacing must be positive");
  }
  check_focus(focus_teeth, pinion.teeth, "pinion_body_outline");
  const PinionGeometry& g = geometry.pinion;
  if (bore_radius >= g.root_radius) {
    throw DesignError("bore_beyond_root", "bore radius " + fmt(bore_radius * 1e3) + " mm is not below the root radius " +
                                              fmt(g.root_radius * 1e3) + " mm: no rim is left to mesh");
  }
  const bool graded = !focus_teeth.empty();
  const double coarse = graded && other_spacing > 0 ? other_spacing : spacing;
  BodyOutline out;
  const double merge = 1e-9 * g.tip_radius;
  // Two tooth shapes at most: built once, the flank names set per tooth.
  const std::vector<Piece> fine_tooth = pinion_tooth_pieces(pinion, g, spacing, 0);
  const std::vector<Piece> coarse_tooth = graded ? pinion_tooth_pieces(pinion, g, coarse, 0, kMinCoarseCurvePoints) : fine_tooth;
  for (int k = 0; k < pinion.teeth; ++k) {
    std::vector<Piece> pieces = !graded || contains(focus_teeth, k) ? fine_tooth : coarse_tooth;
    const std::string t = "T" + std::to_string(k);
    pieces[2].name = t + "_FLANK_R";
    pieces[4].name = t + "_FLANK_L";
    append(out.outer, pieces, 2 * M_PI * k / pinion.teeth, merge);
  }
  // The last tooth's space middle is tooth 0's start: close without repeating it.
  const Point2 &first = out.outer.vertices.front(), &last = out.outer.vertices.back();
  if (std::hypot(first.x - last.x, first.y - last.y) < 1e-6 * spacing) {
    out.outer.vertices.pop_back();
    out.outer.edge_names.pop_back();
  }
  if (bore_radius > 0) {
    const int n = std::max(graded ? kMinCoarseBoreSides : kMinBoreSides,
                             static_cast<int>(std::ceil(2 * M_PI * bore_radius / coarse)));
    Polygon2D bore;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      bore.vertices.push_back({bore_radius * std::cos(a), bore_radius * std::sin(a)});
      bore.edge_names.push_back("BORE");
    }
    out.holes.push_back(bore);
  }
  return out;
}

Mesh2D mesh_pinion_body(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius, int level,
                        const MeshGrading& grading) {
  const double size = gear_element_size(pinion.module, level);
  if (grading.focus_teeth.empty()) {
    const BodyOutline o = pinion_body_outline(pinion, geometry, bore_radius, size / 2);
    return mesh_polygon_with_holes(o.outer, o.holes, size, grading.refinements);
  }
  const double coarse = coarse_size(grading, size, pinion.module);
  const BodyOutline o = pinion_body_outline(pinion, geometry, bore_radius, size / 2, grading.focus_teeth, coarse / 2);
  std::vector<Refinement> discs;
  for (int k : grading.focus_teeth) discs.push_back(pinion_focus_disc(pinion, geometry, k, size));
  discs.insert(discs.end(), grading.refinements.begin(), grading.refinements.end());
  return mesh_polygon_with_holes(o.outer, o.holes, coarse, discs);
}

BodyOutline rack_segment_outline(const MeshGeometry& geometry, int teeth, double body_height, double root_radius) {
  if (teeth < 1) throw std::invalid_argument("rack_segment_outline: at least one tooth");
  if (!(body_height > 0) || !std::isfinite(body_height)) {
    throw std::invalid_argument("rack_segment_outline: the body height must be positive");
  }
  if (!(root_radius >= 0) || !std::isfinite(root_radius)) {
    throw std::invalid_argument("rack_segment_outline: the root radius must be >= 0 (0 = the cutter tip radius)");
  }
  const RackGeometry& r = geometry.rack;
  if (!(r.half_thickness_at_tip > 0)) {
    throw DesignError("pointed_tooth", "rack tooth tip half thickness " + fmt(r.half_thickness_at_tip * 1e3) +
                                           " mm: the tooth is pointed");
  }
  if (!(r.half_thickness_at_root < r.pitch / 2)) {
    throw DesignError("rack_root_closed", "rack tooth half thickness at the root " +
                                              fmt(r.half_thickness_at_root * 1e3) + " mm leaves no root in a pitch of " +
                                              fmt(r.pitch * 1e3) + " mm");
  }
  const double rho = root_radius > 0 ? root_radius : geometry.pinion.cutter_tip_radius;
  const double a0 = geometry.pressure_angle, sin_a0 = std::sin(a0), cos_a0 = std::cos(a0);
  // The air angle at a root corner is 90 deg + a0: the tangent points lie
  // t = rho / tan(45 deg + a0/2) = rho cos a0 / (1 + sin a0) from it.
  const double t = rho * cos_a0 / (1 + sin_a0);
  const double root_width = r.pitch - 2 * r.half_thickness_at_root;
  const double flank_length = (r.addendum + r.dedendum) / cos_a0;
  if (2 * t > root_width || t > flank_length) {
    throw DesignError("rack_root_round", "rack root round " + fmt(rho * 1e3) + " mm reaches " + fmt(t * 1e3) +
                                             " mm along the root line and the flank: the root holds " +
                                             fmt(root_width / 2 * 1e3) + " mm per round, the flank " +
                                             fmt(flank_length * 1e3) + " mm");
  }
  const double y_root = -r.dedendum, y_tip = r.addendum, y_base = y_root - body_height;
  const double length = teeth * r.pitch;
  BodyOutline out;
  Polygon2D& p = out.outer;
  const auto add = [&](double x, double y, const std::string& edge) {
    p.vertices.push_back({x, y});
    p.edge_names.push_back(edge);
  };
  constexpr int kRoundChords = 12;
  // The round of a corner at x_corner: centre rho above the root line, t from
  // the corner on the space side (side = +1 right of a tooth, -1 left),
  // swept from angle `from` to `to` about it.
  const auto round = [&](double x_corner, int side, double from, double to, const std::string& last_edge) {
    const Point2 c{x_corner + side * t, y_root + rho};
    for (int i = 0; i <= kRoundChords; ++i) {
      const double a = from + (to - from) * i / kRoundChords;
      add(c.x + rho * std::cos(a), c.y + rho * std::sin(a), i == kRoundChords ? last_edge : "");
    }
  };
  add(0, y_base, "BASE");
  add(length, y_base, "RIGHT_END");
  add(length, y_root, "");
  for (int k = teeth - 1; k >= 0; --k) {  // along the top from +x to -x: counter-clockwise
    const double xc = (k + 0.5) * r.pitch;
    const std::string name = "T" + std::to_string(k);
    if (t > 0) {
      round(xc + r.half_thickness_at_root, +1, 1.5 * M_PI, M_PI + a0, name + "_FLANK_R");
    } else {
      add(xc + r.half_thickness_at_root, y_root, name + "_FLANK_R");
    }
    add(xc + r.half_thickness_at_tip, y_tip, "");
    add(xc - r.half_thickness_at_tip, y_tip, name + "_FLANK_L");
    if (t > 0) {
      round(xc - r.half_thickness_at_root, -1, 2 * M_PI - a0, 1.5 * M_PI, "");
    } else {
      add(xc - r.half_thickness_at_root, y_root, "");
    }
  }
  add(0, y_root, "LEFT_END");
  // A round that fills its half of an end space exactly ends on the cut face.
  for (std::size_t i = 1; i < p.vertices.size(); ++i) {
    if (std::hypot(p.vertices[i].x - p.vertices[i - 1].x, p.vertices[i].y - p.vertices[i - 1].y) < 1e-12 * r.pitch) {
      p.vertices.erase(p.vertices.begin() + static_cast<long>(i));
      p.edge_names.erase(p.edge_names.begin() + static_cast<long>(i - 1));
      --i;
    }
  }
  return out;
}

Mesh2D mesh_rack_segment(const MeshGeometry& geometry, int teeth, double body_height, int level,
                         const MeshGrading& grading, double root_radius) {
  const double module = geometry.rack.pitch / M_PI;
  const double size = gear_element_size(module, level);
  const BodyOutline o = rack_segment_outline(geometry, teeth, body_height, root_radius);
  if (grading.focus_teeth.empty()) return mesh_polygon_with_holes(o.outer, o.holes, size, grading.refinements);
  check_focus(grading.focus_teeth, teeth, "mesh_rack_segment");
  std::vector<Refinement> discs;
  for (int k : grading.focus_teeth) discs.push_back(rack_focus_disc(geometry, k, size));
  discs.insert(discs.end(), grading.refinements.begin(), grading.refinements.end());
  return mesh_polygon_with_holes(o.outer, o.holes, coarse_size(grading, size, module), discs);
}

int rack_teeth_each_side(double body_depth, double pitch) {
  return std::max(1, static_cast<int>(std::ceil(3 * body_depth / pitch)));
}

}  // namespace rackopt::fe
