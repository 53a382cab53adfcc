// The warnings of a study as report.md (and so report.html), summary.json
// and the text `rackopt run` prints show them: the best (pareto: chosen)
// design's own warnings first, under their own heading, then the run's
// warnings grouped by kind (study/warning_groups.hpp), each kind once with
// the number of designs that gave it, their evaluation ids and one example.
// docs/output.md, "Warnings".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study/warning_groups.hpp"

namespace rackopt::study_report {

struct ReportWarnings {
  std::string design = "best design";      // what the report calls result.best: "best design", "chosen design", "design"
  std::vector<std::string> best;           // the best design's own warnings, as the models wrote them
  std::int64_t best_evaluation = 0;        // the best design's evaluation id (0 = unknown)
  // Every warning of the run by kind, first-use order: the designs' (from
  // result.warning_groups, counts complete, the best design included), then
  // the report's own (gnuplot missing, ...: no design, designs = 0).
  std::vector<study::WarningGroup> groups;
  std::size_t kinds_dropped = 0;           // warnings of kinds beyond study::kMaxWarningKinds
};

// `run_warnings` is what the report lists as the run's warnings
// (StudyReport::warnings: result.warnings, then the report's own). A result
// without warning_groups (one not made by run_study) is grouped from
// result.warnings, without evaluation ids. `spec` names the design
// (optimize and sweep: best, pareto: chosen, evaluate and reliability: the design).
ReportWarnings report_warnings(const study::StudySpec& spec, const study::StudyResult& result,
                               const std::vector<std::string>& run_warnings);

// The groups a reader is shown after the best design's own warnings: all
// but those that only the best design gave (already listed above them).
std::vector<study::WarningGroup> other_warning_groups(const ReportWarnings& w);

// One group as a line of text (no markup): the message itself when the
// group holds one, else its kind with an example; then where it came from,
// "448 designs (evaluations 3, 7, 12, …)", and with `with_example` the
// group's first message. `max_ids` ids are listed.
std::string warning_group_text(const study::WarningGroup& g, std::size_t max_ids, bool with_example);

// "## Warnings of the best design" (chosen design, design) and "## Other warnings of the run, by
// kind" (or "## Warnings, by kind" when the best design has none); "" when
// there are no warnings.
std::string warnings_markdown(const ReportWarnings& w);

// The CLI's lines, each "  ...\n": the best design's warnings, then at most
// `max_groups` groups (kind and designs; the examples are in report.md) and
// a line counting the rest.
std::string warnings_text(const ReportWarnings& w, std::size_t max_groups);

// summary.json's "warning_groups": [{kind, example, designs, messages,
// evaluations, best_design}] and "warning_kinds_dropped".
void warning_groups_json(JsonWriter& j, const ReportWarnings& w);

}  // namespace rackopt::study_report
