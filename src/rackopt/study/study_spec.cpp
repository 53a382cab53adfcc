#include "rackopt/study/study_spec.hpp"

#include <cctype>
#include <set>

#include "rackopt/core/error.hpp"

namespace rackopt::study {

const char* kind_name(StudyKind kind) {
  switch (kind) {
    case StudyKind::kEvaluate: return "evaluate";
    case StudyKind::kSweep: return "sweep";
    case StudyKind::kOptimize: return "optimize";
    case StudyKind::kPareto: return "pareto";
    case StudyKind::kReliability: return "reliability";
  }
  return "unknown";
}

std::vector<metrics::MetricRequest> StudySpec::all_metrics() const {
  std::vector<metrics::MetricRequest> out;
  std::set<std::string> seen;
  auto add = [&](const metrics::MetricRequest& r) {
    if (seen.insert(metrics::to_string(r)).second) out.push_back(r);
  };
  for (const auto& o : objectives) add(o.metric);
  for (const auto& c : constraints) add(c.metric);
  for (const auto& r : report_metrics) add(r);
  return out;
}

std::string default_out_dir(const StudySpec& spec) {
  std::string folder;
  for (char c : spec.name) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    folder += plain ? c : '_';
  }
  if (folder.empty() || folder == "." || folder == "..") folder = "study";
  if (folder.size() > kMaxFolderNameBytes) {
    throw InputError(spec.name_mark, "study.name",
                     "the name is " + std::to_string(folder.size()) + " bytes long; the default output folder "
                     "out/<name> takes at most " + std::to_string(kMaxFolderNameBytes) +
                     " (the longest file name): give a shorter name or choose the output folder");
  }
  return "out/" + folder;
}

ProblemTree study_problem_tree(const StudySpec& spec) {
  if (spec.problem_root) return load_problem_tree_node(*spec.problem_root, spec.problem_path, spec.problem_overrides);
  return load_problem_tree_file(spec.problem_path, spec.problem_overrides);
}

}  // namespace rackopt::study
