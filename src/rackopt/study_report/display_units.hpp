// How the study report shows numbers and units, shared by its tables, plots,
// report.md and summary.json: SI units as column-name suffixes, each
// metric's and variable's display unit with its factor, and number text.
// The public display functions (metric_display, variable_display) are
// declared in study_report.hpp.
#pragma once

#include <string>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

struct MetricUnit {
  std::string si;       // "N/m", "-", "1/m"
  std::string display;  // "MN/m", "" (dimensionless), "1/m"
  double factor = 1;    // SI value of one display unit
  const metrics::MetricDefinition* def = nullptr;
};

// The units of metric `label` (a parameter is allowed: "wear_life_at_R(0.9)");
// a label the registry does not know gets si = "" and factor 1 (shown as a
// plain number).
MetricUnit metric_unit(const std::string& label);

struct VariableUnit {
  std::string si, display;
  double factor = 1;  // SI value of one display unit
};

// The units of variable `v`: display is v.unit, else the kind's default
// unit; a unit the kind does not know falls back to SI with factor 1.
VariableUnit variable_unit(const DesignVariable& v);

// `v` with 17 significant digits, so a CSV round-trips it bit for bit; ""
// when not finite (an empty cell).
std::string exact_number(double v);

// `v` with 6 significant digits for people; "nan", "inf", "-inf" when not finite.
std::string short_number(double v);

// A constraint with its bounds in display units, for people:
// "20 MN/m ≤ min_stiffness ≤ 40 MN/m", "contact_ratio = 1.5".
std::string bound_text(const ConstraintSpec& c);

}  // namespace rackopt::study_report
