#include "rackopt/geometry/pinion_section.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt {
namespace {

constexpr int kPoints = 240;

void add_arc(std::vector<ToothPoint>& pts, double radius, double from_angle, double to_angle) {
  for (int i = 0; i <= kPoints; ++i) {
    const double a = from_angle + (to_angle - from_angle) * i / kPoints;
    pts.push_back({radius * std::sin(a), radius * std::cos(a)});
  }
}

double radius_of(const ToothPoint& p) { return std::hypot(p.x, p.y); }

}  // namespace

double pinion_outline_area(const PinionSpec& pinion, const MeshGeometry& geometry) {
  const PinionGeometry& g = geometry.pinion;
  const double half_pitch_angle = M_PI / pinion.teeth;
  // Outline of the half pitch sector from the middle of the tooth space to
  // the tooth centre line; the origin (pinion centre) closes the polygon.
  std::vector<ToothPoint> pts;
  pts.reserve(4 * (kPoints + 1) + 1);
  pts.push_back({0.0, 0.0});
  const ToothPoint root = fillet_point(pinion, M_PI / 2);
  add_arc(pts, g.root_radius, half_pitch_angle, std::atan2(root.x, root.y));
  // Fillet from the root upwards (phi from pi/2 down to a0), while below the
  // form circle: above it the involute is the flank.
  const double a0 = pinion.pressure_angle;
  for (int i = 0; i <= kPoints; ++i) {
    const double phi = M_PI / 2 - (M_PI / 2 - a0) * i / kPoints;
    const ToothPoint p = fillet_point(pinion, phi);
    if (radius_of(p) >= g.form_radius) break;
    pts.push_back(p);
  }
  for (int i = 0; i <= kPoints; ++i) {
    const double r = g.form_radius + (g.tip_radius - g.form_radius) * i / kPoints;
    pts.push_back(involute_point(pinion, r));
  }
  const ToothPoint tip = pts.back();
  add_arc(pts, g.tip_radius, std::atan2(tip.x, tip.y), 0.0);
  double twice_area = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const ToothPoint& a = pts[i];
    const ToothPoint& b = pts[(i + 1) % pts.size()];
    twice_area += a.x * b.y - b.x * a.y;
  }
  return 2.0 * pinion.teeth * 0.5 * std::abs(twice_area);
}

}  // namespace rackopt
