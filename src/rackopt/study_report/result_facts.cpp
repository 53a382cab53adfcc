#include "rackopt/study_report/result_facts.hpp"

#include <algorithm>

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

std::size_t feasible_points(const StudyResult& r) {
  return static_cast<std::size_t>(std::count_if(r.sweep_points.begin(), r.sweep_points.end(),
                                                [](const DesignResult& p) { return p.feasible; }));
}

std::size_t fresh_evaluations(const StudyResult& r) {
  return r.evaluations >= r.reused_evaluations ? r.evaluations - r.reused_evaluations : 0;
}

std::vector<std::string> recorded_rows_notes(const StudyResult& r) {
  auto evaluations = [](std::size_t n) {
    return std::to_string(n) + (n == 1 ? " recorded evaluation " : " recorded evaluations ");
  };
  std::vector<std::string> out;
  if (r.damaged_records > 0)
    out.push_back(evaluations(r.damaged_records) +
                  (r.damaged_records == 1 ? "failed its checksum and was" : "failed their checksum and were") +
                  " recomputed");
  if (r.unchecked_records > 0)
    out.push_back(evaluations(r.unchecked_records) +
                  (r.unchecked_records == 1 ? "predates checksums (an older rackopt recorded it) and was"
                                            : "predate checksums (an older rackopt recorded them) and were") +
                  " reused unchecked");
  return out;
}

std::vector<std::string> warnings_best_first(const StudyResult& r, const std::vector<std::string>& run_warnings) {
  std::vector<std::string> out = r.best ? r.best->warnings : std::vector<std::string>{};
  for (const auto& w : run_warnings)
    if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
  return out;
}

}  // namespace rackopt::study_report
