#include "rackopt/geometry/mesh_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/pinion_generation.hpp"

namespace rackopt {
namespace {

constexpr double kPi = std::numbers::pi;
// Contact ratios this close to an integer are that integer: designs built for
// eps = 1 or 2 must not fail or grow a 1e-16 zone from round-off.
constexpr double kIntegerSnap = 1e-9;
// The form circle counts as limiting the path only when it lies this far
// (relative to p_b) beyond the rack-tip point. This keeps a tip radius rounded
// to the usual 0.38 (exact limit 0.37995 at 20 deg) from moving the start by
// a few micrometres and flagging every standard drive.
constexpr double kFormTieRelative = 1e-4;

std::string mm(double metres) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g mm", metres * 1e3);
  return buf;
}
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void require(bool ok, const char* key, const std::string& message) {
  if (!ok) throw InputError(SourceMark{}, key, message);
}

void validate(const Drive& d) {
  const PinionSpec& p = d.pinion;
  require(p.teeth >= 1, "pinion.teeth", "must be at least 1, got " + std::to_string(p.teeth));
  require(std::isfinite(p.module) && p.module > 0, "pinion.module", "must be > 0");
  require(std::isfinite(p.pressure_angle) && p.pressure_angle > 0 &&
              p.pressure_angle <= kPi / 4 + 1e-12,
          "pinion.pressure_angle", "must be in (0, 45] deg, got " + num(p.pressure_angle) + " rad");
  require(std::isfinite(p.profile_shift), "pinion.profile_shift", "must be finite");
  require(std::isfinite(p.addendum_coef) && p.addendum_coef >= 0, "pinion.addendum_coef",
          "must be >= 0");
  require(std::isfinite(p.dedendum_coef) && p.dedendum_coef > 0, "pinion.dedendum_coef",
          "must be > 0");
  require(std::isfinite(p.tip_radius_coef) && p.tip_radius_coef >= 0, "pinion.tip_radius_coef",
          "must be >= 0");
  require(std::isfinite(d.rack.addendum_coef) && d.rack.addendum_coef >= 0, "rack.addendum_coef",
          "must be >= 0");
  require(std::isfinite(d.rack.dedendum_coef) && d.rack.dedendum_coef >= 0, "rack.dedendum_coef",
          "must be >= 0");
  require(std::isfinite(d.mounting.clearance), "mounting.clearance", "must be finite");
}

double snap_to_integer(double eps) {
  const double n = std::round(eps);
  return std::abs(eps - n) < kIntegerSnap ? n : eps;
}

}  // namespace

double MeshGeometry::contact_height_above_datum(double s) const {
  const double sa = std::sin(pressure_angle);
  return pinion.pitch_radius * sa * sa - s * sa + profile_shift_length + clearance;
}

double MeshGeometry::pinion_contact_radius(double s) const {
  return std::hypot(pinion.base_radius, s);
}

MeshGeometry build_mesh_geometry(const Drive& drive) {
  validate(drive);
  const PinionSpec& ps = drive.pinion;
  const RackSpec& rs = drive.rack;
  const double m = ps.module;
  const double z = ps.teeth;
  const double a0 = ps.pressure_angle;
  const double x = ps.profile_shift;
  const double delta = drive.mounting.clearance;
  const double sin_a = std::sin(a0);
  const double cos_a = std::cos(a0);
  const double tan_a = std::tan(a0);

  MeshGeometry g;
  g.pressure_angle = a0;
  g.clearance = delta;
  g.profile_shift_length = x * m;
  g.backlash = 2.0 * delta * tan_a;

  // --- cutter ---------------------------------------------------------------
  PinionGeometry& pin = g.pinion;
  pin.cutter_tip_radius = ps.tip_radius_coef * m;
  pin.cutter_tip_flat_half_width = cutter_tip_flat_half_width(ps);
  const double rho_flat_max = cutter_tip_radius_for_zero_flat(ps);
  if (rho_flat_max < 0.0) {
    throw DesignError("pointed_cutter",
                      "cutter tooth is pointed: its addendum h_a0* = " + num(ps.dedendum_coef) +
                          " exceeds pi/(4 tan a0) = " + num(kPi / (4.0 * tan_a)));
  }
  if (pin.cutter_tip_flat_half_width < 0.0) {
    throw DesignError("cutter_tip_radius",
                      "cutter tip radius " + mm(pin.cutter_tip_radius) +
                          " leaves no flat on the cutter tip (the two rounds overlap); at most " +
                          mm(rho_flat_max) + " fits");
  }
  const double c_star = ps.dedendum_coef - rs.addendum_coef;
  pin.cutter_tip_radius_max = std::max(c_star, 0.0) * m / (1.0 - sin_a);

  // --- rack -----------------------------------------------------------------
  RackGeometry& rack = g.rack;
  rack.pitch = kPi * m;
  rack.addendum = rs.addendum_coef * m;
  rack.dedendum = rs.dedendum_coef * m;
  rack.half_thickness_at_datum = kPi * m / 4.0;
  rack.half_thickness_at_root = rack.half_thickness_at_datum + rack.dedendum * tan_a;
  rack.half_thickness_at_tip = rack.half_thickness_at_datum - rack.addendum * tan_a;
  if (rack.half_thickness_at_tip <= 0.0) {
    throw DesignError("pointed_tooth", "rack tooth is pointed: tip half thickness " +
                                           mm(rack.half_thickness_at_tip) +
                                           " <= 0 (rack addendum too large for the pressure angle)");
  }
  const double rack_space_at_root = rack.pitch - 2.0 * rack.half_thickness_at_root;
  if (rack_space_at_root <= 0.0) {
    throw DesignError("rack_root_closed", "rack space width at the root line is " +
                                              mm(rack_space_at_root) +
                                              " <= 0: rack dedendum too deep for the pressure angle");
  }

  // --- pinion ---------------------------------------------------------------
  pin.pitch_radius = 0.5 * m * z;
  pin.base_radius = pin.pitch_radius * cos_a;
  pin.tip_radius = pin.pitch_radius + (ps.addendum_coef + x) * m;
  pin.root_radius = pin.pitch_radius - (ps.dedendum_coef - x) * m;
  if (pin.root_radius <= 0.0) {
    throw DesignError("no_root_circle", "pinion root radius " + mm(pin.root_radius) +
                                            " <= 0 (too few teeth for the dedendum)");
  }
  pin.half_base_angle = kPi / (2.0 * z) + (tan_a - a0) + 2.0 * x * tan_a / z;
  // Sainsot root angle with the TOOL addendum; independent of x (docs/models/tooth.md, docs/models/geometry.md).
  pin.root_angle = kPi / z - pin.cutter_tip_flat_half_width / pin.pitch_radius;
  if (pin.tip_radius <= pin.base_radius) {
    throw DesignError("no_involute", "pinion tip radius " + mm(pin.tip_radius) +
                                         " is not above the base radius " + mm(pin.base_radius));
  }
  pin.tip_thickness = 2.0 * pin.tip_radius * involute_half_angle(ps, pin.tip_radius);
  if (pin.tip_thickness <= 0.0) {
    throw DesignError("pointed_tooth", "pinion tooth is pointed: tip thickness " +
                                           mm(pin.tip_thickness) + " <= 0 at r_a = " +
                                           mm(pin.tip_radius));
  }
  const FormCircle form = generated_form_circle(ps);
  pin.form_radius = form.radius;
  pin.undercut = form.undercut;
  pin.undercut_teeth_limit = teeth_for_no_undercut(ps);
  if (pin.form_radius >= pin.tip_radius) {
    throw DesignError("no_involute", "form radius " + mm(pin.form_radius) +
                                         " is not below the tip radius " + mm(pin.tip_radius) +
                                         ": no involute left on the pinion");
  }
  if (pin.undercut) {
    g.warnings.push_back("pinion undercut: z = " + std::to_string(ps.teeth) + " < z_min = " +
                         num(pin.undercut_teeth_limit) + "; intact involute starts at r = " +
                         mm(pin.form_radius) + " (base circle " + mm(pin.base_radius) + ")");
  }
  if (pin.cutter_tip_radius > pin.cutter_tip_radius_max * (1.0 + 1e-3)) {
    g.warnings.push_back("cutter tip radius " + mm(pin.cutter_tip_radius) +
                         " exceeds c* m/(1 - sin a0) = " + mm(pin.cutter_tip_radius_max) +
                         ": the form circle rises above the rack tip contact at zero clearance");
  }

  // --- mounting ---------------------------------------------------------------
  if (delta < 0.0) {
    throw DesignError("negative_clearance",
                      "clearance " + mm(delta) +
                          " < 0: the teeth would overlap (clearance 0 is the zero-backlash mesh)");
  }
  const double datum_depth = pin.pitch_radius + x * m + delta;  // below the pinion centre
  const double rack_tip_depth = datum_depth - rack.addendum;
  if (rack_tip_depth < pin.root_radius) {
    throw DesignError("rack_tip_below_pinion_root",
                      "rack tip line is " + mm(pin.root_radius - rack_tip_depth) +
                          " inside the pinion root circle (rack addendum > cutter addendum - clearance)");
  }
  const double rack_root_depth = datum_depth + rack.dedendum;
  if (pin.tip_radius > rack_root_depth) {
    throw DesignError("pinion_tip_below_rack_root",
                      "pinion tip circle reaches " + mm(pin.tip_radius - rack_root_depth) +
                          " below the rack root line (rack dedendum too small)");
  }

  // --- path of contact (docs/models/geometry.md) --------------------------------------------
  ContactPath& path = g.path;
  path.base_pitch = kPi * m * cos_a;
  path.s_pitch = pin.pitch_radius * sin_a;
  path.s_rack_tip = path.s_pitch + ((x - rs.addendum_coef) * m + delta) / sin_a;
  path.s_end = std::sqrt(pin.tip_radius * pin.tip_radius - pin.base_radius * pin.base_radius);
  path.s_form = form.loa;
  path.contact_ratio_geometric =
      snap_to_integer((path.s_end - path.s_rack_tip) / path.base_pitch);
  if (drive.effects.interference_limit) {
    if (path.s_form <= path.s_rack_tip + kFormTieRelative * path.base_pitch) {
      path.s_start = path.s_rack_tip;
      path.start_limited_by = "rack_tip";
    } else if (path.s_form > 0.0) {
      path.s_start = path.s_form;
      path.start_limited_by = "form_circle";
    } else {
      path.s_start = 0.0;
      path.start_limited_by = "base_circle";
    }
    if (path.start_limited_by != "rack_tip") {
      g.warnings.push_back("interference: the rack tip would meet the pinion at s = " +
                           mm(path.s_rack_tip) + ", below the involute; contact starts at s = " +
                           mm(path.s_start) + " (" + path.start_limited_by + ")");
    }
  } else {
    path.s_start = path.s_rack_tip;
    path.start_limited_by = "rack_tip";
    if (path.s_form > path.s_rack_tip + kFormTieRelative * path.base_pitch) {
      g.warnings.push_back("interference ignored as requested: the rack tip meets the pinion at s = " +
                           mm(path.s_rack_tip) + ", below the form circle (s = " +
                           mm(path.s_form) + ")");
    }
    if (path.s_rack_tip < 0.0) {
      g.warnings.push_back("path of contact starts at s = " + mm(path.s_rack_tip) +
                           " behind the base circle: contacts below the base circle are "
                           "evaluated at the base circle");
    }
  }
  path.contact_ratio = snap_to_integer((path.s_end - path.s_start) / path.base_pitch);
  if (path.contact_ratio < 1.0) {
    throw DesignError("contact_ratio_below_one",
                      "contact ratio " + num(path.contact_ratio) + " < 1 (path " +
                          mm(path.s_start) + " to " + mm(path.s_end) + ", base pitch " +
                          mm(path.base_pitch) + ", start limited by " + path.start_limited_by +
                          ")");
  }

  // --- zones (docs/models/geometry.md) -------------------------------------------------
  const double eps = path.contact_ratio;
  const int n = static_cast<int>(std::floor(eps));
  auto make_zone = [&](int pairs, double loa) {
    Zone zone;
    zone.pairs = pairs;
    zone.length_loa = loa;
    zone.length_travel = loa / cos_a;
    zone.length_flank = loa * tan_a;
    zone.pinion_angle = loa / pin.base_radius;
    return zone;
  };
  if (n + 1 - eps > 0.0) g.zones.push_back(make_zone(n, (n + 1 - eps) * path.base_pitch));
  if (eps - n > 0.0) g.zones.push_back(make_zone(n + 1, (eps - n) * path.base_pitch));
  return g;
}

std::vector<PairCountChange> pair_count_changes(const MeshGeometry& geometry) {
  const ContactPath& path = geometry.path;
  const double eps = path.contact_ratio;
  const int n = static_cast<int>(std::floor(eps));
  std::vector<PairCountChange> changes;
  if (eps - n > 0.0) {
    changes.push_back({path.s_start, n + 1});
    changes.push_back({path.s_start + (eps - n) * path.base_pitch, n});
  } else {
    changes.push_back({path.s_start, n});
  }
  return changes;
}

std::vector<double> contact_positions(const MeshGeometry& geometry, double s_reference) {
  const ContactPath& path = geometry.path;
  std::vector<double> positions;
  if (!(path.base_pitch > 0.0) || !std::isfinite(s_reference)) return positions;
  // First pair at or after s_start, then step by p_b while below s_end.
  const double k = std::ceil((path.s_start - s_reference) / path.base_pitch);
  double s = s_reference + k * path.base_pitch;
  if (s < path.s_start) s += path.base_pitch;  // round-off guard
  for (; s < path.s_end; s += path.base_pitch) positions.push_back(s);
  return positions;
}

}  // namespace rackopt
