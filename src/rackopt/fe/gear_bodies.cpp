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
int intervals_for(double length, double spacing) {
  return std::max(kMinCurvePoints, static_cast<int>(std::ceil(length / spacing)));
}

std::vector<ToothPoint> arc(double radius, double from_angle, double to_angle, double spacing) {
  const int n = intervals_for(radius * std::abs(to_angle - from_angle), spacing);
  std::vector<ToothPoint> pts;
  for (int i = 0; i <= n; ++i) {
    const double a = from_angle + (to_angle - from_angle) * i / n;
    pts.push_back({radius * std::sin(a), radius * std::cos(a)});
  }
  return pts;
}

// The fillet from the root (phi = pi/2) up while below the form circle, as
// pinion_section.cpp takes it: above the form circle the involute is the flank.
std::vector<ToothPoint> fillet(const PinionSpec& pinion, double form_radius, double spacing) {
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
  return sample(intervals_for(length_of(sample(64)), spacing));
}

std::vector<ToothPoint> involute(const PinionSpec& pinion, double from_radius, double to_radius, double spacing) {
  const auto sample = [&](int n) {
    std::vector<ToothPoint> pts;
    for (int i = 0; i <= n; ++i) pts.push_back(involute_point(pinion, from_radius + (to_radius - from_radius) * i / n));
    return pts;
  };
  return sample(intervals_for(length_of(sample(64)), spacing));
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

BodyOutline pinion_body_outline(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius,
                                double spacing) {
  if (!(bore_radius >= 0) || !std::isfinite(bore_radius)) {
    throw std::invalid_argument("pinion_body_outline: the bore radius must be >= 0");
  }
  if (!(spacing > 0) || !std::isfinite(spacing)) {
    throw std::invalid_argument("pinion_body_outline: the point spacing must be positive");
  }
  const PinionGeometry& g = geometry.pinion;
  if (bore_radius >= g.root_radius) {
    throw DesignError("bore_beyond_root", "bore radius " + fmt(bore_radius * 1e3) + " mm is not below the root radius " +
                                              fmt(g.root_radius * 1e3) + " mm: no rim is left to mesh");
  }
  const double half_pitch_angle = M_PI / pinion.teeth;
  // One tooth in its frame, counter-clockwise: from the middle of the space
  // on its +x side, over the tooth, to the middle of the space on its -x side.
  const ToothPoint root = fillet_point(pinion, M_PI / 2);
  const std::vector<ToothPoint> root_arc = arc(g.root_radius, half_pitch_angle, std::atan2(root.x, root.y), spacing);
  std::vector<ToothPoint> fil = fillet(pinion, g.form_radius, spacing);
  const std::vector<ToothPoint> inv = involute(pinion, g.form_radius, g.tip_radius, spacing);
  fil.push_back(inv.front());  // the fillet's last chord ends on the form circle
  const ToothPoint tip = inv.back();
  const double tip_angle = std::atan2(tip.x, tip.y);
  const std::vector<ToothPoint> tip_arc = arc(g.tip_radius, tip_angle, -tip_angle, spacing);

  BodyOutline out;
  const double merge = 1e-9 * g.tip_radius;
  for (int k = 0; k < pinion.teeth; ++k) {
    const std::string t = "T" + std::to_string(k);
    const std::vector<Piece> pieces = {{root_arc, ""},
                                       {fil, ""},
                                       {inv, t + "_FLANK_R"},
                                       {tip_arc, ""},
                                       {mirrored_reversed(inv), t + "_FLANK_L"},
                                       {mirrored_reversed(fil), ""},
                                       {mirrored_reversed(root_arc), ""}};
    append(out.outer, pieces, 2 * M_PI * k / pinion.teeth, merge);
  }
  // The last tooth's space middle is tooth 0's start: close without repeating it.
  const Point2 &first = out.outer.vertices.front(), &last = out.outer.vertices.back();
  if (std::hypot(first.x - last.x, first.y - last.y) < 1e-6 * spacing) {
    out.outer.vertices.pop_back();
    out.outer.edge_names.pop_back();
  }
  if (bore_radius > 0) {
    const int n = std::max(kMinBoreSides, static_cast<int>(std::ceil(2 * M_PI * bore_radius / spacing)));
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

Mesh2D mesh_pinion_body(const PinionSpec& pinion, const MeshGeometry& geometry, double bore_radius, int level) {
  const double size = gear_element_size(pinion.module, level);
  const BodyOutline o = pinion_body_outline(pinion, geometry, bore_radius, size / 2);
  return mesh_polygon_with_holes(o.outer, o.holes, size);
}

BodyOutline rack_segment_outline(const MeshGeometry& geometry, int teeth, double body_height) {
  if (teeth < 1) throw std::invalid_argument("rack_segment_outline: at least one tooth");
  if (!(body_height > 0) || !std::isfinite(body_height)) {
    throw std::invalid_argument("rack_segment_outline: the body height must be positive");
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
  const double y_root = -r.dedendum, y_tip = r.addendum, y_base = y_root - body_height;
  const double length = teeth * r.pitch;
  BodyOutline out;
  Polygon2D& p = out.outer;
  const auto add = [&](double x, double y, const std::string& edge) {
    p.vertices.push_back({x, y});
    p.edge_names.push_back(edge);
  };
  add(0, y_base, "BASE");
  add(length, y_base, "RIGHT_END");
  add(length, y_root, "");
  for (int k = teeth - 1; k >= 0; --k) {  // along the top from +x to -x: counter-clockwise
    const double xc = (k + 0.5) * r.pitch;
    const std::string t = "T" + std::to_string(k);
    add(xc + r.half_thickness_at_root, y_root, t + "_FLANK_R");
    add(xc + r.half_thickness_at_tip, y_tip, "");
    add(xc - r.half_thickness_at_tip, y_tip, t + "_FLANK_L");
    add(xc - r.half_thickness_at_root, y_root, "");
  }
  add(0, y_root, "LEFT_END");
  return out;
}

Mesh2D mesh_rack_segment(const MeshGeometry& geometry, int teeth, double body_height, int level) {
  const double size = gear_element_size(geometry.rack.pitch / M_PI, level);
  const BodyOutline o = rack_segment_outline(geometry, teeth, body_height);
  return mesh_polygon_with_holes(o.outer, o.holes, size);
}

}  // namespace rackopt::fe
