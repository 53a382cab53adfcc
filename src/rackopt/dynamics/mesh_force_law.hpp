// The force-deflection law of the mesh along the travel, as the dynamic
// model reads it (docs/models/dynamics.md): at travel X the mesh force for
// the approach delta (along the line of action) is
//   front flank:  F = sum_i k_i(X) max(0, delta - g_i(X))
//   back flank:   F = -sum_i k_i(X) max(0, -delta - backlash - g_i(X))   (same terms mirrored)
// where each term i ("slot") is one tooth pair that can touch at X: its
// stiffness k_i [N/m] and the gap g_i >= 0 [m] it must close before it
// carries load (profile relief, or the corner contact just outside the path
// of contact). Gaps of pairs inside the path without relief are 0, so a
// law without relief is F = K(X) delta for delta >= 0.
//
// The law is tabulated once per design from the static model
// (build_mesh_force_law, mesh_force_law_builder.hpp) and interpolated here:
// the dynamic model never runs the stiffness model per time step.
#pragma once

#include <limits>
#include <vector>

namespace rackopt {

struct MeshForceLaw {
  // The law repeats along the travel with this period [m] (one rack support span).
  double period = 0;
  // Mesh pitch along the travel (p = pi m) [m]: the mesh order's wavelength.
  double mesh_pitch = 0;
  // Samples ascending in [0, period]; a jump is two samples at the same
  // travel, the left limit first. Between samples each slot's k and g are
  // linear in X.
  std::vector<double> travel;
  int slots = 0;
  std::vector<double> stiffness;  // travel.size() * slots, row major [N/m]; 0 = slot not touching
  std::vector<double> gap;        // travel.size() * slots [m]
  // Free play between front- and back-flank contact along the line of
  // action (the normal backlash) [m]; infinity = the back flank never touches.
  double backlash = std::numeric_limits<double>::infinity();

  // Force [N] at travel X (any real: reduced modulo period) and approach delta [m].
  double force(double travel_X, double delta) const;
  // dF/d delta there [N/m] (0 while the flanks are apart).
  double tangent(double travel_X, double delta) const;
  // Sum of the slot stiffnesses at X: the law's tangent once every gap is closed [N/m].
  double full_stiffness(double travel_X) const;
  // The approach at which the front flank carries `force` at X (F(X, delta) = force, force >= 0) [m].
  double approach_at(double travel_X, double force) const;
  // Mean of full_stiffness over the period (trapezoid over the samples) [N/m].
  double mean_stiffness() const;
  // Throws std::invalid_argument when sizes disagree, the period or a
  // stiffness is not finite and positive where it must be, travel is not
  // ascending, or a gap is negative.
  void validate() const;
};

}  // namespace rackopt
