#include "rackopt/studyfile/study_sections.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "rackopt/core/text.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/solvers/solver_backend.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"

namespace rackopt::studyfile {

using namespace rackopt::study;
namespace {

// The keys every library shares; each library's own keys come from its
// SolverBackend::options().
const std::vector<std::string>& common_solver_keys() {
  static const std::vector<std::string> keys = {
      "library",  "algorithm", "local_algorithm", "max_evaluations", "max_time",      "starts",
      "xtol_rel", "xtol_abs",  "ftol_rel",        "ftol_abs",        "constraint_tolerance", "gradients",
      "gradient_step"};
  return keys;
}

// A library's own settings: keys of another library are refused by name.
void read_backend_options(const SectionReader& sv, const solvers::SolverBackend& backend,
                          solvers::SolverSettings& so) {
  for (const solvers::SolverBackend* other : solvers::solver_backends()) {
    for (const solvers::BackendOption& o : other->options()) {
      if (!sv.get(o.key)) continue;
      if (other != &backend) {
        std::vector<std::string> own;
        for (const solvers::BackendOption& mine : backend.options()) own.push_back(mine.key);
        throw InputError(sv.key_mark(o.key), "solver." + o.key,
                         "is a setting of library " + std::string(other->library()) + ", not of " +
                             std::string(backend.library()) + "; " +
                             (own.empty() ? std::string(backend.library()) + " has no settings of its own"
                                          : std::string(backend.library()) + "'s own settings: " + join(own)));
      }
      const ValueRange range{.lo = o.lo, .hi = o.hi, .lo_open = o.lo_open};
      if (o.whole) {
        if (const auto v = sv.integer(o.key, range)) so.options[o.key] = static_cast<double>(*v);
      } else if (const auto v = sv.plain_number(o.key, range)) {
        so.options[o.key] = *v;
      }
    }
  }
}

SectionReader read_solver(const SectionReader& top, StudySpec& spec) {
  std::vector<std::string> keys = common_solver_keys();
  for (const solvers::SolverBackend* b : solvers::solver_backends())
    for (const solvers::BackendOption& o : b->options()) keys.push_back(o.key);
  const SectionReader sv = study_section(top.get("solver"), "solver", top.key_mark("solver"), keys,
                                         "{library: nlopt, algorithm: LN_COBYLA, max_evaluations: 400}");
  solvers::SolverSettings& so = spec.solver;
  so.library = sv.choice("library", solvers::solver_library_names()).value_or("nlopt");
  const solvers::SolverBackend& backend = *solvers::find_solver_backend(so.library);
  so.algorithm = sv.text("algorithm", backend.default_algorithm());
  so.local_algorithm = sv.text("local_algorithm", "");
  so.max_evaluations = static_cast<std::size_t>(sv.integer("max_evaluations", {1, 100000000}).value_or(1000));
  so.max_seconds =
      sv.quantity_in("max_time", QuantityKind::kTime, {.lo = 0}, {}, "s", expected_kind_text(QuantityKind::kTime))
          .value_or(0);
  so.starts = static_cast<int>(sv.integer("starts", {1, 10000}).value_or(1));
  so.xtol_rel = sv.plain_number("xtol_rel", {.lo = 0}).value_or(1e-6);
  so.xtol_abs = sv.plain_number("xtol_abs", {.lo = 0}).value_or(so.xtol_abs);
  so.ftol_rel = sv.plain_number("ftol_rel", {.lo = 0}).value_or(so.ftol_rel);
  so.ftol_abs = sv.plain_number("ftol_abs", {.lo = 0}).value_or(so.ftol_abs);
  so.constraint_tolerance = sv.plain_number("constraint_tolerance", {.lo = 0}).value_or(so.constraint_tolerance);
  const auto gradients = sv.choice("gradients", {"forward", "central"});
  // Ipopt's steps are sensitive to the O(h) bias of forward differences.
  so.central_differences = gradients ? *gradients == "central" : so.library == "ipopt";
  so.gradient_step =
      sv.plain_number("gradient_step", {.lo = 0, .hi = 0.25, .lo_open = true}).value_or(so.gradient_step);
  read_backend_options(sv, backend, so);
  so.seed = spec.seed;
  return sv;
}

// Needs spec.objectives: pareto.primary names one of them.
SectionReader read_pareto(const SectionReader& top, StudySpec& spec) {
  const SectionReader pa = study_section(top.get("pareto"), "pareto", top.key_mark("pareto"),
                                         {"method", "points", "primary", "duplicate_tolerance", "choose_weights"},
                                         "{method: eps_constraint, points: 20}");
  // Without a method: the solver's own front search when its algorithm has
  // one (pagmo's nsga2, moead), else the eps-constraint scalarization.
  const std::string method =
      pa.choice("method", {"eps_constraint", "weighted_sum", "population"})
          .value_or(solvers::algorithm_finds_fronts(spec.solver) ? "population" : "eps_constraint");
  spec.pareto.method = method == "weighted_sum" ? solvers::Scalarization::kWeightedSum
                       : method == "population" ? solvers::Scalarization::kPopulation
                                                : solvers::Scalarization::kEpsilonConstraint;
  spec.pareto.points = static_cast<std::size_t>(pa.integer("points", {2, 10000}).value_or(20));
  spec.pareto.duplicate_tolerance =
      pa.plain_number("duplicate_tolerance", {.lo = 0, .hi = 1}).value_or(spec.pareto.duplicate_tolerance);
  if (const auto primary = pa.scalar("primary", "an objective's metric or its index (0, 1, 2)")) {
    const std::string t = trim(primary->first);
    std::vector<std::string> labels;
    for (const auto& o : spec.objectives) labels.push_back(o.label);
    const bool is_index = !t.empty() && std::all_of(t.begin(), t.end(),
                                                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    std::optional<std::size_t> found;
    if (is_index) {
      const std::size_t i = t.size() > 6 ? labels.size() : static_cast<std::size_t>(std::stoul(t));
      if (i < labels.size()) found = i;
    } else {
      std::string wanted = t;
      try {
        wanted = metrics::to_string(metrics::resolve_request(metrics::parse_metric_request(t)));
      } catch (const InputError&) {
        // not a metric text: compared as written below
      }
      for (std::size_t i = 0; i < labels.size(); ++i) {
        if (labels[i] == wanted || labels[i] == t) found = i;
      }
    }
    if (!found) {
      std::vector<std::string> choices;
      for (std::size_t i = 0; i < labels.size(); ++i) choices.push_back(std::to_string(i) + " = " + labels[i]);
      throw InputError(primary->second, "pareto.primary",
                       "'" + primary->first + "' is not one of the objectives; allowed: " +
                           (choices.empty() ? std::string("(the study has no objectives)") : join(choices)));
    }
    spec.pareto.primary = *found;
  }
  if (const MarkedNode* cw = pa.get("choose_weights")) {
    if (cw->type != MarkedNode::Type::kSequence) {
      throw InputError(cw->mark, "pareto.choose_weights",
                       "expected a list of weights, one per objective, e.g. [1, 1], found " + cw->type_name());
    }
    bool any_positive = false;
    for (std::size_t i = 0; i < cw->items.size(); ++i) {
      const std::string path = item_path("pareto.choose_weights", i);
      const ValueSite w = read_value(cw->items[i], path, QuantityKind::kDimensionless);
      if (w.value < 0) {
        throw InputError(w.mark, path, format_number(w.value, 10) + " is out of range; allowed: weight >= 0");
      }
      any_positive = any_positive || w.value > 0;
      spec.choose_weights.push_back(w.value);
    }
    if (spec.kind == StudyKind::kPareto && spec.choose_weights.size() != spec.objectives.size()) {
      throw InputError(cw->mark, "pareto.choose_weights",
                       "gives " + std::to_string(spec.choose_weights.size()) + " weights for " +
                           std::to_string(spec.objectives.size()) + " objectives; give one per objective, in order");
    }
    if (!any_positive) {
      throw InputError(cw->mark, "pareto.choose_weights", "every weight is 0; at least one must be > 0");
    }
  }
  return pa;
}

SectionReader read_sweep(const SectionReader& top, StudySpec& spec) {
  const SectionReader sw = study_section(top.get("sweep"), "sweep", top.key_mark("sweep"),
                                         {"method", "levels", "points", "max_points"}, "{method: grid, levels: 5}");
  const std::string sweep_method = sw.choice("method", {"grid", "lhs", "sobol"}).value_or("grid");
  spec.sweep.method = sweep_method == "lhs"     ? SweepSpec::Method::kLatinHypercube
                      : sweep_method == "sobol" ? SweepSpec::Method::kSobol
                                                : SweepSpec::Method::kGrid;
  spec.sweep.levels = static_cast<int>(sw.integer("levels", {2, 100000}).value_or(spec.sweep.levels));
  spec.sweep.points = static_cast<std::size_t>(sw.integer("points", {1, 100000000}).value_or(64));
  spec.sweep.max_points = static_cast<std::size_t>(sw.integer("max_points", {1, 100000000}).value_or(100000));
  return sw;
}

// Whether a metric of the study reads the stiffness curve: then its best
// design's curve is worth drawing by default. A study of wear lives or
// stresses alone leaves the curve (about 1.5 s of a small study with its
// plot) to `output.stiffness_curve: on`.
bool reads_stiffness_curve(const StudySpec& spec) {
  for (const metrics::MetricRequest& r : spec.all_metrics())
    if (metrics::find_metric(r.name).models.contains(metrics::Model::kStiffnessCurve)) return true;
  return false;
}

void read_output_and_limits(const SectionReader& top, StudySpec& spec) {
  const SectionReader out = study_section(top.get("output"), "output", top.key_mark("output"),
                                          {"plots", "report", "stiffness_curve"}, "{plots: on, report: on}");
  spec.output.plots = out.flag("plots", true);
  spec.output.report = out.flag("report", true);
  spec.output.stiffness_curve = out.flag("stiffness_curve", reads_stiffness_curve(spec));
  const SectionReader lim = study_section(top.get("limits"), "limits", top.key_mark("limits"),
                                          {"max_discrete_combinations"}, "{max_discrete_combinations: 256}");
  spec.max_discrete_combinations =
      static_cast<std::size_t>(lim.integer("max_discrete_combinations", {1, 100000000}).value_or(256));
}

}  // namespace

SettingsSections read_settings_sections(const SectionReader& top, StudySpec& spec) {
  SectionReader solver = read_solver(top, spec);
  SectionReader pareto = read_pareto(top, spec);
  SectionReader sweep = read_sweep(top, spec);
  read_output_and_limits(top, spec);
  return SettingsSections{std::move(solver), std::move(pareto), std::move(sweep)};
}

}  // namespace rackopt::studyfile
