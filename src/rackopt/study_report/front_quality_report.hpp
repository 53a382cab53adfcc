// The front's quality in a pareto study's report: the "Front quality"
// section of report.md, the "front_quality" object of summary.json and
// hypervolume.csv with the hypervolume against evaluations (plotted as
// history.png for a pareto study). docs/output.md ("Study results") and
// docs/solvers.md ("Front quality") say what each number means.
#pragma once

#include <optional>
#include <string>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// "### Front quality" with the points delivered against those requested,
// the normalized hypervolume and its box, the spacing and, when short, why;
// "" when the study has no front summary.
std::string front_quality_markdown(const StudySpec& spec, const StudyResult& result);

// Key "front_quality" of summary.json (nothing without a front summary):
// {requested, points, non_dominated, hypervolume, spacing, ideal {metric:
// value}, reference {metric: value} (SI, the metrics' own senses),
// hypervolume_history [[evaluations, hypervolume], ...], shortfall [...]}.
void front_quality_json(JsonWriter& j, const StudySpec& spec, const StudyResult& result);

// hypervolume.csv: evaluations,hypervolume; nullopt without a history.
std::optional<std::string> hypervolume_table(const StudyResult& result);

}  // namespace rackopt::study_report
