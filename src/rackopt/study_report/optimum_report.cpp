#include "rackopt/study_report/optimum_report.hpp"

#include <cmath>
#include <sstream>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/study_report/markdown_text.hpp"
#include "rackopt/study/study_kind_rules.hpp"
#include "rackopt/study_report/discretization_report.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study/sweep_sensitivity.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

namespace {

// A combination the study stopped before has no status: shown empty.
std::string combination_status_text(const CombinationOutcome& c) {
  return c.status ? std::string(solvers::to_string(*c.status)) : std::string();
}

}  // namespace
namespace {

// SI per display unit of a variable (1 for plain numbers).
double per_display_unit(const DesignVariable& v) {
  if (v.kind == QuantityKind::kDimensionless || v.kind == QuantityKind::kCount || v.unit.empty()) return 1.0;
  try {
    return unit_factor(v.unit, v.kind);
  } catch (const std::exception&) {
    return 1.0;
  }
}

std::string unit_text(const DesignVariable& v) {
  if (v.kind == QuantityKind::kDimensionless || v.kind == QuantityKind::kCount || v.unit.empty()) return "unit";
  return v.unit;
}

const DesignVariable* variable_named(const StudySpec& spec, const std::string& key) {
  for (const auto& v : spec.variables)
    if (v.key == key) return &v;
  return nullptr;
}

// "Variables at a bound ...: `key` at its lower bound 17 deg, held there
// ...", or that none is; one paragraph.
std::string variables_at_bounds_markdown(const StudySpec& spec, const OptimumExplanation& e) {
  std::ostringstream o;
  bool any = false;
  double tolerance_fraction = 0;
  for (const VariableStatus& s : e.variables) {
    const DesignVariable* v = variable_named(spec, s.key);
    if (v && !s.discrete && v->upper > v->lower) tolerance_fraction = s.bound_tolerance / (v->upper - v->lower);
    if (!s.at_lower && !s.at_upper) continue;
    o << (any ? "; " : "Variables at a bound: ");
    any = true;
    const double bound = v ? (s.at_lower ? v->lower : v->upper) : s.value;
    o << "`" << s.key << "` at its " << (s.at_lower ? "lower" : "upper") << " bound "
      << (v ? variable_display(*v, bound) : format_number(bound, 6));
    if (s.pushed_into_bound) {
      o << (*s.pushed_into_bound ? ", which holds the optimum (the objective, with the active constraints, "
                                   "would improve past it)"
                                 : ", though the gradient points into the box (the solver stopped next to the "
                                   "bound, which does not hold it)");
    }
  }
  const std::string within = format_number(100 * tolerance_fraction, 3) + " % of its range";
  if (any) {
    o << ". A variable counts as at a bound when it is within " << within
      << " from it (the solver's step tolerance, at least 0.1 %).\n\n";
  } else {
    o << "No continuous variable is at a bound (within " << within << ").\n\n";
  }
  return o.str();
}

}  // namespace

std::string per_combination_markdown(const StudySpec& spec, const StudyResult& r) {
  if (r.per_combination.empty()) return "";
  std::ostringstream o;
  o << "### Best design per combination\n\n";
  if (searches_discrete_as_integers(spec))
    o << "The discrete variables were searched as integers in one " << spec.solver.algorithm
      << " run: each row is the best design that run visited in the combination, its status the run's; "
         "combinations it never visited are not listed.\n\n";
  o << "| combination | status | feasible |";
  for (const auto& v : spec.variables)
    if (!v.discrete()) o << " " << markdown_code_cell(v.key) << " |";
  for (const auto& ob : spec.objectives) o << " " << markdown_text(ob.label) << " |";
  o << " note |\n|---|---|---|";
  for (const auto& v : spec.variables)
    if (!v.discrete()) o << "---|";
  for (std::size_t i = 0; i < spec.objectives.size(); ++i) o << "---|";
  o << "---|\n";
  for (const CombinationOutcome& c : r.per_combination) {
    const DesignResult* d = c.best ? &*c.best : c.least_infeasible ? &*c.least_infeasible : nullptr;
    const bool is_best = c.best && r.best && c.best->x == r.best->x;
    o << "| " << (is_best ? "**" + markdown_text(c.label) + "**" : markdown_text(c.label)) << " | " << combination_status_text(c) << " | "
      << (c.best ? "yes" : d ? "no (least infeasible shown)" : "no design") << " |";
    for (std::size_t i = 0; i < spec.variables.size(); ++i) {
      if (spec.variables[i].discrete()) continue;
      o << " " << (d && i < d->x.size() ? variable_display(spec.variables[i], d->x[i]) : "") << " |";
    }
    for (std::size_t i = 0; i < spec.objectives.size(); ++i)
      o << " " << (d && i < d->objectives.size() ? metric_display(spec.objectives[i].label, d->objectives[i]) : "")
        << " |";
    std::string note = d && !c.best ? "violation " + format_number(d->max_violation, 3) : "";
    if (is_best) note = "the optimum";
    o << " " << note << " |\n";
  }
  o << "\n";
  return o.str();
}

std::string explanation_markdown(const StudySpec& spec, const StudyResult& r) {
  if (!r.explanation) return "";
  const OptimumExplanation& e = *r.explanation;
  std::ostringstream o;
  o << "### Why this optimum\n\n";
  o << "| constraint | value | bound | slack | active | " << e.objective << " per 1 % of the bound |\n"
    << "|---|---|---|---|---|---|\n";
  for (const ConstraintStatus& c : e.constraints) {
    std::string sens;
    if (c.bound_sensitivity) {
      // Tightening a min bound or an equality by 1 %, or a max bound by 1 %.
      const double delta = 0.01 * std::abs(c.bound) * (c.side == "max" ? -1.0 : 1.0);
      sens = metric_display(e.objective, *c.bound_sensitivity * delta);
    }
    o << "| " << markdown_text(c.label) << " | " << metric_display(c.label, c.value) << " | " << c.side << " "
      << metric_display(c.label, c.bound) << " | " << format_number(100 * c.relative_slack, 3) << " % | "
      << (c.active ? "**active**" : "") << " | " << sens << " |\n";
  }
  o << "\nThe last column is the change of the optimal " << e.objective
    << " when the bound is tightened by 1 % (Lagrange multiplier times the change; positive = costs objective), "
       "to first order.\n\n";
  o << discretization_markdown(e);
  o << variables_at_bounds_markdown(spec, e);
  if (!e.gradient_variables.empty()) {
    o << "| variable | difference | d " << e.objective << " |";
    for (const ConstraintStatus& c : e.constraints) o << " d " << markdown_text(c.label) << " |";
    o << "\n|---|---|---|";
    for (std::size_t i = 0; i < e.constraints.size(); ++i) o << "---|";
    o << "\n";
    for (std::size_t q = 0; q < e.gradient_variables.size(); ++q) {
      const DesignVariable* v = variable_named(spec, e.gradient_variables[q]);
      const double f = v ? per_display_unit(*v) : 1.0;
      const std::string per = v ? unit_text(*v) : "unit";
      std::string diff;
      for (const VariableStatus& s : e.variables)
        if (s.key == e.gradient_variables[q]) diff = s.difference;
      o << "| " << markdown_code_cell(e.gradient_variables[q]) << " (per " << per << ") | " << diff << " | "
        << (e.objective_gradient.size() > q && e.objective_gradient[q]
                ? metric_display(e.objective, *e.objective_gradient[q] * f)
                : "failed")
        << " |";
      for (const ConstraintStatus& c : e.constraints)
        o << " " << (c.gradient.size() > q && c.gradient[q] ? metric_display(c.label, *c.gradient[q] * f) : "failed")
          << " |";
      o << "\n";
    }
    o << "\n";
  }
  o << "Gradients: " << e.note << "; KKT residual " << format_number(e.kkt_residual, 3)
    << " (0 = the objective's gradient is exactly a combination of the active constraints'; "
       "large = a non-smooth metric or a point the solver left early).\n\n";
  return o.str();
}

std::string fidelity_markdown(const StudyResult& r) {
  if (r.fidelity.empty()) return "";
  std::ostringstream o;
  o << "## Fidelity settings\n\nThe models ran with (docs/accuracy.md gives what each costs and buys):\n\n"
    << "| setting | value |\n|---|---|\n";
  for (const auto& [k, v] : r.fidelity) o << "| " << k << " | " << v << " |\n";
  o << "\n";
  return o.str();
}

std::string sweep_sensitivity_markdown(const StudySpec& spec, const StudyResult& r) {
  if (spec.kind != StudyKind::kSweep || r.sensitivity.empty()) return "";
  return "## Sensitivity over the design box\n\nSobol indices from the sweep's own points "
         "(docs/models/sensitivity.md): S_i is the share of a metric's variance that the variable explains alone, "
         "S_Ti with its interactions.\n\n" +
         sensitivity_markdown(r.sensitivity) + "\n";
}

void optimum_json(JsonWriter& j, const StudySpec& spec, const StudyResult& r,
                  void (*design)(JsonWriter&, const StudySpec&, const DesignResult&)) {
  if (!r.per_combination.empty()) {
    j.key("per_combination").begin_array();
    for (const CombinationOutcome& c : r.per_combination) {
      j.begin_object().key("combination").value(c.label).key("status").value(combination_status_text(c));
      j.key("best");
      if (c.best) {
        design(j, spec, *c.best);
      } else {
        j.null();
      }
      if (c.least_infeasible) {
        j.key("least_infeasible");
        design(j, spec, *c.least_infeasible);
      }
      j.end_object();
    }
    j.end_array();
  }
  if (r.explanation) {
    const OptimumExplanation& e = *r.explanation;
    auto opt = [&j](const std::optional<double>& v) {
      if (v) {
        j.value(*v);
      } else {
        j.null();
      }
    };
    j.key("explanation").begin_object();
    j.key("objective").value(e.objective);
    j.key("gradient_variables").begin_array();
    for (const auto& k : e.gradient_variables) j.value(k);
    j.end_array();
    j.key("objective_gradient").begin_array();
    for (const auto& g : e.objective_gradient) opt(g);
    j.end_array();
    j.key("variables").begin_array();
    for (const VariableStatus& v : e.variables) {
      j.begin_object().key("name").value(v.key).key("value").value(v.value).key("discrete").value(v.discrete);
      j.key("at_lower").value(v.at_lower).key("at_upper").value(v.at_upper);
      j.key("bound_tolerance").value(v.bound_tolerance).key("pushed_into_bound");
      if (v.pushed_into_bound) {
        j.value(*v.pushed_into_bound);
      } else {
        j.null();
      }
      j.key("step").value(v.step).key("difference").value(v.difference).end_object();
    }
    j.end_array();
    j.key("constraints").begin_array();
    for (const ConstraintStatus& c : e.constraints) {
      j.begin_object().key("metric").value(c.label).key("side").value(c.side).key("value").value(c.value);
      j.key("bound").value(c.bound).key("relative_slack").value(c.relative_slack).key("active").value(c.active);
      j.key("bound_sensitivity");
      opt(c.bound_sensitivity);
      j.key("gradient").begin_array();
      for (const auto& g : c.gradient) opt(g);
      j.end_array();
      if (c.discretization) {
        j.key("discretization");
        discretization_json(j, *c.discretization);
      }
      j.end_object();
    }
    j.end_array();
    j.key("kkt_residual").value(e.kkt_residual);
    j.key("note").value(e.note);
    j.end_object();
  }
  if (!r.fidelity.empty()) {
    j.key("fidelity").begin_object();
    for (const auto& [k, v] : r.fidelity) j.key(k).value(v);
    j.end_object();
  }
  if (spec.kind == StudyKind::kSweep && !r.sensitivity.empty()) {
    j.key("sensitivity");
    sensitivity_json(j, r.sensitivity);
  }
}

}  // namespace rackopt::study_report
