// The analytic mesh model beside the FE reference for one drive: N travel
// positions over one mesh period, at each the FE mesh state (K, load shares)
// and the FE single-tooth compliances of pinion and rack at every
// theoretical pair's contact, with the analytic numbers at the same travel
// and the error of each. What `rackopt fe` and a study's `verify: fe` show
// (docs/fe.md).
//
// Conventions (the FE models fix them; docs/fe.md says why):
//  * The rack body is rigid in the analytic model (effects.rack_span =
//    kRigid): the FE rack segment's base is fixed. With
//    FeOptions::rack_on_supports both codes put the rack on its hinges
//    instead (the coupled rack-span beam of the FE body's section; the FE
//    rack the whole span, fe/rack_span_fe.hpp). Every other effect stays
//    as the drive has it. Spalls and profile relief are removed from the
//    drive for both codes: the FE bodies carry neither (fe_reference_drive).
//  * Only the theoretical pairs (those MeshStiffnessModel::at has in mesh)
//    are compared; extended-contact pairs of the FE are reported beside.
//  * Pinion compliance = tooth (bending + shear + axial) + fillet foundation;
//    rack compliance = tooth (bending + shear + axial); Hertz is in K only.
//  * Errors: (analytic - FE) / FE for K and the compliances; for the load
//    shares, which are fractions of the same total already, the difference
//    analytic - FE (a relative error of a share near 0 means nothing).
//
// Example:
//   FeComparisonOptions opt;
//   opt.positions = 4;
//   opt.fe.level = 0;
//   FeComparison c = compare_with_fe(load_problem("problems/rack_small.yaml"), opt);
//   std::cout << c.summary.max_k_error << "\n";
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/fe/fe_options.hpp"
#include "rackopt/fe/mesh_position_fe.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::fe {

// The FE solves the comparison calls: the real ones (fe_mesh_position,
// fe_tooth_compliance) by default, fakes in tests. Both must be safe to call
// from several threads at once (the real ones are: Gmsh is serialized by
// the mesher, each ccx run has its own folder).
struct FeCalls {
  std::function<FePosition(const Drive&, double travel, const FeOptions&)> mesh_position;
  std::function<ToothComplianceFe(const Drive&, ToothMember, double s, const FeOptions&)> tooth_compliance;
};

// fe_mesh_position and fe_tooth_compliance.
FeCalls real_fe_calls();

constexpr int kMaxFePositions = 64;

struct FeComparisonOptions {
  int positions = 4;       // 1..kMaxFePositions, uniform over one mesh period
  FeOptions fe;            // level, extended contact, rack body depth, ccx
  unsigned threads = 0;    // solves at once; 0 = all cores. Results do not depend on it.
  FeCalls calls;           // an empty member = the real solve
  std::function<bool()> stop;  // polled before each solve; true = stop (throws Interrupted)
  // After each FE solve: solves done, solves in all. Called under a lock
  // (one thread at a time), from the worker threads.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// One theoretical pair at one position. Compliances in m/N (whole face width).
struct ComparedPair {
  int rack_tooth = 0, pinion_tooth = 0;
  int slot = 0;                  // PairState::slot: the CSV column group
  double s = 0;                  // LOA coordinate of the contact [m]
  bool carried_in_fe = false;    // the FE solution has this pair carrying load
  double share_fe = 0, share_analytic = 0, share_error = 0;     // error = analytic - FE
  // false when the pinion's contact lies off its involute (s <= 0 or below
  // the form circle: a path kept longer than the involute allows): no FE
  // single-tooth solve can load it, and pinion_fe / pinion_error stay 0.
  bool pinion_compared = true;
  double pinion_fe = 0, pinion_analytic = 0, pinion_error = 0;  // error = (analytic - FE) / FE
  double rack_fe = 0, rack_analytic = 0, rack_error = 0;
  double pinion_seconds = 0, rack_seconds = 0;  // wall time of each FE single-tooth solve
};

struct ComparedPosition {
  double travel = 0;              // X [m]
  double k_fe = 0, k_analytic = 0, k_error = 0;  // N/m; error = (analytic - FE) / FE
  double fe_force = 0;            // the FE's mesh force at its last step [N]
  std::vector<ComparedPair> pairs;      // the theoretical pairs, s descending (as MeshState)
  std::vector<FePair> extended_pairs;   // FE pairs off the theoretical ones (extended contact)
  double extended_share_fe = 0;         // their shares summed: the part of the mesh force they carry
  int nodes = 0, elements = 0;          // of the FE mesh-position model
  double fe_mesh_seconds = 0;     // wall time of the FE mesh-position solve
  double fe_tooth_seconds = 0;    // sum of the single-tooth solves of this position
  double analytic_seconds = 0;    // one MeshStiffnessModel::at (mean of repeated calls)
  // The FE meshes and displacements when options.fe.keep_shape, else null.
  std::shared_ptr<const DeformedShape> shape;
};

struct FeComparisonSummary {
  // Largest |error| over every position (and pair); 0 when nothing compared.
  double max_k_error = 0, max_share_error = 0, max_pinion_error = 0, max_rack_error = 0;
  double fe_mesh_seconds_per_position = 0;  // mean over the positions
  double fe_seconds_per_position = 0;       // mesh solve + single-tooth solves, mean
  double analytic_seconds_per_position = 0; // mean
  double time_ratio = 0;                    // fe_seconds_per_position / analytic_seconds_per_position
  double analytic_model_seconds = 0;        // building the analytic model (geometry, tooth tables), once
  double wall_seconds = 0;                  // the whole comparison, as run (threads)
};

struct FeComparison {
  double pitch = 0;                 // mesh period in travel [m]
  double period_start = 0;          // X_0: a pair enters mesh here (fe_positions)
  std::vector<double> travels;      // the positions compared
  FeOptions fe;                     // as run
  unsigned threads = 0;             // as run (after 0 = all cores)
  int slots = 0;                    // pair slots (floor(contact ratio) + 1)
  double contact_ratio = 0;
  std::vector<ComparedPosition> rows;  // travel order
  FeComparisonSummary summary;
  // The analytic K over [period_start, period_start + pitch]: uniform
  // samples plus both limits at every discontinuity (travel, K).
  std::vector<std::pair<double, double>> analytic_curve;
  std::vector<std::string> notes;   // the conventions in words, for every output
};

// `drive` as both codes see it: rack body rigid, no spalls (effects.spalling
// off), no profile relief on either member; every other effect as given.
Drive fe_reference_drive(const Drive& drive);

// The same for FE options `fe`: with fe.rack_on_supports the rack body is
// the coupled rack-span beam of the FE rack on its hinges instead of rigid
// (rack_on_supports_drive, fe/rack_span_fe.hpp); otherwise
// fe_reference_drive(drive).
Drive fe_reference_drive(const Drive& drive, const FeOptions& fe);

// The N travel positions over one mesh period of `model` (a model of
// fe_reference_drive): X_i = X_0 + (i + 1/2) p / N, where X_0 is the travel
// at which a pair enters mesh nearest the middle of the rack span (the
// period starts with the entering pair; cell midpoints keep every position
// off the discontinuities, where a contact sits on a tooth's tip corner).
// Without any entry in one period around mid-span (an integer contact
// ratio): X_0 = span / 2. `period_start` receives X_0.
std::vector<double> fe_positions(const MeshStiffnessModel& model, int positions, double* period_start = nullptr);

// (analytic - fe) / fe; NaN when fe is not a positive finite number.
double relative_error(double analytic, double fe);

// Runs the comparison. Throws std::invalid_argument for positions outside
// 1..kMaxFePositions or bad FE options, DesignError from the analytic model
// before any FE solve (and from the FE solves before their own work),
// CcxNotFound before any solve when ccx is missing (real solves only),
// CcxError from a failed solve (the first failing solve in position order,
// whatever the thread count), Interrupted when `stop` says so, and
// std::runtime_error when an FE solve returns a K or compliance that is not
// a positive finite number.
FeComparison compare_with_fe(const Drive& drive, const FeComparisonOptions& options);

}  // namespace rackopt::fe
