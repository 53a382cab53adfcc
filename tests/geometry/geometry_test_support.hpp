// Helpers shared by the geometry tests: drives in SI units and an independent
// brute-force simulation of rack-cutter generation used to check the
// closed-form / envelope results of rackopt/geometry.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rackopt/core/drive.hpp"

namespace rackopt::geometry_test {

constexpr double kPi = std::numbers::pi;
inline double deg(double d) { return d * kPi / 180.0; }

// Standard full-depth drive: h_a* = 1, cutter addendum 1.25, rack 1 / 1.25.
inline Drive standard_drive(int z, double module, double alpha_deg, double x = 0.0,
                            double tip_radius_coef = 0.3) {
  Drive d;
  d.pinion.teeth = z;
  d.pinion.module = module;
  d.pinion.pressure_angle = deg(alpha_deg);
  d.pinion.profile_shift = x;
  d.pinion.addendum_coef = 1.0;
  d.pinion.dedendum_coef = 1.25;
  d.pinion.tip_radius_coef = tip_radius_coef;
  d.rack.addendum_coef = 1.0;
  d.rack.dedendum_coef = 1.25;
  return d;
}

// The rack railway paper as stated in docs/models/geometry.md: m = 31.831 mm (p = 100 mm), z = 22,
// 14 deg, h_a* = 0.9, c* = 0.166 (tool addendum 1.066), rack 0.9 / 1.066.
// Tip radius: the full round c*/(1 - sin a0) (the seed gives none).
inline Drive railway_paper_drive(double alpha_deg = 14.0, double clearance = 0.0) {
  Drive d;
  d.pinion.teeth = 22;
  d.pinion.module = 0.031831;
  d.pinion.pressure_angle = deg(alpha_deg);
  d.pinion.addendum_coef = 0.9;
  d.pinion.dedendum_coef = 1.066;
  d.pinion.tip_radius_coef = 0.166 / (1.0 - std::sin(deg(alpha_deg)));
  d.rack.addendum_coef = 0.9;
  d.rack.dedendum_coef = 1.066;
  d.mounting.clearance = clearance;
  return d;
}

// Brute-force cutting: the cutter tooth is the trapezoid of the basic rack
// (half width pi m/4 at the datum, flanks at a0, tip h_a0 m above the datum)
// with its two tip corners rounded by rho, i.e. the set of points within rho of
// the trapezoid shrunk by rho. penetration() returns how deep a point of the
// pinion lies inside the cutter, maximised over the roll parameter t by dense
// sampling plus golden-section refinement. It shares no code with the library.
class CuttingSimulation {
 public:
  explicit CuttingSimulation(const PinionSpec& p)
      : m_(p.module),
        a0_(p.pressure_angle),
        top_(p.dedendum_coef * p.module - p.tip_radius_coef * p.module),
        rho_(p.tip_radius_coef * p.module),
        shift_(p.profile_shift * p.module),
        r_(0.5 * p.module * p.teeth),
        z_(p.teeth) {
    w_ = (kPi * m_ / 4.0) * std::cos(a0_) - rho_;
  }

  // Point at radius R, at angle theta from the centre line of the studied
  // tooth, on the side of the flank the library describes.
  double penetration(double radius, double theta) const {
    const double ang = -kPi / 2.0 + kPi / z_ - theta;
    const double qx = radius * std::cos(ang);
    const double qy = radius * std::sin(ang);
    auto pen = [&](double t) {
      const double ix = r_ * std::sin(t), iy = -r_ * std::cos(t);
      const double dx = qx - ix, dy = qy - iy;
      const double cx = r_ * t + dx * std::cos(t) + dy * std::sin(t);  // along the cutter
      const double cy = -dx * std::sin(t) + dy * std::cos(t) + shift_;  // above the datum
      return rho_ - distance_to_core(cx, cy);
    };
    // Roll range: the whole half turn around the studied tooth; far from the
    // point's own generation angle the cutter is above it and cannot touch it.
    const double t0 = -kPi / 2.0, t1 = kPi / 2.0;
    constexpr int kN = 40000;
    double best = -1e300, tb = 0.0;
    for (int i = 0; i <= kN; ++i) {
      const double t = t0 + (t1 - t0) * i / kN;
      const double v = pen(t);
      if (v > best) best = v, tb = t;
    }
    double a = tb - (t1 - t0) / kN, b = tb + (t1 - t0) / kN;
    for (int i = 0; i < 200; ++i) {
      const double m1 = a + 0.381966 * (b - a), m2 = a + 0.618034 * (b - a);
      if (pen(m1) > pen(m2)) b = m2; else a = m1;
    }
    return std::max(best, pen(0.5 * (a + b)));
  }

  // Distance from (X, Y) to the shrunk trapezoid {Y <= top, |X| cos a0 + Y sin a0 <= w};
  // negative depth inside.
  // Half angle of the simulated tooth at radius R (angle of the boundary point
  // from the tooth centre line), by bisection between intact and cut.
  double boundary_half_angle(double radius) const {
    double lo = 0.0, hi = kPi / z_;  // lo intact (tooth centre), hi cut (space centre)
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (penetration(radius, mid) > 0.0) hi = mid; else lo = mid;
    }
    return lo;
  }

 private:
  double distance_to_core(double X, double Y) const {
    const double ca = std::cos(a0_), sa = std::sin(a0_);
    auto inside = [&](double px, double py) {
      return py <= top_ + 1e-15 && std::abs(px) * ca + py * sa <= w_ + 1e-15;
    };
    if (inside(X, Y)) {
      return -std::min({top_ - Y, w_ - (X * ca + Y * sa), w_ - (-X * ca + Y * sa)});
    }
    double best = 1e300;
    if (inside(X, top_)) best = std::min(best, std::abs(Y - top_));
    for (int sg = -1; sg <= 1; sg += 2) {
      const double nx = sg * ca, ny = sa;
      const double d = nx * X + ny * Y - w_;
      if (inside(X - d * nx, Y - d * ny)) best = std::min(best, std::abs(d));
      const double corner_x = sg * (w_ - top_ * sa) / ca;
      best = std::min(best, std::hypot(X - corner_x, Y - top_));
    }
    return best;
  }

  double m_, a0_, top_, rho_, shift_, r_, z_, w_;
};

}  // namespace rackopt::geometry_test
