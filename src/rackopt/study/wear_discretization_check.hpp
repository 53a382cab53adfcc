// The discretization error of an optimum's active wear-life constraints,
// estimated by one refinement: the best design re-evaluated once with twice
// the wear profile points (docs/accuracy.md, "Profile points"; docs/output.md).
// An optimizer drives a constrained life exactly onto its bound, so the
// model's discretization error at that design is the amount by which the
// design may really miss it.
#pragma once

#include <vector>

#include "rackopt/study/optimum_explanation.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::study {

// The metrics whose value depends on wear.profile_points: wear_life,
// wear_life_cycles and wear_life_at_R.
bool is_wear_life_metric(const std::string& metric_name);

// For every active constraint of `explanation` (explain_optimum at x) on a
// wear-life metric: evaluates x once more with wear.profile_points doubled
// (capped at the key's largest value, 2000; nothing when it is already
// there) and fills the constraint's `discretization`. One extra evaluation
// of every metric of the design when some constraint qualifies, none
// otherwise; a refined evaluation that fails leaves the fields empty and
// says why in the explanation's note. Deterministic (the life at R reuses
// the same samples: only the discretization differs).
void check_wear_discretization(const StudyProblem& problem, const std::vector<double>& x,
                               OptimumExplanation& explanation, unsigned threads = 1);

}  // namespace rackopt::study
