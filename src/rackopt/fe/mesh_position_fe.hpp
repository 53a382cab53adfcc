// The mesh at one travel position by FE: the whole pinion (bore driven by a
// rigid hub rotation) in contact with a rack segment (base fixed; or, with
// FeOptions::rack_on_supports, the whole span on its hinges), solved by
// CalculiX with penalty contact in two load steps; the mesh stiffness is the
// secant between them, so an initial micro-gap does not enter it.
#pragma once

#include <memory>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_options.hpp"

namespace rackopt::fe {

struct DeformedShape;  // fe/deformed_shape.hpp

// One tooth pair that carries load in the FE solution.
struct FePair {
  int rack_tooth = 0;      // numbering as MeshStiffnessModel's PairState
  int pinion_tooth = 0;
  double s = 0;            // LOA coordinate of the theoretical contact [m]
  bool theoretical = true; // false: an extended-contact pair (neighbouring flanks)
  double load_share = 0;   // (f2 - f1) / (F2 - F1): the secant share of this pair
  double force = 0;        // its normal force at the last step [N, whole face width]
};

struct FePosition {
  double travel = 0;          // X, as MeshStiffnessModel::at [m]
  double stiffness = 0;       // K = (F2 - F1) / (r_b (theta2 - theta1)) [N/m, whole face width]
  double force = 0;           // mesh force along the LOA at the last step, F2 [N]
  double load_fraction = 0;   // F2 / load.force: how close the last step came to the drive's load
  std::vector<FePair> pairs;  // ordered by s, descending (as MeshState)
  // Every load step of the (last) ccx run: hub rotation [rad] and mesh force [N].
  std::vector<double> step_rotations, step_forces;
  int ccx_runs = 1;           // 2 when the first run missed the load by more than the tolerance
  int nodes = 0, elements = 0;
  double seconds = 0;         // wall time of mesh + solve(s)
  // The meshes and displacements at the last step when options.keep_shape,
  // else null (fe/deformed_shape.hpp).
  std::shared_ptr<const DeformedShape> shape;
};

// FE mesh state at travel X of `drive`: the pairs MeshStiffnessModel::at(X)
// has in mesh, placed so that each touches at its theoretical contact
// unloaded; the last step loads the mesh to the drive's load.force within
// MeshPositionTuning::load_tolerance (the hub rotation is predicted from the
// analytic stiffness times a calibrated ratio; a run that misses is repeated
// once with the rotation corrected by its own secant, see ccx_runs).
// Throws DesignError before any FE work, CcxNotFound / CcxError from the
// solve (non-convergence included: the deck is kept).
FePosition fe_mesh_position(const Drive& drive, double travel, const FeOptions& options = {});

// Knobs of the solve that are fixed in normal use, open for the checks that
// the results do not depend on them (docs/models/fe_reference.md, "Mesh
// positions").
struct MeshPositionTuning {
  // Contact penalty slope = penalty_factor * E* / (element size at the
  // contacts) [Pa/m]: the overclosure at the Hertz peak pressure is then
  // about F'/(pi penalty_factor E*), some 1e-3 of the mesh deflection at 30.
  double penalty_factor = 30;
  // The predicted FE/analytic stiffness ratio: the last step's hub rotation
  // is load.force / (ratio K_an r_b), K_an the analytic mesh stiffness with a
  // rigid rack body of the drive's own effects. With the FE-grade pair
  // compliance (the default effects) K_an is within a few per cent of FE
  // (docs/models/fe_calibration.md), so 1; a drive analysed with the
  // papers' tooth model needs about 0.6 (docs/models/fe_reference.md,
  // "Load level"). Positions within load_tolerance of it take one run.
  double predicted_stiffness_ratio = 1.0;
  // |F2 / load.force - 1| above this: the solve is run once more with the
  // rotations scaled by the measured secant (the mesh is reused).
  double load_tolerance = 0.1;
  // The load steps as fractions of the last step's hub rotation, rising,
  // ending at 1; K and the shares are the secant between the first and the
  // last. More steps cost one more ccx step each (the load-window checks).
  std::vector<double> step_fractions = {0.2, 1.0};
  // FeOptions::rack_on_supports: half height of each hinge patch as a
  // fraction of the rack body depth (fe/rack_span_fe.hpp).
  double hinge_patch_fraction = 0.1;
  // FeOptions::rack_on_supports: K_FE / K_analytic with the coupled
  // rack-span beam (effects.supported_rack on: within a few per cent,
  // docs/models/rack_span.md "Against FE"), which predicts the hub
  // rotation instead.
  double predicted_stiffness_ratio_on_supports = 1.0;
};

// fe_mesh_position with explicit tuning.
FePosition fe_mesh_position(const Drive& drive, double travel, const FeOptions& options,
                            const MeshPositionTuning& tuning);

}  // namespace rackopt::fe
