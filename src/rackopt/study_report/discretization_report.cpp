#include "rackopt/study_report/discretization_report.hpp"

#include <sstream>

#include "rackopt/study_report/study_report.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::study_report {

std::string discretization_markdown(const study::OptimumExplanation& e) {
  std::ostringstream o;
  bool any = false;
  for (const study::ConstraintStatus& c : e.constraints) {
    if (!c.discretization) continue;
    const study::DiscretizationError& d = *c.discretization;
    if (!any)
      o << "Discretization error of the active wear lives at the optimum (one refinement: the best design "
           "evaluated once more with twice the profile points; error = (value - refined) / refined):\n\n";
    any = true;
    o << "- " << c.label << ": " << metric_display(c.label, c.value) << ", discretization error "
      << (d.relative_error >= 0 ? "+" : "") << format_number(100 * d.relative_error, 2) << " % (one refinement, "
      << d.setting << " " << d.points << " -> " << d.refined_points << ": "
      << metric_display(c.label, d.refined_value) << ")\n";
  }
  if (any) o << "\n";
  return o.str();
}

void discretization_json(JsonWriter& j, const study::DiscretizationError& d) {
  j.begin_object().key("setting").value(d.setting).key("points").value(d.points);
  j.key("refined_points").value(d.refined_points).key("refined_value").value(d.refined_value);
  j.key("relative_error").value(d.relative_error).end_object();
}

}  // namespace rackopt::study_report
