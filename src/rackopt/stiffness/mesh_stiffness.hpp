// Time-varying mesh stiffness of a rack drive over the travel along one rack
// span: the pairs in mesh at each position, each pair's local compliance
// (pair_compliance.hpp: pinion tooth, fillet foundation, contact, rack tooth
// and its foundation), the rack body shared by
// all pairs through one flexibility matrix, the mesh stiffness and each pair's
// load share (docs/models/rack_span.md, docs/models/geometry.md).
//
// Example:
//   Drive drive = load_problem("problems/rack_railway.yaml");
//   MeshStiffnessModel model(drive);          // geometry, tooth tables, checks
//   StiffnessCurve curve = model.curve();     // whole travel over one span
//   std::cout << curve.k_min << " N/m at X = " << curve.travel_at_min << " m\n";
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

// One tooth pair in mesh at one travel position. Compliances in m/N.
struct PairState {
  int rack_tooth = 0;    // global rack tooth index (0 = first tooth of the studied segment)
  int pinion_tooth = 0;  // 0..z-1; pinion tooth 0 meshes with rack tooth 0
  int slot = 0;          // column in the CSV: rack_tooth mod (floor(eps)+1), stable while in mesh
  double s = 0;          // LOA coordinate of the contact [m]
  double x = 0;          // rack-fixed abscissa of the contact [m] (global)
  int segment = 0;       // rack segment that carries the contact
  double a = 0;          // abscissa within that segment [m]
  double e = 0;          // contact height above the rack neutral axis [m]
  ToothCompliance pinion;
  double fillet = 0;
  double hertz = 0;
  ToothCompliance rack;
  double rack_foundation = 0;  // the rack tooth's foundation in its body
  double body = 0;       // diagonal of the body flexibility matrix (own load on own contact)
  bool spalled = false;  // a spall changes this pair at this position
  double relief = 0;     // profile relief at this contact: gap to close before it carries load [m]
  double local() const { return pinion.total() + fillet + hertz + rack.total() + rack_foundation; }
  // f_j / F under load.force. Contact is unilateral: 0 when the rack body
  // carries this contact away from the pinion faster than the common
  // approach (the pair opens), or when its relief is not closed.
  double load_share = 0;
  // This pair's part of the mesh stiffness K: (C_A^-1 1)_i / K over the pairs
  // that carry load (C_A their flexibility matrix), so that
  // sum_i K stiffness_share_i (delta - relief_i) = load.force at the static
  // approach. Equals load_share without relief (f = delta C_A^-1 1 there); 0
  // for a pair that carries no load. The dynamic model's mesh force law reads
  // it (dynamics/mesh_force_law_builder.hpp).
  double stiffness_share = 0;
};

// Mesh state at one travel position X.
// With profile relief the state is the loaded one (load.force): K is the
// tangent stiffness dF/d(delta) of the pairs that carry load, which equals
// the unloaded K wherever every pair in mesh carries load
// (docs/models/transmission_error.md).
struct MeshState {
  double travel = 0;         // X [m]
  double stiffness = 0;      // K_mesh [N/m]
  // Mesh deflection (approach) along the line of action that carries
  // load.force: the static transmission error [m]. F/K without relief.
  double approach = 0;
  // Sum of 1/local compliance: the mesh with a rigid rack body [N/m] (with
  // profile relief: over the pairs that carry load).
  double local_stiffness = 0;
  std::vector<PairState> pairs;  // ordered by s, descending (nearest the pinion tip first)
};

struct StiffnessCurve {
  // Samples sorted by travel. At a discontinuity (a pair enters or leaves, a
  // contact crosses a support) two samples share the travel value: the left
  // and the right limit, in that order. With profile relief a relieved pair
  // starting or stopping to carry load is a discontinuity too: its two
  // limits lie within 1e-9 p of each other (found by bisection).
  std::vector<MeshState> samples;
  std::vector<double> breakpoints;  // travel positions of the discontinuities in [0, span]
  double k_min = 0, k_max = 0, k_mean = 0;
  double travel_at_min = 0, travel_at_max = 0;
  double k_fluctuation = 0;  // (k_max - k_min) / k_mean
  int max_pairs = 0;         // CSV slot count
  std::vector<std::string> warnings;
};

// What curve() keeps of each sample.
enum class CurveDetail {
  kFull,     // every sample with its pairs (the CSV, plots, the FE comparison)
  kSummary,  // each sample's travel, stiffness, approach and local_stiffness, no
             // pairs: what the stiffness metrics, the KS aggregates and the
             // per-period statistics read. Same values as kFull, bit for bit;
             // a curve without relief then allocates nothing per sample.
};

class MeshStiffnessModel {
 public:
  // Builds the geometry and the tooth models and checks the spalls. Throws
  // DesignError for an impossible design or fault.
  explicit MeshStiffnessModel(const Drive& drive);
  // The same with the drive's geometry built already: `geometry` must be
  // build_mesh_geometry(drive). A caller that needed it anyway saves
  // building it again: nearly all of the model's construction (the
  // undercut search), about a tenth of a design with its curve.
  MeshStiffnessModel(const Drive& drive, MeshGeometry geometry);
  ~MeshStiffnessModel();
  MeshStiffnessModel(MeshStiffnessModel&&) noexcept;
  MeshStiffnessModel& operator=(MeshStiffnessModel&&) noexcept;

  const Drive& drive() const;
  const MeshGeometry& geometry() const;
  const std::vector<std::string>& warnings() const;

  // State at travel X. side = -1 / +1 picks the left / right limit when X is
  // exactly at a discontinuity (0: right limit).
  MeshState at(double travel, int side = 0) const;
  // Only K_mesh at X (no per-pair details kept).
  double stiffness(double travel, int side = 0) const;

  // The whole travel over one span, sampled at numerics.positions_per_period
  // per mesh period plus every discontinuity (including, with relief, the
  // load switches of relieved pairs); min, max (refined inside smooth
  // pieces) and mean (piecewise cubic quadrature) do not depend on where the
  // uniform samples fall. CurveDetail::kSummary leaves every sample's
  // `pairs` empty (k_min, k_max, k_mean, the breakpoints and the samples'
  // own values are the same). positions_per_period > 0 samples that many
  // per period instead of the drive's numerics.positions_per_period (the
  // metrics of a study may ask for fewer than its plots; accepted range as
  // the problem key's, 4 ... 10000); 0 keeps the drive's.
  StiffnessCurve curve(CurveDetail detail = CurveDetail::kFull, int positions_per_period = 0) const;

  // Travel positions in [lo, hi] where the number of pairs changes or a
  // contact crosses a support.
  std::vector<double> breakpoints(double lo, double hi) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rackopt
