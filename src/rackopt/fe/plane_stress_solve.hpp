// Solving a plane-stress model with CalculiX: deck (ccx_deck.hpp), solve in
// its own folder (ccx_runner.hpp), .dat read back (ccx_dat.hpp), results per
// unit thickness.
#pragma once

#include <vector>

#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

struct PlaneStressResult {
  std::vector<Point2> displacement;  // per node (m)
  // Support forces per supported node (N per metre of thickness): what the
  // supports exert, loads applied on the node itself not included.
  std::vector<NodeLoad> reactions;
  Point2 total_reaction;             // their sum (N/m)
  double slice_thickness = 0;        // of the solved slice (m)
};

// Solves `model` on a slice of `slice_thickness` (m; <= 0: the default
// slice_thickness_for(model.mesh); a thick slice only to show the trap
// described in ccx_deck.hpp). Besides
// CcxError/CcxNotFound (ccx_runner.hpp) and std::invalid_argument
// (check_model), the result must balance: |applied + reactions| at most
// 1e-5 of the sum of the magnitudes of all loads and reactions (else the model was not properly supported,
// which the sparse solver may not notice), else CcxError with the deck kept.
PlaneStressResult solve_plane_stress(const PlaneStressModel& model, const CcxOptions& options = {},
                                     double slice_thickness = 0);

}  // namespace rackopt::fe
