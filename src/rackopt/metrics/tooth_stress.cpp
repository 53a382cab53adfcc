#include "rackopt/metrics/tooth_stress.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt::metrics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kCriticalTangent = kPi / 6.0;  // ISO 6336-3: 30 deg to the tooth centre line

// Dolan-Broghamer stress correction as ISO 6336-3 writes it.
double stress_correction(double chord, double arm, double fillet_radius) {
  const double L = chord / arm;
  const double qs = chord / (2.0 * fillet_radius);
  return (1.2 + 0.13 * L) * std::pow(qs, 1.0 / (1.21 + 2.3 / L));
}

double form_factor(double chord, double arm, double load_angle, double module, double pressure_angle) {
  const double s = chord / module;
  return 6.0 * (arm / module) * std::cos(load_angle) / (s * s * std::cos(pressure_angle));
}

struct Derivs {
  ToothPoint p, d1, d2;
};

// Fillet point and its first two derivatives in phi (central differences; the
// fillet is an analytic function of phi, see fillet_point). Steps chosen so the
// truncation and rounding errors both stay below 1e-8 relative.
Derivs fillet_derivatives(const PinionSpec& pinion, double phi) {
  Derivs d;
  d.p = fillet_point(pinion, phi);
  const double h1 = 1e-6;
  const ToothPoint a = fillet_point(pinion, phi + h1), b = fillet_point(pinion, phi - h1);
  d.d1 = {(a.x - b.x) / (2 * h1), (a.y - b.y) / (2 * h1)};
  const double h2 = 1e-4;
  const ToothPoint c = fillet_point(pinion, phi + h2), e = fillet_point(pinion, phi - h2);
  d.d2 = {(c.x - 2 * d.p.x + e.x) / (h2 * h2), (c.y - 2 * d.p.y + e.y) / (h2 * h2)};
  return d;
}

// Angle between the fillet tangent at phi and the tooth centre line (y axis).
// Only the first derivative: the two points of fillet_derivatives' central
// difference, the same bits without the three points of the second
// derivative (the section search calls this some 500 times per design).
double tangent_angle(const PinionSpec& pinion, double phi) {
  const double h1 = 1e-6;
  const ToothPoint a = fillet_point(pinion, phi + h1), b = fillet_point(pinion, phi - h1);
  const double dx = (a.x - b.x) / (2 * h1), dy = (a.y - b.y) / (2 * h1);
  return std::atan2(std::abs(dx), std::abs(dy));
}

void check_factor(double v, const char* key) {
  if (!std::isfinite(v) || !(v > 0)) {
    throw InputError(SourceMark{"<metric options>", 0, 0}, key, "load factor must be > 0 and finite");
  }
}

}  // namespace

RootSection pinion_root_section(const PinionSpec& pinion, const MeshGeometry& g) {
  const double a0 = pinion.pressure_angle;
  // Walk from the root (phi = pi/2, tangent at 90 deg - theta_f to the centre
  // line) towards the flank (phi = a0) and stop at the first 30 deg tangent.
  constexpr int kSteps = 400;
  const double top = 0.5 * kPi;
  double prev_phi = top;
  double prev_f = tangent_angle(pinion, prev_phi) - kCriticalTangent;
  double lo = 0, hi = 0;
  bool found = false;
  for (int k = 1; k <= kSteps && !found; ++k) {
    const double phi = top - (top - a0) * k / kSteps;
    const double f = tangent_angle(pinion, phi) - kCriticalTangent;
    if (prev_f >= 0 && f <= 0) {
      hi = prev_phi;  // angle >= 30 deg
      lo = phi;       // angle <= 30 deg
      found = true;
    }
    prev_phi = phi;
    prev_f = f;
  }
  if (!found) {
    throw DesignError("stress_section",
                      "no point of the pinion fillet has a tangent at 30 deg to the tooth centre line: "
                      "the ISO critical section is undefined for this cutter");
  }
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (tangent_angle(pinion, mid) - kCriticalTangent >= 0) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  const double phi = 0.5 * (lo + hi);
  const Derivs d = fillet_derivatives(pinion, phi);
  const double speed = std::hypot(d.d1.x, d.d1.y);
  const double cross = std::abs(d.d1.x * d.d2.y - d.d1.y * d.d2.x);

  RootSection out;
  out.chord = 2.0 * d.p.x;
  out.height = d.p.y;
  out.fillet_radius = speed * speed * speed / cross;
  // Load at the pinion tip: load angle a_Fen = tan(a_a) - alpha_2 (docs/models/tooth.md, alpha_1 at the tip).
  const double ra = g.pinion.tip_radius, rb = g.pinion.base_radius;
  const double alpha2 = involute_half_angle(pinion, rb);
  out.load_angle = std::sqrt(ra * ra / (rb * rb) - 1.0) - alpha2;
  const ToothPoint tip = involute_point(pinion, ra);
  const double load_line_on_centre = tip.y - tip.x * std::tan(out.load_angle);
  out.arm = load_line_on_centre - out.height;
  out.form_factor = form_factor(out.chord, out.arm, out.load_angle, pinion.module, a0);
  out.stress_correction = stress_correction(out.chord, out.arm, out.fillet_radius);
  return out;
}

double rack_root_radius_limit(const MeshGeometry& g, double module) {
  const double a0 = g.pressure_angle;
  const double space_half_at_root = 0.5 * kPi * module - g.rack.half_thickness_at_root;
  return space_half_at_root * std::cos(a0) / (1.0 - std::sin(a0));
}

RootSection rack_root_section(const Drive& drive, const MeshGeometry& g, double rho) {
  const double a0 = g.pressure_angle;
  const double m = drive.pinion.module;
  const double wf = g.rack.half_thickness_at_root;
  // Root round tangent to the root line (y = 0) and the flank x = w_f - y tan a0;
  // its points C - rho (cos p, sin p), p in [a0, pi/2], have their tangent at p
  // to the centre line, so the 30 deg point is p = 30 deg (the flank/round
  // junction p = a0 when the flank itself is steeper than 30 deg to the centre line).
  const double xc = wf + rho * (1.0 - std::sin(a0)) / std::cos(a0);
  const double p = std::max(kCriticalTangent, a0);
  RootSection out;
  out.chord = 2.0 * (xc - rho * std::cos(p));
  out.height = rho * (1.0 - std::sin(p));
  out.fillet_radius = rho;
  out.load_angle = a0;  // the load is normal to the straight flank
  // Highest rack contact: the start of the path (docs/models/geometry.md: the height above the datum).
  const double yc = g.contact_height_above_datum(g.path.s_start) + g.rack.dedendum;
  const double wc = wf - yc * std::tan(a0);
  out.arm = yc - wc * std::tan(a0) - out.height;
  out.form_factor = form_factor(out.chord, out.arm, out.load_angle, m, a0);
  out.stress_correction = stress_correction(out.chord, out.arm, out.fillet_radius);
  return out;
}

double derived_face_load_factor_bending(const Drive& drive, double face_load_factor_contact) {
  const PinionSpec& pin = drive.pinion;
  const RackSpec& rack = drive.rack;
  const double b_rack = rack.face_width > 0 ? rack.face_width : pin.face_width;
  const double h_pinion = (pin.addendum_coef + pin.dedendum_coef) * pin.module;
  const double h_rack = (rack.addendum_coef + rack.dedendum_coef) * pin.module;
  const double bh = std::max(3.0, std::min(pin.face_width / h_pinion, b_rack / h_rack));
  // Written in 1/bh so that a degenerate tooth (bh -> inf) gives N_F -> 1, not inf/inf.
  const double nf = 1.0 / (1.0 + 1.0 / bh + 1.0 / (bh * bh));
  return std::pow(face_load_factor_contact, nf);
}

LoadFactors drive_load_factors(const Drive& drive) {
  const Load& l = drive.load;
  LoadFactors k;
  k.application = l.application_factor;
  k.dynamic = l.dynamic_factor;
  k.face_contact = l.face_load_factor;
  k.face_bending = l.face_load_factor_bending > 0 ? l.face_load_factor_bending
                                                  : derived_face_load_factor_bending(drive, l.face_load_factor);
  k.transverse_contact = l.transverse_load_factor;
  k.transverse_bending = l.transverse_load_factor;
  return k;
}

ToothStress tooth_stress(const Drive& drive, const MeshGeometry& g, const LoadFactors& k, double rack_root_radius) {
  check_factor(k.application, "application_factor");
  check_factor(k.dynamic, "dynamic_factor");
  check_factor(k.face_bending, "face_load_factor_bending");
  check_factor(k.transverse_bending, "transverse_load_factor_bending");
  check_factor(k.face_contact, "face_load_factor_contact");
  check_factor(k.transverse_contact, "transverse_load_factor_contact");
  if (!std::isfinite(drive.load.force) || !(drive.load.force > 0)) {
    throw InputError(SourceMark{drive.source_file, 0, 0}, "load.force", "stresses need a load > 0");
  }
  const PinionSpec& pin = drive.pinion;
  const double a0 = pin.pressure_angle;
  const double m = pin.module;
  const double eps = g.path.contact_ratio;
  if (!(eps < 4.0)) {
    throw DesignError("stress_method_range", "contact ratio " + std::to_string(eps) +
                                                 " >= 4: the ISO contact ratio factor Z_eps = sqrt((4 - eps)/3) "
                                                 "is undefined");
  }
  ToothStress out;
  out.tangential_force = drive.load.force * std::cos(a0);
  const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : pin.face_width;
  out.face_width = std::min(pin.face_width, b_rack);
  out.contact_ratio = eps;
  out.contact_ratio_factor = 0.25 + 0.75 / eps;

  out.pinion = pinion_root_section(pin, g);
  double rho = rack_root_radius > 0       ? rack_root_radius
               : drive.rack.root_radius > 0 ? drive.rack.root_radius
                                            : pin.tip_radius_coef * m;
  const double rho_max = rack_root_radius_limit(g, m);
  if (rho > rho_max) {
    rho = rho_max;
    out.rack_root_radius_clamped = true;
  }
  if (!(rho > 0)) {
    throw DesignError("rack_root_closed", "the rack space at the root line has no room for a root round");
  }
  out.rack_root_radius = rho;
  out.rack = rack_root_section(drive, g, rho);

  const double nominal = out.tangential_force / (out.face_width * m) * out.contact_ratio_factor;
  const double kf = k.application * k.dynamic * k.face_bending * k.transverse_bending;
  out.pinion_root_stress = nominal * out.pinion.form_factor * out.pinion.stress_correction * kf;
  out.rack_root_stress = nominal * out.rack.form_factor * out.rack.stress_correction * kf;

  const Material& m1 = pin.material;
  const Material& m2 = drive.rack.material;
  const double inv_estar = (1 - m1.poisson_ratio * m1.poisson_ratio) / m1.youngs_modulus +
                           (1 - m2.poisson_ratio * m2.poisson_ratio) / m2.youngs_modulus;
  out.elasticity_factor = std::sqrt(1.0 / (kPi * inv_estar));
  out.zone_factor = std::sqrt(2.0 / (std::cos(a0) * std::sin(a0)));
  out.contact_ratio_factor_contact = std::sqrt((4.0 - eps) / 3.0);
  const double d = m * pin.teeth;
  const double kh = k.application * k.dynamic * k.face_contact * k.transverse_contact;
  out.contact_stress = out.elasticity_factor * out.zone_factor * out.contact_ratio_factor_contact *
                       std::sqrt(out.tangential_force / (out.face_width * d)) * std::sqrt(kh);
  return out;
}

}  // namespace rackopt::metrics
