// The report's lines for the discretization error of an optimum's active
// wear-life constraints (study/wear_discretization_check.hpp): one
// refinement of the wear profile points at the best design.
#pragma once

#include <string>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study/optimum_explanation.hpp"

namespace rackopt::study_report {

// A paragraph for report.md, e.g.
//   "Discretization error at the optimum (one refinement: ...):
//    - wear_life_at_R(0.9): 20 yr, discretization error -0.3 % (60 -> 120 profile points: 20.06 yr)"
// "" when no constraint carries one.
std::string discretization_markdown(const study::OptimumExplanation& explanation);

// The value of a constraint's "discretization" member in summary.json:
// {setting, points, refined_points, refined_value, relative_error}.
void discretization_json(JsonWriter& j, const study::DiscretizationError& d);

}  // namespace rackopt::study_report
