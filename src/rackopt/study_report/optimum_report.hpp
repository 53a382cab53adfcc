// The parts of the study report that explain an optimum: the best design of
// each discrete combination, the binding constraints and variables at a
// bound with the objective's sensitivities, the fidelity settings in effect,
// and a sweep's global sensitivity ranking. Markdown for report.md and JSON
// for summary.json; report_markdown.cpp and summary_json.cpp place them.
// Nothing here runs a model: the runner computed what is shown (StudyResult).
#pragma once

#include <string>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// "### Best design per combination" table ("" when the study has none).
std::string per_combination_markdown(const StudySpec& spec, const StudyResult& result);
// "### Why this optimum" (constraints, variables at bounds, sensitivities; "" without an explanation).
std::string explanation_markdown(const StudySpec& spec, const StudyResult& result);
// "## Fidelity settings" ("" when none were recorded).
std::string fidelity_markdown(const StudyResult& result);
// "## Sensitivity over the design box" for sweeps (StudyResult::sensitivity; "" otherwise).
std::string sweep_sensitivity_markdown(const StudySpec& spec, const StudyResult& result);

// summary.json members (each writes its key and value; nothing when absent):
// "per_combination", "explanation", "fidelity", "sensitivity".
void optimum_json(JsonWriter& j, const StudySpec& spec, const StudyResult& result,
                  void (*design)(JsonWriter&, const StudySpec&, const DesignResult&));

}  // namespace rackopt::study_report
