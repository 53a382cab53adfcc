// What `rackopt run` tells people when a study ends (stdout; stderr with
// --json): the status, the best or chosen design with its variables and
// metrics, the wear and FE summaries, a sweep's metric ranges, the counts,
// the warnings (the best design's own, then the first kinds of the rest:
// warnings_report.hpp), and where the files went.
#pragma once

#include <string>

#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// The text, several lines each ending in "\n". `report` is what
// write_study_report returned for `result` (its warnings and the paths of
// report.md and report.html are shown), `out_dir` the output folder as the
// user named it (the resume hint of a stopped run repeats it).
std::string study_summary_text(const StudySpec& spec, const StudyResult& result, const StudyReport& report,
                               const std::string& out_dir);

}  // namespace rackopt::study_report
