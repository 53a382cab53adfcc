// The mesh force law (mesh_force_law.hpp) tabulated from the static stiffness
// model over one rack span (docs/models/dynamics.md, "Mesh force law").
//
// Each pair in mesh becomes a slot with stiffness k_i = K stiffness_share_i
// (its part of the static mesh stiffness) and gap g_i = its profile relief,
// so that the law carries load.force at the static approach and its tangent
// there is the static K. Just outside the path of contact a pair can touch at
// a tooth corner (the pinion tip corner on the rack flank beyond s_end; the
// rack tip corner, or an undercut pinion's form corner, before s_start): two
// extra slots hold those corner contacts, with the gap the approach must close
// first, so that the mesh force stays continuous in travel when a pair enters
// or leaves the path under load.
//
// Example:
//   MeshStiffnessModel model(drive);
//   MeshForceLaw law = build_mesh_force_law(drive, model);
#pragma once

#include <optional>

#include "rackopt/core/drive.hpp"
#include "rackopt/dynamics/mesh_force_law.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt {

struct MeshForceLawOptions {
  // Corner contact just outside the path of contact (off: each pair enters
  // and leaves the law at the path ends with its full stiffness, a jump of
  // the force in travel at fixed approach).
  bool corner_contact = true;
  // A corner slot is kept while its geometric gap is below corner_reach times
  // F / K_local,min, the largest static deflection of the teeth alone (the
  // rack body's bending is common to neighbouring pairs and closes no corner
  // gap). Beyond it the slot is 0 (not touching). > 0.
  double corner_reach = 3.0;
};

// The law over travel [0, rack.span] (period = span, mesh_pitch = pi m),
// sampled where the stiffness curve is (positions_per_period per mesh period,
// 0 = the drive's numerics.positions_per_period, and both limits at every
// discontinuity), plus both limits where a corner slot starts or stops.
// Slots 0 .. S-1 are the curve's (PairState::slot, S = max_pairs); with
// corner contact, slot S is the pinion-tip-side corner pair (s > s_end) and
// S+1 the root-side one (s < s_start). backlash = 2 Delta sin(alpha), the
// circumferential backlash 2 Delta tan(alpha) along the line of action.
// `drive` must be model.drive(). Throws std::invalid_argument for a drive
// without a positive load.force or options out of range; DesignError and
// std::runtime_error from the stiffness model pass through.
MeshForceLaw build_mesh_force_law(const Drive& drive, const MeshStiffnessModel& model, int positions_per_period = 0,
                                  const MeshForceLawOptions& options = {});

// Which corner can touch outside the path of contact, and the gap it leaves.
// The approach delta is the pinion's rotation (times r_b) past its rigid-body
// position with the rack held, so a gap is the delta at which the corner
// touches the mating flank.
//  * s > s_end: the pinion tip corner (radius r_a) against the straight rack
//    flank: g = r_b asin(s / r_a) - s + r_b inv(alpha_a), tan alpha_a = s_end / r_b.
//  * s < s_start, start limited by the rack tip: the rack tip corner K against
//    the pinion involute: g = r_b (psi_K + inv alpha_K) - s, psi_K the polar
//    angle of K from the base-circle tangency point T of the line of action
//    and cos alpha_K = r_b / |K|.
//  * s < s_start, start limited by the form circle of an undercut pinion: the
//    form corner (radius r_form, where the undercut fillet cuts the involute)
//    against the rack flank, the first formula with r_form, while it touches
//    the flank below the rack tip, else the rack tip corner against the
//    involute (the smaller gap where both touch).
// Where the touching point leaves the straight rack flank (above its tip,
// into its root round) the flank line is taken as extended, so the gap stays
// continuous and growing. nullopt where no corner can touch: s inside the
// path; a start on or behind the base circle (interference ignored), or on
// the form circle of a pinion that is not undercut (the fillet there stands out of the involute: interference,
// not a corner); |s| >= the corner's radius; the rack tip corner beyond the
// pinion tip circle.
std::optional<double> corner_gap(const MeshGeometry& geometry, double s);

}  // namespace rackopt
