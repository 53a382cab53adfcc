#include "rackopt/study_report/display_units.hpp"

#include <cmath>
#include <cstdio>

#include "rackopt/core/error.hpp"
#include "rackopt/study_report/study_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

MetricUnit metric_unit(const std::string& label) {
  MetricUnit u;
  try {
    const metrics::MetricRequest req = metrics::parse_metric_request(label);
    const metrics::MetricDefinition& def = metrics::find_metric(req.name);
    u.def = &def;
    u.si = std::string(def.unit);
    if (def.kind && !def.display_unit.empty()) {
      u.display = std::string(def.display_unit);
      u.factor = unit_factor(def.display_unit, *def.kind);
    } else {
      u.display = u.si == "-" ? "" : u.si;
    }
  } catch (const InputError&) {
    u.si = "";  // a label we do not know (a test's synthetic metric): plain number
  }
  return u;
}

VariableUnit variable_unit(const DesignVariable& v) {
  VariableUnit u;
  u.si = std::string(si_unit(v.kind));
  u.display = v.unit.empty() ? std::string(default_unit(v.kind)) : v.unit;
  if (!u.display.empty()) {
    try {
      u.factor = unit_factor(u.display, v.kind);
    } catch (const InputError&) {
      u.display = u.si;
      u.factor = 1;
    }
  }
  return u;
}

std::string exact_number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string short_number(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  return format_number(v, 6);
}

std::string bound_text(const ConstraintSpec& c) {
  std::string s;
  if (c.equals) return c.label + " = " + metric_display(c.label, *c.equals);
  if (c.min) s += metric_display(c.label, *c.min) + " ≤ ";
  s += c.label;
  if (c.max) s += " ≤ " + metric_display(c.label, *c.max);
  return s;
}

std::string metric_display(const std::string& label, double value_si) {
  const MetricUnit u = metric_unit(label);
  if (!std::isfinite(value_si)) return short_number(value_si);
  if (u.def != nullptr && u.def->kind) return format_quantity(value_si, *u.def->kind, u.display, 4);
  const std::string n = format_number(value_si, 4);
  return u.display.empty() ? n : n + " " + u.display;
}

std::string variable_display(const DesignVariable& v, double value_si) {
  if (!std::isfinite(value_si)) return short_number(value_si);
  if (v.kind == QuantityKind::kCount) return format_number(std::round(value_si), 12);
  const VariableUnit u = variable_unit(v);
  return format_quantity(value_si, v.kind, u.display, 6);
}

}  // namespace rackopt::study_report
