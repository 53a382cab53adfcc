// The stiffness curve of a study's best (pareto: chosen) design, for the
// report's stiffness.csv and stiffness.png (docs/output.md, "Study
// results"). The runner computes it so that presenting a result never runs a
// physics model.
#pragma once

#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// Sets result.best_curve to the curve of result.best_drive when
// spec.output.stiffness_curve is on and result.best_drive is set; nothing
// otherwise (a curve nobody asked for costs no time). When the model refuses
// the design (DesignError), best_curve stays empty and best_curve_error
// holds the warning for the report. Any other exception propagates.
void attach_best_design_curve(const StudySpec& spec, StudyResult& result);

}  // namespace rackopt::study
