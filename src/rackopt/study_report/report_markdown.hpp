// report.md of a study: the study's setup (kind, files, seed, solver,
// variables, objectives, constraints), the outcome with the best or chosen
// design, the optimum's explanation, counts and timings, the warnings, and
// links to the files and plots (docs/output.md, "Study results").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// The text of report.md, without its last line (the link to summary.json,
// which does not exist yet when this is written). `files` are linked
// relative to `out_dir` when inside it, only those that exist; `warnings`
// are the run's and the report's (the best design's own are listed first).
std::string report_markdown(const StudySpec& spec, const StudyResult& result, const ReportFiles& files,
                            const std::vector<std::string>& warnings, const std::filesystem::path& out_dir);

// How report.md links the file `path`: relative to `out_dir` when inside it,
// so the report still works when the folder is moved or copied; else absolute.
std::string link_target(const std::filesystem::path& out_dir, const std::string& path);

}  // namespace rackopt::study_report
