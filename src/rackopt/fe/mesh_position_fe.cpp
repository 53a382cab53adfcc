#include "rackopt/fe/mesh_position_fe.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "rackopt/fe/ccx_contact_deck.hpp"
#include "rackopt/fe/deformed_shape.hpp"
#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/fe/mesh_placement.hpp"
#include "rackopt/fe/gmsh_library.hpp"
#include "rackopt/fe/hertz_patch.hpp"
#include "rackopt/fe/rack_span_fe.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::fe {
namespace {

// Nested discs around a contact: size h_c doubling outwards (radius 4 sizes
// each) up to `outer_size`, so the elements grow geometrically away from it.
void contact_discs(std::vector<Refinement>& refs, Point2 at, double h_c, double outer_size) {
  for (double size = h_c; size < outer_size; size *= 2) refs.push_back({at, 4 * size, size});
}

// The rack segment that carries every pair in mesh (a position whose pairs
// straddle a joint between two spans is not modelled on supports).
int segment_of(const MeshState& state) {
  const int seg = state.pairs.front().segment;
  for (const PairState& p : state.pairs) {
    if (p.segment != seg) throw std::invalid_argument("rack on its supports: the pairs in mesh lie on two rack spans");
  }
  return seg;
}

// The stiffness that predicts the hub rotation for the drive's load: the
// analytic model of the same rack body as the FE one (rigid, or on its
// hinges) times the calibrated FE/analytic ratio of that model.
double predicted_fe_stiffness(const Drive& drive, const FeOptions& options, const MeshPositionTuning& tuning,
                              double travel, double rigid_stiffness) {
  if (!options.rack_on_supports) return tuning.predicted_stiffness_ratio * rigid_stiffness;
  return tuning.predicted_stiffness_ratio_on_supports *
         MeshStiffnessModel(rack_on_supports_drive(drive, options)).at(travel).stiffness;
}

}  // namespace

FePosition fe_mesh_position(const Drive& drive, double travel, const FeOptions& options) {
  return fe_mesh_position(drive, travel, options, MeshPositionTuning{});
}

FePosition fe_mesh_position(const Drive& drive, double travel, const FeOptions& options,
                            const MeshPositionTuning& tuning) {
  check_fe_options(options);
  if (!std::isfinite(travel)) throw std::invalid_argument("fe_mesh_position: the travel must be finite");
  if (!(tuning.penalty_factor > 0)) throw std::invalid_argument("fe_mesh_position: the penalty factor must be positive");
  if (!(tuning.predicted_stiffness_ratio > 0) || !(tuning.predicted_stiffness_ratio_on_supports > 0)) {
    throw std::invalid_argument("fe_mesh_position: the predicted stiffness ratio must be positive");
  }
  if (!(tuning.load_tolerance > 0)) throw std::invalid_argument("fe_mesh_position: the load tolerance must be positive");
  {
    const std::vector<double>& f = tuning.step_fractions;
    bool ok = f.size() >= 2 && f.front() > 0 && f.back() == 1.0;
    for (std::size_t k = 1; k < f.size(); ++k) ok = ok && f[k] > f[k - 1];
    if (!ok) {
      throw std::invalid_argument("fe_mesh_position: the step fractions must rise from above 0 to 1 (at least two)");
    }
  }
  const auto start = std::chrono::steady_clock::now();
  // The analytic model with a rigid rack body: the pairs, their shares for
  // sizing, and the stiffness that predicts the hub rotation for the load.
  Drive rigid = drive;
  rigid.effects.rack_span = RackSpanModel::kRigid;
  const MeshStiffnessModel model(rigid);  // DesignError for an impossible design
  const MeshGeometry& geo = model.geometry();
  const MeshState analytic = model.at(travel);
  if (analytic.pairs.empty() || !(analytic.stiffness > 0)) {
    throw std::runtime_error("fe_mesh_position: no pair in mesh at this travel");
  }
  const double m = drive.pinion.module, rb = geo.pinion.base_radius;
  const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
  const double width = std::min(drive.pinion.face_width, b_rack);  // as the analytic model's contact width
  double depth = options.rack_body_depth;
  if (depth <= 0) depth = drive.rack.body_height > 0 ? drive.rack.body_height : 2 * drive.rack.section.neutral_axis_depth;
  if (!(depth > 0)) throw std::invalid_argument("fe_mesh_position: the rack has no body depth (rack.body_height or its section)");

  // Sizes: the level's size on the loaded teeth, a fraction of the Hertz
  // half-width at the contacts (the smallest over the pairs at their
  // analytic share of the load), the hub and far teeth coarser.
  const double h = gear_element_size(m, options.level);
  const double e_star = effective_modulus(drive.pinion.material, drive.rack.material);
  double b_hertz = INFINITY;
  for (const PairState& p : analytic.pairs) {
    const double per_width = drive.load.force * std::max(p.load_share, 0.1) / width;
    const double R = patch_curvature_radius(p.s, m);
    b_hertz = std::min(b_hertz, hertz_half_width(per_width, R, e_star));
  }
  const double h_c = std::clamp(0.5 * b_hertz / std::pow(2.0, options.level), h / 64, h);
  const double far = 8 * h;

  const MeshPlacement pl =
      place_mesh(drive, model, travel, PlacementSpacing{2 * h, h_c, 0.2, far / 2}, depth, options.extended_contact,
                 options.rack_on_supports ? 1 : 0);
  if (options.rack_on_supports) {  // a position too near a hinge is refused before ccx is looked for
    (void)rack_span_outline(drive, geo, pl, segment_of(analytic), depth, tuning.hinge_patch_fraction * depth, far / 2);
  }
  find_ccx(options.ccx);  // CcxNotFound after the design checks, before the meshing
  (void)gmsh_api();       // GmshNotFound likewise
  const Point2 o = pl.pinion_centre;
  // The teeth in contact (and the neighbours that may touch) with their
  // fillets and roots at the level's size (gear_bodies' focus discs,
  // placed), the contacts finer.
  std::vector<Refinement> refs;
  const double cr = std::cos(pl.pinion_rotation), sr = std::sin(pl.pinion_rotation);
  for (const FlankContact& fc : pl.contacts) {
    Refinement r = pinion_focus_disc(drive.pinion, geo, fc.pinion_tooth, h);
    r.center = {o.x + r.center.x * cr - r.center.y * sr, o.y + r.center.x * sr + r.center.y * cr};
    refs.push_back(r);
    r = rack_focus_disc(geo, fc.rack_tooth - pl.first_rack_tooth, h);
    r.center.x += pl.rack_shift;
    refs.push_back(r);
    if (fc.theoretical) contact_discs(refs, fc.contact, h_c, h);
  }
  ContactModel cm;
  cm.bodies.push_back({"P", mesh_polygon_with_holes(pl.pinion.outer, pl.pinion.holes, far, refs),
                       drive.pinion.material.youngs_modulus, drive.pinion.material.poisson_ratio});
  SpanRackMesh span;
  if (options.rack_on_supports) {
    span = mesh_span_rack(drive, geo, pl, segment_of(analytic), depth, far, far / 2, refs, tuning.hinge_patch_fraction);
  }
  cm.bodies.push_back({"R", options.rack_on_supports ? span.mesh : mesh_polygon_with_holes(pl.rack.outer, pl.rack.holes, far, refs),
                       drive.rack.material.youngs_modulus, drive.rack.material.poisson_ratio});
  const Mesh2D& pinion = cm.bodies[0].mesh;
  const Mesh2D& rack = cm.bodies[1].mesh;

  // Hub rotation: the last step aims at the drive's load with the analytic
  // (rigid-body) stiffness times the calibrated FE/analytic ratio; the
  // earlier steps at the given fractions of it.
  const std::vector<double>& fr = tuning.step_fractions;
  cm.steps = static_cast<int>(fr.size());
  for (const FlankContact& c : pl.contacts) cm.contacts.push_back({0, c.pinion_set, 1, c.rack_set});
  cm.penalty_slope = tuning.penalty_factor * e_star / h_c;
  cm.reaction_sets = {{0, "BORE"}};
  cm.print_displacements = options.keep_shape;
  const std::vector<int>& bore = pinion.node_set("BORE");
  if (options.rack_on_supports)
    for (const NodeEquation& e : span.hinges.equations) cm.equations.push_back({1, e});
  std::vector<double> theta(fr.size()), F(fr.size());
  std::vector<ContactStepResult> r;
  const auto run = [&](double theta_last) {
    for (std::size_t k = 0; k < fr.size(); ++k) theta[k] = fr[k] * theta_last;
    cm.supports.clear();
    for (int n : bore) {
      const Point2 p = pinion.nodes[n];
      SteppedDisplacement u{0, n, 1, {}}, v{0, n, 2, {}};
      for (double t : theta) {
        u.values.push_back(-t * (p.y - o.y));
        v.values.push_back(t * (p.x - o.x));
      }
      cm.supports.push_back(u);
      cm.supports.push_back(v);
    }
    if (options.rack_on_supports) {
      for (const PrescribedDisplacement& d : span.hinges.supports)
        cm.supports.push_back({1, d.node, d.dof, std::vector<double>(fr.size(), 0.0)});
    } else {
      for (int n : rack.node_set("BASE")) {
        cm.supports.push_back({1, n, 1, std::vector<double>(fr.size(), 0.0)});
        cm.supports.push_back({1, n, 2, std::vector<double>(fr.size(), 0.0)});
      }
    }
    r = solve_contact(cm, options.ccx);
    // Torque of the hub on the pinion about its centre, per unit thickness,
    // and the mesh force along the line of action it balances.
    for (std::size_t k = 0; k < fr.size(); ++k) {
      double torque = 0;
      for (const auto& [n, f] : r[k].reactions[0]) {
        const Point2 p = pinion.nodes[n];
        torque += (p.x - o.x) * f.y - (p.y - o.y) * f.x;
      }
      F[k] = torque / rb;
    }
  };
  const double target = drive.load.force / width;  // per unit thickness, as F
  run(target / (predicted_fe_stiffness(drive, options, tuning, travel, analytic.stiffness) / width) / rb);
  int runs = 1;
  if (std::abs(F.back() / target - 1) > tuning.load_tolerance) {
    // Missed: aim again along the measured secant, F(theta) ~ a + k theta
    // (nearly linear once the flanks touch; a < 0 holds a micro-gap).
    const double k_sec = (F.back() - F.front()) / (theta.back() - theta.front());
    if (!(k_sec > 0)) throw std::runtime_error("fe_mesh_position: the hub rotation raised no mesh force");
    const double a = F.front() - k_sec * theta.front();
    run((target - a) / k_sec);
    runs = 2;
  }
  const double theta1 = theta.front(), theta2 = theta.back();

  FePosition out;
  out.travel = travel;
  out.stiffness = (F.back() - F.front()) / (rb * (theta2 - theta1)) * width;
  out.force = F.back() * width;
  out.load_fraction = out.force / drive.load.force;
  out.ccx_runs = runs;
  for (std::size_t k = 0; k < fr.size(); ++k) {
    out.step_rotations.push_back(theta[k]);
    out.step_forces.push_back(F[k] * width);
  }
  for (std::size_t k = 0; k < pl.contacts.size(); ++k) {
    const FlankContact& c = pl.contacts[k];
    // Frictionless contact on a straight rack flank: the force is along its normal, the LOA.
    const auto along = [&](int step) {
      const Point2 f = r[static_cast<std::size_t>(step)].contact_force[k];
      return std::abs(f.x * pl.loa_direction.x + f.y * pl.loa_direction.y);
    };
    const double f1 = along(0), f2 = along(cm.steps - 1);
    if (!c.theoretical && !(f2 > 1e-6 * F.back())) continue;  // a neighbour that stayed apart
    FePair p;
    p.rack_tooth = c.rack_tooth;
    p.pinion_tooth = c.pinion_tooth;
    p.s = c.s;
    p.theoretical = c.theoretical;
    p.load_share = (f2 - f1) / (F.back() - F.front());
    p.force = f2 * width;
    out.pairs.push_back(p);
  }
  std::sort(out.pairs.begin(), out.pairs.end(), [](const FePair& a, const FePair& b) { return a.s > b.s; });
  out.nodes = static_cast<int>(pinion.nodes.size() + rack.nodes.size());
  out.elements = static_cast<int>(pinion.triangles.size() + rack.triangles.size());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.keep_shape) {
    out.shape = std::make_shared<const DeformedShape>(make_deformed_shape(cm, r.back(), pl, m, options.level, theta2));
  }
  return out;
}

}  // namespace rackopt::fe
