#include "rackopt/geometry/pinion_generation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rackopt {
namespace {

constexpr double kPi = std::numbers::pi;

double involute_function(double a) { return std::tan(a) - a; }

double pitch_radius(const PinionSpec& p) { return 0.5 * p.module * p.teeth; }
double base_radius(const PinionSpec& p) { return pitch_radius(p) * std::cos(p.pressure_angle); }

// Polar description of a point of the pinion frame used for generation: the
// cutter rolls under the pinion centre, the space cut by the cutter tooth at
// rest is centred on the downward direction, the studied tooth is centred at
// +pi/z from it.
struct Polar {
  double radius;
  double angle_from_centre_line;  // theta >= 0 towards the studied flank
};

// What the fillet and the involute of one pinion need that does not depend
// on the point: the undercut search evaluates both about a thousand times
// per design, and these took five of their ten transcendental calls.
struct Generation {
  double m, r, rho, xc, yc, teeth;
  double rb, alpha2;
  explicit Generation(const PinionSpec& p)
      : m(p.module),
        r(pitch_radius(p)),
        rho(p.tip_radius_coef * m),
        xc(cutter_tip_flat_half_width(p)),
        yc((p.dedendum_coef - p.profile_shift) * m - rho),
        teeth(p.teeth),
        rb(base_radius(p)),
        alpha2(kPi / (2.0 * p.teeth) + involute_function(p.pressure_angle) +
               2.0 * p.profile_shift * std::tan(p.pressure_angle) / p.teeth) {}
};

// Fillet point in polar form (see fillet_point for the meaning of phi).
//
// Generation kinematics, pinion frame with the pinion centre at the origin:
// at roll parameter t the pitch point (instantaneous centre) is
// I(t) = r (sin t, -cos t), the cutter axes are e_X = (cos t, sin t) along the
// cutter and e_Y = (-sin t, cos t) towards the pinion centre, and the cutter
// point (X, Y) (Y from the rolling line) sits at I + (X - r t) e_X + Y e_Y.
// The round centre is (X_c, Y_c) = (w_flat, (h_a0 - x) m - rho). The round
// touches the generated surface where its normal passes through I, i.e. at
// X_c - r t = Y_c cot(phi) for the round normal angle phi.
Polar fillet_polar(const Generation& g, double phi) {
  const double r = g.r, rho = g.rho, xc = g.xc, yc = g.yc;
  const double cot_phi = std::cos(phi) / std::sin(phi);
  const double t = (xc - yc * cot_phi) / r;
  const double along = yc * cot_phi + rho * std::cos(phi);  // e_X component from I
  const double up = yc + rho * std::sin(phi);               // e_Y component from I
  const double st = std::sin(t);
  const double ct = std::cos(t);
  const double fx = r * st + along * ct - up * st;
  const double fy = -r * ct + along * st + up * ct;
  // Angle measured from the downward direction (centre of the cut space).
  const double from_space_centre = std::atan2(fx, -fy);
  return {std::hypot(fx, fy), kPi / g.teeth - from_space_centre};
}

// involute_half_angle with the pinion's constants computed once.
double involute_half_angle(const Generation& g, double radius) {
  const double ratio = std::max(radius / g.rb, 1.0);
  // inv(alpha_R) = tan alpha_R - alpha_R with cos alpha_R = r_b / R.
  const double inv_r = std::sqrt(ratio * ratio - 1.0) - std::acos(1.0 / ratio);
  return g.alpha2 - inv_r;
}

}  // namespace

double cutter_tip_flat_half_width(const PinionSpec& p) {
  const double a0 = p.pressure_angle;
  const double m = p.module;
  return kPi * m / 4.0 - p.dedendum_coef * m * std::tan(a0) -
         p.tip_radius_coef * m * (1.0 - std::sin(a0)) / std::cos(a0);
}

double cutter_tip_radius_for_zero_flat(const PinionSpec& p) {
  const double a0 = p.pressure_angle;
  const double m = p.module;
  return (kPi * m / 4.0 - p.dedendum_coef * m * std::tan(a0)) * std::cos(a0) /
         (1.0 - std::sin(a0));
}

ToothPoint fillet_point(const PinionSpec& p, double phi) {
  const Polar q = fillet_polar(Generation(p), phi);
  return {q.radius * std::sin(q.angle_from_centre_line),
          q.radius * std::cos(q.angle_from_centre_line)};
}

double involute_half_angle(const PinionSpec& p, double radius) {
  return involute_half_angle(Generation(p), radius);
}

ToothPoint involute_point(const PinionSpec& p, double radius) {
  const double th = involute_half_angle(p, radius);
  return {radius * std::sin(th), radius * std::cos(th)};
}

double flank_tangency_loa(const PinionSpec& p) {
  const double a0 = p.pressure_angle;
  const double m = p.module;
  const double h_st = (p.dedendum_coef - p.profile_shift) * m -
                      p.tip_radius_coef * m * (1.0 - std::sin(a0));
  return base_radius(p) * std::tan(a0) - h_st / std::sin(a0);
}

double teeth_for_no_undercut(const PinionSpec& p) {
  const double s = std::sin(p.pressure_angle);
  return 2.0 * ((p.dedendum_coef - p.profile_shift) - p.tip_radius_coef * (1.0 - s)) / (s * s);
}

FormCircle generated_form_circle(const PinionSpec& p) {
  const double rb = base_radius(p);
  const double s_c = flank_tangency_loa(p);
  if (s_c >= 0.0) {
    // The straight flank generates the involute down to the point made by the
    // flank/round tangency point; the fillet joins it there tangentially.
    return {std::hypot(rb, s_c), s_c, false};
  }

  // Undercut: the tip round sweeps through the involute. Walk the fillet from
  // the root (phi = pi/2) to the flank tangency point (phi = a0) and find where
  // it leaves the tooth (crosses the involute outwards). gap > 0 means the
  // fillet point lies inside the involute tooth outline, i.e. the involute
  // there has been cut away.
  const double a0 = p.pressure_angle;
  const Generation gen(p);
  auto gap = [&](double phi, double* radius) {
    const Polar q = fillet_polar(gen, phi);
    *radius = q.radius;
    if (q.radius < rb) return -1.0;  // no involute there; marker only
    return involute_half_angle(gen, q.radius) - q.angle_from_centre_line;
  };
  // Bisection on phi between a point where pred holds and one where it fails;
  // returns the last point where it holds.
  auto bisect = [](double holds, double fails, auto pred) {
    for (int it = 0; it < 200 && std::abs(fails - holds) > 1e-15; ++it) {
      const double mid = 0.5 * (holds + fails);
      if (pred(mid)) {
        holds = mid;
      } else {
        fails = mid;
      }
    }
    return holds;
  };
  auto inside_tooth = [&](double phi) {
    double rad = 0.0;
    return gap(phi, &rad) > 0.0;
  };
  constexpr int kSamples = 800;
  double best = rb;
  double prev_phi = 0.5 * kPi;
  double prev_r = 0.0;
  double prev_gap = gap(prev_phi, &prev_r);
  for (int k = 1; k <= kSamples; ++k) {
    const double phi = 0.5 * kPi - (0.5 * kPi - a0) * k / kSamples;
    double rad = 0.0;
    const double g = gap(phi, &rad);
    if (rad >= rb && g <= 0.0) {
      double lo = prev_phi;  // candidate start of the interval where the fillet is inside
      bool crossing = prev_r >= rb && prev_gap > 0.0;
      if (prev_r < rb) {
        // The fillet climbs through the base circle inside this step: start
        // from the point where it reaches r_b and ask whether it enters the
        // tooth there (the involute starts at the base circle).
        const double at_base = bisect(phi, prev_phi, [&](double q) {
          double rq = 0.0;
          gap(q, &rq);
          return rq >= rb;
        });
        double r_base = 0.0;
        crossing = gap(at_base, &r_base) > 0.0;
        lo = at_base;
      }
      if (crossing) {
        double r_cross = 0.0;
        gap(bisect(lo, phi, inside_tooth), &r_cross);
        best = std::max(best, r_cross);
      }
    }
    prev_phi = phi;
    prev_r = rad;
    prev_gap = g;
  }
  return {best, std::sqrt(std::max(best * best - rb * rb, 0.0)), true};
}

}  // namespace rackopt
