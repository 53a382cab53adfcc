// How good a Pareto front is, as numbers a report can compare: the
// hypervolume it dominates (pagmo's exact algorithms), how evenly its points
// are spaced, and how many there are. docs/solvers.md ("Front quality")
// defines each and the reference point.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace rackopt::solvers {

// Every vector holds the minimized objectives of one front point, all of the
// same size (a maximized metric enters negated).
using ObjectiveVectors = std::vector<std::vector<double>>;

struct FrontQuality {
  std::size_t points = 0;          // vectors given
  std::size_t non_dominated = 0;   // of them, dominated by no other
  // The box the hypervolume is measured in: from `ideal` (the best of each
  // objective over the front) to `reference` (a point every front point
  // should dominate), both in the minimized objectives.
  std::vector<double> ideal, reference;
  // The volume dominated by the front inside that box, as a fraction of the
  // box (0 = nothing, 1 = the ideal point itself is on the front).
  double hypervolume = 0;
  // Schott's spacing on objectives normalized by their range over the front:
  // the standard deviation of each point's L1 distance to its nearest
  // neighbour (0 = evenly spaced; 0 for fewer than 3 points).
  double spacing = 0;
};

// The default reference point: the front's worst value of each objective
// plus 10 % of its range (of 1e-3 * max(1, |worst|) when the range is 0).
std::vector<double> default_reference_point(const ObjectiveVectors& front);

// The hypervolume dominated by `points` and bounded by `reference`: only
// points better than the reference in every objective count (the others
// add nothing). Exact (pagmo's WFG / HV2D / HV3D). 0 for no such point.
// Throws std::invalid_argument for vectors of other sizes than the reference.
double hypervolume(const ObjectiveVectors& points, std::span<const double> reference);

// Schott's spacing (see FrontQuality::spacing).
double spacing(const ObjectiveVectors& front);

// All of FrontQuality for `front`; an empty `reference` means the default.
// An empty front gives zeros.
FrontQuality front_quality(const ObjectiveVectors& front, std::span<const double> reference = {});

}  // namespace rackopt::solvers
