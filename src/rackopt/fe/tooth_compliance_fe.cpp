#include "rackopt/fe/tooth_compliance_fe.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/fe/hertz_patch.hpp"
#include "rackopt/fe/plane_stress_solve.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/geometry/pinion_generation.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/stiffness/pinion_tooth.hpp"
#include "rackopt/stiffness/rack_tooth.hpp"

namespace rackopt::fe {
namespace {

// Away from the focus teeth the elements grow to min(6 x the level's size,
// module): the module at level 0. Against 4 x the size this moves the
// railway pinion's compliance by 1e-4 (docs/models/fe_reference.md).
constexpr double kCoarseFactor = 6;

std::string mm(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v * 1e3 << " mm";
  return o.str();
}

double rack_face_width(const Drive& drive) {
  return drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
}

void check_contact(const MeshGeometry& g, ToothMember member, double s) {
  const ContactPath& path = g.path;
  const double tol = 1e-9 * path.base_pitch;
  if (!std::isfinite(s) || s < path.s_start - tol || s > path.s_end + tol) {
    throw std::invalid_argument("FE tooth compliance: s = " + mm(s) + " is outside the path of contact " + mm(path.s_start) +
                                " .. " + mm(path.s_end));
  }
  if (member == ToothMember::kPinion && !pinion_contact_on_involute(g, s)) {
    throw std::invalid_argument("FE tooth compliance: s = " + mm(s) + " puts the pinion contact off its involute (s <= 0 "
                                "or below the form circle " + mm(g.pinion.form_radius) + "): nothing to load there");
  }
}

// Where a load line (through `p` along `d`) crosses the vertical line x = x_axis.
Point2 crossing(Point2 p, Point2 d, double x_axis) {
  const double lambda = (x_axis - p.x) / d.x;
  return {p.x + lambda * d.x, p.y + lambda * d.y};
}

// Discs around the Hertz patch: b_H / 3 within 3 b_H (six elements across
// the patch), then 4 b_H / 3 within 12 b_H, so the mesh grades down to the
// level's size without a steep jump.
std::vector<Refinement> patch_discs(Point2 centre, double half_width, double level_size) {
  std::vector<Refinement> discs{{centre, 3 * half_width, half_width / 3}};
  if (4 * half_width / 3 < level_size) discs.push_back({centre, 12 * half_width, 4 * half_width / 3});
  return discs;
}

}  // namespace

bool pinion_contact_on_involute(const MeshGeometry& g, double s) {
  return s > 0 && g.pinion_contact_radius(s) >= g.pinion.form_radius * (1 - 1e-12);
}

double patch_curvature_radius(double s, double module) { return std::max(s, 0.1 * module); }

double analytic_tooth_compliance(const Drive& drive, ToothMember member, double s) {
  const MeshGeometry g = build_mesh_geometry(drive);
  // The FE rack segment's base is held: the rack foundation of a held body,
  // not the local one of a rack on its supports (stiffness/supported_rack.hpp).
  Drive held = drive;
  held.effects.rack_span = RackSpanModel::kRigid;
  // The fillet foundation at the pinion's own face width, as the FE pinion is loaded.
  const PairTeeth t = PairCompliance(held, g).teeth(s, nullptr, nullptr, drive.pinion.face_width);
  if (member == ToothMember::kPinion) return t.pinion.total() + t.fillet;
  return t.rack.total() + t.rack_foundation;
}

ToothComplianceFe fe_tooth_compliance(const Drive& drive, ToothMember member, double s, const FeOptions& options) {
  check_fe_options(options);
  const MeshGeometry g = build_mesh_geometry(drive);
  check_contact(g, member, s);
  const double force = drive.load.force;
  if (!(force > 0) || !std::isfinite(force)) {
    throw std::invalid_argument("FE tooth compliance: the drive's load.force must be positive");
  }
  const auto t0 = std::chrono::steady_clock::now();
  const double e_star = effective_modulus(drive.pinion.material, drive.rack.material);
  const double size = gear_element_size(drive.pinion.module, options.level);

  ToothComplianceFe out;
  out.member = member;
  out.s = s;
  PlaneStressModel model;
  Point2 direction;
  double force_per_width = 0;
  if (member == ToothMember::kPinion) {
    const PinionSpec& pinion = drive.pinion;
    if (!(pinion.bore_radius > 0)) {
      throw std::invalid_argument("FE tooth compliance: the pinion needs a bore (pinion.bore_radius) to be held by");
    }
    const double radius = std::min(g.pinion_contact_radius(s), g.pinion.tip_radius);
    out.load_point = {involute_point(pinion, radius).x, involute_point(pinion, radius).y};
    // The load acts along the involute's normal, the line of action: from the
    // contact to its tangency point T on the base circle (OT at the angle
    // alpha_R = acos(r_b / R) from OP). Of the two tangents, the one into the
    // tooth: the flank runs outwards in the counter-clockwise outline, so the
    // material lies on the left of its tangent.
    const double dr = 1e-7 * radius;
    const ToothPoint lo = involute_point(pinion, radius - dr);
    const Point2 inward{-(out.load_point.y - lo.y), out.load_point.x - lo.x};
    const double polar = std::atan2(out.load_point.y, out.load_point.x);
    const double alpha = std::acos(std::min(1.0, g.pinion.base_radius / radius));
    double best = -std::numeric_limits<double>::infinity();
    for (double sign : {-1.0, 1.0}) {
      const Point2 t{g.pinion.base_radius * std::cos(polar + sign * alpha),
                     g.pinion.base_radius * std::sin(polar + sign * alpha)};
      const double dx = t.x - out.load_point.x, dy = t.y - out.load_point.y, n = std::hypot(dx, dy);
      const double along = (dx * inward.x + dy * inward.y) / n;
      if (along > best) {
        best = along;
        direction = {dx / n, dy / n};
      }
    }
    force_per_width = force / pinion.face_width;
    out.hertz_half_width = hertz_half_width(force_per_width, patch_curvature_radius(s, drive.pinion.module), e_star);
    out.read_point = crossing(out.load_point, direction, 0.0);
    MeshGrading grading;
    const int z = pinion.teeth;
    grading.focus_teeth = {0};
    if (z >= 2) grading.focus_teeth.push_back(1);
    if (z >= 3) grading.focus_teeth.push_back(z - 1);
    grading.coarse_factor = kCoarseFactor;
    grading.refinements = patch_discs(out.load_point, out.hertz_half_width, size);
    model.mesh = mesh_pinion_body(pinion, g, pinion.bore_radius, options.level, grading);
    model.youngs_modulus = pinion.material.youngs_modulus;
    model.poisson_ratio = pinion.material.poisson_ratio;
    fix_node_set(model, "BORE", 1);
    fix_node_set(model, "BORE", 2);
    model.loads = hertz_patch_loads(model.mesh, "T0_FLANK_R", out.load_point, direction, out.hertz_half_width,
                                    force_per_width);
  } else {
    const RackSpec& rack = drive.rack;
    double depth = options.rack_body_depth;
    if (!(depth > 0)) depth = rack.body_height > 0 ? rack.body_height : 2 * rack.section.neutral_axis_depth;
    if (!(depth > 0)) throw std::invalid_argument("FE tooth compliance: the rack has no body depth to mesh");
    const RackGeometry& r = g.rack;
    const double a0 = g.pressure_angle;
    const double y = g.contact_height_above_datum(s);
    const int side_teeth = rack_teeth_each_side(depth, r.pitch), loaded = side_teeth;
    const double xc = (loaded + 0.5) * r.pitch;
    out.rack_teeth = 2 * side_teeth + 1;
    out.load_point = {xc - r.half_thickness_at_root + (y + r.dedendum) * std::tan(a0), y};
    direction = {std::cos(a0), -std::sin(a0)};  // the mesh force on the rack (core/drive.hpp)
    force_per_width = force / rack_face_width(drive);
    out.hertz_half_width = hertz_half_width(force_per_width, patch_curvature_radius(s, drive.pinion.module), e_star);
    out.read_point = crossing(out.load_point, direction, xc);
    MeshGrading grading;
    // The loaded tooth alone: its neighbours fine too move the compliance by 1e-4.
    grading.focus_teeth = {loaded};
    grading.coarse_factor = kCoarseFactor;
    grading.refinements = patch_discs(out.load_point, out.hertz_half_width, size);
    model.mesh = mesh_rack_segment(g, 2 * side_teeth + 1, depth, options.level, grading, rack.root_radius);
    model.youngs_modulus = rack.material.youngs_modulus;
    model.poisson_ratio = rack.material.poisson_ratio;
    fix_node_set(model, "BASE", 1);
    fix_node_set(model, "BASE", 2);
    model.loads = hertz_patch_loads(model.mesh, "T" + std::to_string(loaded) + "_FLANK_L", out.load_point,
                                    direction, out.hertz_half_width, force_per_width);
  }
  const PlaneStressResult result = solve_plane_stress(model, options.ccx);
  const Point2 u = model.mesh.interpolate(result.displacement, out.read_point);
  // Per unit thickness under F' = F / b: u / F is the whole face width's compliance.
  out.compliance = (u.x * direction.x + u.y * direction.y) / force;
  out.nodes = static_cast<int>(model.mesh.nodes.size());
  out.elements = static_cast<int>(model.mesh.triangles.size());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.analytic = analytic_tooth_compliance(drive, member, s);
  return out;
}

}  // namespace rackopt::fe
