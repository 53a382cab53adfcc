// Facts the study report derives from a result and shows in several places
// (the status message, report.md, summary.json), computed once here so the
// places cannot disagree.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rackopt/study/study_result.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// How many of r.sweep_points are feasible.
std::size_t feasible_points(const StudyResult& r);

// Evaluations this run computed itself (not taken from the store on
// --resume): the count the per-evaluation time is taken over.
std::size_t fresh_evaluations(const StudyResult& r);

// What --resume found wrong or could not check in the recorded rows, one
// sentence each: "3 recorded evaluations failed their checksum and were
// recomputed", "12 recorded evaluations predate checksums and were reused
// unchecked"; none when every row checked out.
std::vector<std::string> recorded_rows_notes(const StudyResult& r);

// The best (pareto: chosen) design's own warnings, then those of
// `run_warnings` not among them: the optimum's remarks are the ones a
// reader acts on.
std::vector<std::string> warnings_best_first(const StudyResult& r, const std::vector<std::string>& run_warnings);

}  // namespace rackopt::study_report
