#include "rackopt/fe/mesh_position_fe.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "rackopt/fe/ccx_contact_deck.hpp"
#include "rackopt/fe/deformed_shape.hpp"
#include "rackopt/fe/gear_bodies.hpp"
#include "rackopt/fe/mesh_placement.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::fe {
namespace {

// Nested discs around a contact: size h_c doubling outwards (radius 4 sizes
// each) up to `outer_size`, so the elements grow geometrically away from it.
void contact_discs(std::vector<Refinement>& refs, Point2 at, double h_c, double outer_size) {
  for (double size = h_c; size < outer_size; size *= 2) refs.push_back({at, 4 * size, size});
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
    const double R = std::max(p.s, 0.1 * m);  // a contact at the base circle: no curvature to speak of
    b_hertz = std::min(b_hertz, std::sqrt(4 * per_width * R / (M_PI * e_star)));
  }
  const double h_c = std::clamp(0.5 * b_hertz / std::pow(2.0, options.level), h / 64, h);
  const double far = 8 * h;

  const MeshPlacement pl =
      place_mesh(drive, model, travel, PlacementSpacing{2 * h, h_c, 0.2, far / 2}, depth, options.extended_contact);
  find_ccx(options.ccx);  // CcxNotFound after the design checks, before the meshing
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
  cm.bodies.push_back({"R", mesh_polygon_with_holes(pl.rack.outer, pl.rack.holes, far, refs),
                       drive.rack.material.youngs_modulus, drive.rack.material.poisson_ratio});
  const Mesh2D& pinion = cm.bodies[0].mesh;
  const Mesh2D& rack = cm.bodies[1].mesh;

  // Hub rotation: theta2 aims at the drive's load with the analytic
  // (rigid-body) stiffness, theta1 at a fifth of it.
  const double theta2 = drive.load.force / analytic.stiffness / rb, theta1 = 0.2 * theta2;
  cm.steps = 2;
  for (int n : pinion.node_set("BORE")) {
    const Point2 p = pinion.nodes[n];
    cm.supports.push_back({0, n, 1, {-theta1 * (p.y - o.y), -theta2 * (p.y - o.y)}});
    cm.supports.push_back({0, n, 2, {theta1 * (p.x - o.x), theta2 * (p.x - o.x)}});
  }
  for (int n : rack.node_set("BASE")) {
    cm.supports.push_back({1, n, 1, {0, 0}});
    cm.supports.push_back({1, n, 2, {0, 0}});
  }
  for (const FlankContact& c : pl.contacts) cm.contacts.push_back({0, c.pinion_set, 1, c.rack_set});
  cm.penalty_slope = tuning.penalty_factor * e_star / h_c;
  cm.reaction_sets = {{0, "BORE"}};
  cm.print_displacements = options.keep_shape;
  const std::vector<ContactStepResult> r = solve_contact(cm, options.ccx);

  // Torque of the hub on the pinion about its centre, per unit thickness,
  // and the mesh force along the line of action it balances.
  double F[2];
  for (int k = 0; k < 2; ++k) {
    double torque = 0;
    for (const auto& [n, f] : r[k].reactions[0]) {
      const Point2 p = pinion.nodes[n];
      torque += (p.x - o.x) * f.y - (p.y - o.y) * f.x;
    }
    F[k] = torque / rb;
  }
  FePosition out;
  out.travel = travel;
  out.stiffness = (F[1] - F[0]) / (rb * (theta2 - theta1)) * width;
  out.force = F[1] * width;
  for (std::size_t k = 0; k < pl.contacts.size(); ++k) {
    const FlankContact& c = pl.contacts[k];
    // Frictionless contact on a straight rack flank: the force is along its normal, the LOA.
    const auto along = [&](int step) {
      const Point2 f = r[static_cast<std::size_t>(step)].contact_force[k];
      return std::abs(f.x * pl.loa_direction.x + f.y * pl.loa_direction.y);
    };
    const double f1 = along(0), f2 = along(1);
    if (!c.theoretical && !(f2 > 1e-6 * F[1])) continue;  // a neighbour that stayed apart
    FePair p;
    p.rack_tooth = c.rack_tooth;
    p.pinion_tooth = c.pinion_tooth;
    p.s = c.s;
    p.theoretical = c.theoretical;
    p.load_share = (f2 - f1) / (F[1] - F[0]);
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
