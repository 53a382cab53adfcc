// What a pareto study says about its front besides the points: how good it
// is (hypervolume, spacing, count; solvers/front_quality.hpp), how the
// hypervolume grew with the evaluations, and why the front holds fewer
// points than requested when it does.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/solvers/front_quality.hpp"

namespace rackopt::study {

// One feasible evaluation of a study, in evaluation order: its 0-based
// evaluation index and its objectives minimized in their own units (a
// maximized metric negated).
using FeasibleObjectives = std::pair<std::size_t, std::vector<double>>;

struct FrontSummary {
  std::size_t requested = 0;  // pareto.points
  // Of the delivered front, on the objectives minimized in their own units
  // (a maximized metric negated): quality.ideal and quality.reference bound
  // the box the normalized hypervolume is measured in.
  solvers::FrontQuality quality;
  // The hypervolume (normalized, in quality's box) of every feasible design
  // evaluated so far, after history_evaluations[i] evaluations: at most 64
  // points, the last one after every evaluation. It can end above
  // quality.hypervolume when the front was thinned to `requested` points.
  std::vector<std::size_t> history_evaluations;
  std::vector<double> history_hypervolume;
  // Why the front has fewer than `requested` points: one line per cause
  // (a sub-problem without a feasible point, points dominated by another
  // combination's, a population run that found no more); empty otherwise.
  std::vector<std::string> shortfall;
};

// quality of `front` (minimized own-unit vectors) against `reference`
// (empty: the default of front_quality.hpp), then the history over
// `feasible_in_order` out of `total_evaluations`. Leaves `requested` and
// `shortfall` to the caller.
FrontSummary summarize_front(const std::vector<std::vector<double>>& front, std::span<const double> reference,
                             const std::vector<FeasibleObjectives>& feasible_in_order, std::size_t total_evaluations);

}  // namespace rackopt::study
