#include "rackopt/study_report/front_quality_report.hpp"

#include <sstream>

#include "rackopt/study_report/display_units.hpp"
#include "rackopt/study_report/study_report.hpp"

namespace rackopt::study_report {

namespace {

// A minimized own-unit value back in the metric's own sense.
double own_sense(const StudySpec& spec, std::size_t i, double minimized) {
  return spec.objectives[i].maximize ? -minimized : minimized;
}

}  // namespace

std::string front_quality_markdown(const StudySpec& spec, const StudyResult& result) {
  if (!result.front_summary) return "";
  const study::FrontSummary& s = *result.front_summary;
  const solvers::FrontQuality& q = s.quality;
  std::ostringstream o;
  o << "### Front quality\n\n";
  o << "- points: " << result.front.size() << " delivered of " << s.requested << " requested";
  if (q.points > 0) o << " (" << q.non_dominated << " non-dominated)";
  o << "\n";
  if (q.points > 0) {
    o << "- hypervolume: " << short_number(q.hypervolume)
      << " of the box from the front's best value of each objective to the reference point";
    if (!s.history_hypervolume.empty())
      o << " (every feasible design evaluated: " << short_number(s.history_hypervolume.back()) << ")";
    o << "\n";
    o << "- reference point:";
    for (std::size_t i = 0; i < spec.objectives.size() && i < q.reference.size(); ++i)
      o << (i ? "," : "") << " " << spec.objectives[i].label << " "
        << metric_display(spec.objectives[i].label, own_sense(spec, i, q.reference[i]));
    o << " (the front's worst value of each objective plus 10 % of its range)\n";
    o << "- spacing: " << short_number(q.spacing)
      << " (the spread of the distances between neighbouring points, objectives normalized by their range; "
         "0 = evenly spaced)\n";
  }
  if (!s.shortfall.empty()) {
    o << "- why fewer points than requested:\n";
    for (const std::string& line : s.shortfall) o << "  - " << line << "\n";
  }
  o << "\n";
  return o.str();
}

void front_quality_json(JsonWriter& j, const StudySpec& spec, const StudyResult& result) {
  if (!result.front_summary) return;
  const study::FrontSummary& s = *result.front_summary;
  const solvers::FrontQuality& q = s.quality;
  j.key("front_quality").begin_object();
  j.key("requested").value(static_cast<long>(s.requested));
  j.key("points").value(static_cast<long>(result.front.size()));
  j.key("non_dominated").value(static_cast<long>(q.non_dominated));
  j.key("hypervolume").value(q.hypervolume);
  j.key("spacing").value(q.spacing);
  auto point = [&](const char* key, const std::vector<double>& v) {
    j.key(key).begin_object();
    for (std::size_t i = 0; i < spec.objectives.size() && i < v.size(); ++i)
      j.key(spec.objectives[i].label).value(own_sense(spec, i, v[i]));
    j.end_object();
  };
  point("ideal", q.ideal);
  point("reference", q.reference);
  j.key("hypervolume_history").begin_array();
  for (std::size_t k = 0; k < s.history_evaluations.size(); ++k) {
    j.begin_array().value(static_cast<long>(s.history_evaluations[k])).value(s.history_hypervolume[k]);
    j.end_array();
  }
  j.end_array();
  j.key("shortfall").begin_array();
  for (const std::string& line : s.shortfall) j.value(line);
  j.end_array();
  j.end_object();
}

std::optional<std::string> hypervolume_table(const StudyResult& result) {
  if (!result.front_summary || result.front_summary->history_evaluations.empty()) return std::nullopt;
  const study::FrontSummary& s = *result.front_summary;
  std::ostringstream o;
  o << "evaluations,hypervolume\n";
  o.precision(17);
  for (std::size_t k = 0; k < s.history_evaluations.size(); ++k)
    o << s.history_evaluations[k] << "," << s.history_hypervolume[k] << "\n";
  return o.str();
}

}  // namespace rackopt::study_report
