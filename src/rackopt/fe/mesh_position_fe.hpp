// The mesh at one travel position by FE: the whole pinion (bore driven by a
// rigid hub rotation) in contact with a rack segment (base fixed), solved by
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
  double force = 0;        // its normal force at the second step [N, whole face width]
};

struct FePosition {
  double travel = 0;          // X, as MeshStiffnessModel::at [m]
  double stiffness = 0;       // K = (F2 - F1) / (r_b (theta2 - theta1)) [N/m, whole face width]
  double force = 0;           // mesh force along the LOA at the second step [N]
  std::vector<FePair> pairs;  // ordered by s, descending (as MeshState)
  int nodes = 0, elements = 0;
  double seconds = 0;         // wall time of mesh + solve
  // The meshes and displacements at the last step when options.keep_shape,
  // else null (fe/deformed_shape.hpp).
  std::shared_ptr<const DeformedShape> shape;
};

// FE mesh state at travel X of `drive`: the pairs MeshStiffnessModel::at(X)
// has in mesh, placed so that each touches at its theoretical contact
// unloaded; the second step loads the mesh to about the drive's load.force.
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
};

// fe_mesh_position with explicit tuning.
FePosition fe_mesh_position(const Drive& drive, double travel, const FeOptions& options,
                            const MeshPositionTuning& tuning);

}  // namespace rackopt::fe
