#include "rackopt/study/study_problem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "rackopt/problem/design_point.hpp"

namespace rackopt::study {

namespace {

// One row of the constraint mapping: which metric, which bound, which scale.
struct ConstraintRow {
  std::size_t metric = 0;
  enum class Kind { kMin, kMax, kEquals } kind = Kind::kMin;
  double bound = 0;
  double scale = 1;
};

double bound_scale(double explicit_scale, double bound) {
  if (explicit_scale > 0) return explicit_scale;
  return bound != 0 ? std::abs(bound) : 1.0;
}

}  // namespace

struct StudyProblem::Shared {
  StudySpec spec;
  ProblemTree tree;
  std::vector<metrics::MetricRequest> requests;
  std::vector<std::string> labels;
  std::vector<std::size_t> continuous, discrete;
  std::vector<std::size_t> searched;  // of `discrete` (positions in it), the ones of two or more values
  std::vector<std::size_t> objective_metric;  // per objective: index into labels
  std::vector<ConstraintRow> inequality, equality;
  std::size_t combinations = 1;
};

StudyProblem::StudyProblem(const StudySpec& spec) {
  auto s = std::make_shared<Shared>();
  s->spec = spec;
  s->tree = study_problem_tree(spec);
  s->requests = spec.all_metrics();
  for (const auto& r : s->requests) s->labels.push_back(metrics::to_string(r));
  auto index_of = [&](const metrics::MetricRequest& r) {
    const std::string label = metrics::to_string(r);
    return static_cast<std::size_t>(std::find(s->labels.begin(), s->labels.end(), label) - s->labels.begin());
  };
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    if (spec.variables[i].discrete()) {
      s->discrete.push_back(i);
      // Saturating product: the runner refuses anything above
      // max_discrete_combinations anyway.
      const std::size_t n = spec.variables[i].values.size();
      s->combinations = s->combinations > (std::size_t{1} << 40) / n ? (std::size_t{1} << 40) : s->combinations * n;
    } else {
      s->continuous.push_back(i);
    }
  }
  for (std::size_t k = 0; k < s->discrete.size(); ++k)
    if (spec.variables[s->discrete[k]].values.size() >= 2) s->searched.push_back(k);
  for (const auto& o : spec.objectives) s->objective_metric.push_back(index_of(o.metric));
  for (const auto& c : spec.constraints) {
    const std::size_t m = index_of(c.metric);
    if (c.min) s->inequality.push_back({m, ConstraintRow::Kind::kMin, *c.min, bound_scale(c.scale, *c.min)});
    if (c.max) s->inequality.push_back({m, ConstraintRow::Kind::kMax, *c.max, bound_scale(c.scale, *c.max)});
    if (c.equals)
      s->equality.push_back({m, ConstraintRow::Kind::kEquals, *c.equals, bound_scale(c.scale, *c.equals)});
  }
  for (const auto& o : spec.objectives) objective_scales_.push_back(o.scale > 0 ? o.scale : 1.0);
  shared_ = std::move(s);
  *this = for_combination(0);
}

StudyProblem StudyProblem::for_combination(std::size_t c) const {
  if (c >= shared_->combinations) throw std::out_of_range("StudyProblem: combination out of range");
  StudyProblem p = *this;
  p.combination_ = c;
  p.combination_values_.assign(shared_->discrete.size(), 0.0);
  // Last discrete variable fastest, like doe::full_grid.
  std::size_t rest = c;
  for (std::size_t k = shared_->discrete.size(); k-- > 0;) {
    const auto& values = shared_->spec.variables[shared_->discrete[k]].values;
    p.combination_values_[k] = values[rest % values.size()];
    rest /= values.size();
  }
  return p;
}

StudyProblem StudyProblem::with_discrete_as_integers() const {
  StudyProblem p = for_combination(0);
  p.integers_ = true;
  return p;
}

std::size_t StudyProblem::combination_of(std::span<const double> x_si) const {
  std::size_t c = 0;
  for (std::size_t i : shared_->discrete) {
    const auto& values = shared_->spec.variables[i].values;
    const auto it = std::find(values.begin(), values.end(), i < x_si.size() ? x_si[i] : values.front());
    c = c * values.size() + static_cast<std::size_t>(it == values.end() ? 0 : it - values.begin());
  }
  return c;
}

namespace {

// The list entry nearest to `value` (the first of equally near ones).
std::size_t nearest_index(const std::vector<double>& values, double value) {
  std::size_t best = 0;
  for (std::size_t j = 1; j < values.size(); ++j)
    if (std::abs(values[j] - value) < std::abs(values[best] - value)) best = j;
  return best;
}

}  // namespace

const StudySpec& StudyProblem::spec() const { return shared_->spec; }
const ProblemTree& StudyProblem::tree() const { return shared_->tree; }
const std::vector<metrics::MetricRequest>& StudyProblem::metric_requests() const { return shared_->requests; }
const std::vector<std::string>& StudyProblem::metric_labels() const { return shared_->labels; }
const std::vector<std::size_t>& StudyProblem::continuous_indices() const { return shared_->continuous; }
const std::vector<std::size_t>& StudyProblem::discrete_indices() const { return shared_->discrete; }
std::size_t StudyProblem::num_combinations() const { return shared_->combinations; }
std::size_t StudyProblem::combination() const { return combination_; }

std::vector<std::string> StudyProblem::variable_keys() const {
  std::vector<std::string> keys;
  for (const auto& v : shared_->spec.variables) keys.push_back(v.key);
  return keys;
}

std::string StudyProblem::combination_label() const {
  std::string out;
  for (std::size_t k = 0; k < shared_->discrete.size(); ++k) {
    const DesignVariable& v = shared_->spec.variables[shared_->discrete[k]];
    if (!out.empty()) out += ", ";
    out += v.key + "=" + format_quantity(combination_values_[k], v.kind, v.unit);
  }
  return out;
}

std::vector<double> StudyProblem::start_design() const {
  const auto& vars = shared_->spec.variables;
  std::vector<double> x(vars.size());
  for (std::size_t i : shared_->continuous)
    x[i] = vars[i].start ? *vars[i].start : 0.5 * (vars[i].lower + vars[i].upper);
  for (std::size_t k = 0; k < shared_->discrete.size(); ++k) {
    const std::size_t i = shared_->discrete[k];
    x[i] = vars[i].start ? *vars[i].start : combination_values_[k];
  }
  return x;
}

std::vector<double> StudyProblem::start_unit() const {
  const auto& vars = shared_->spec.variables;
  const std::vector<double> x = start_design();
  std::vector<double> u;
  for (std::size_t i : shared_->continuous)
    u.push_back(std::clamp((x[i] - vars[i].lower) / (vars[i].upper - vars[i].lower), 0.0, 1.0));
  if (integers_)
    for (std::size_t k : shared_->searched) {
      const std::size_t i = shared_->discrete[k];
      u.push_back(static_cast<double>(nearest_index(vars[i].values, x[i])));
    }
  return u;
}

std::vector<double> StudyProblem::to_design(std::span<const double> u) const {
  const auto& vars = shared_->spec.variables;
  std::vector<double> x(vars.size());
  for (std::size_t k = 0; k < shared_->continuous.size(); ++k) {
    const DesignVariable& v = vars[shared_->continuous[k]];
    const double t = std::clamp(k < u.size() ? u[k] : 0.0, 0.0, 1.0);
    // Exact ends: a bound the user wrote must reach the drive unchanged.
    x[shared_->continuous[k]] = t == 1.0 ? v.upper : v.lower + t * (v.upper - v.lower);
  }
  for (std::size_t k = 0; k < shared_->discrete.size(); ++k) x[shared_->discrete[k]] = combination_values_[k];
  if (integers_) {
    const std::size_t n_c = shared_->continuous.size();
    for (std::size_t j = 0; j < shared_->searched.size(); ++j) {
      const std::size_t i = shared_->discrete[shared_->searched[j]];
      const auto& values = vars[i].values;
      const double index = n_c + j < u.size() ? std::round(u[n_c + j]) : 0.0;
      x[i] = values[static_cast<std::size_t>(std::clamp(index, 0.0, static_cast<double>(values.size() - 1)))];
    }
  }
  return x;
}

void StudyProblem::set_objective_scales_from(const DesignEvaluation& start) {
  const auto& objs = shared_->spec.objectives;
  for (std::size_t i = 0; i < objs.size(); ++i) {
    if (objs[i].scale > 0) continue;
    const std::size_t m = shared_->objective_metric[i];
    const bool usable = m < start.metric_ok.size() && start.metric_ok[m] && start.metric_values[m] != 0 &&
                        std::isfinite(start.metric_values[m]);
    objective_scales_[i] = usable ? std::abs(start.metric_values[m]) : 1.0;
  }
}

const std::vector<double>& StudyProblem::objective_scales() const { return objective_scales_; }

Drive StudyProblem::drive_at(std::span<const double> x_si) const {
  std::vector<std::pair<std::string, double>> values;
  values.reserve(x_si.size());
  for (std::size_t i = 0; i < x_si.size(); ++i) values.emplace_back(shared_->spec.variables[i].key, x_si[i]);
  return drive_with_values(shared_->tree, values);
}

solvers::Evaluation StudyProblem::map_metrics(std::span<const double> values, const std::vector<bool>& ok,
                                              const std::string& failure) const {
  solvers::Evaluation e;
  if (std::find(ok.begin(), ok.end(), false) != ok.end()) {
    e.status = solvers::EvaluationStatus::kFailed;
    e.message = failure.empty() ? std::string("a metric could not be computed") : failure;
    return e;
  }
  const auto& objs = shared_->spec.objectives;
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const double v = values[shared_->objective_metric[i]];
    e.objectives.push_back((objs[i].maximize ? -v : v) / objective_scales_[i]);
  }
  auto row_value = [&](const ConstraintRow& r) {
    const double v = values[r.metric];
    switch (r.kind) {
      case ConstraintRow::Kind::kMin: return (r.bound - v) / r.scale;
      case ConstraintRow::Kind::kMax:
      case ConstraintRow::Kind::kEquals: return (v - r.bound) / r.scale;
    }
    return 0.0;
  };
  for (const auto& r : shared_->inequality) e.inequality.push_back(row_value(r));
  for (const auto& r : shared_->equality) e.equality.push_back(row_value(r));
  return e;
}

DesignEvaluation StudyProblem::evaluate_design(std::span<const double> x_si, unsigned metric_options_threads) const {
  return to_evaluation(compute_metrics(x_si, metric_options_threads));
}

DesignMetrics StudyProblem::compute_metrics(std::span<const double> x_si, unsigned metric_options_threads) const {
  const auto t0 = std::chrono::steady_clock::now();
  DesignMetrics d;
  d.x.assign(x_si.begin(), x_si.end());
  const std::size_t n = shared_->labels.size();
  d.metric_values.assign(n, 0.0);
  d.metric_ok.assign(n, false);
  try {
    const Drive drive = drive_at(x_si);
    metrics::MetricOptions mo = shared_->spec.metric_options;
    mo.threads = std::max(1u, metric_options_threads);
    const metrics::MetricValues mv = metrics::evaluate_metrics(drive, shared_->requests, mo);
    for (std::size_t i = 0; i < n; ++i) {
      d.metric_ok[i] = mv.values[i].ok;
      d.metric_values[i] = mv.values[i].ok ? mv.values[i].value : 0.0;
    }
    if (const metrics::MetricValue* f = mv.first_failure()) {
      // Name the real cause: an impossible geometry fails every metric that
      // needs it, and is not the first such metric's failure.
      d.failure = f->cause == "geometry"
                      ? "the design's geometry is impossible (" + f->error_code + "): " + f->message
                      : f->label + " failed (" + f->error_code + (f->cause.empty() || f->cause == "metric"
                                                                      ? std::string()
                                                                      : ", in the " + f->cause + " model") +
                            "): " + f->message;
    }
    d.warnings = mv.warnings;
    d.models = mv.models_run.names();
  } catch (const InputError& e) {
    // A range check of the loader that only this design breaks (e.g. a
    // clearance below -0.25 m at a small module): an impossible design, not
    // a set-up error; the runner checks the start design up front.
    d.failure = "design refused by the problem checks (invalid_design): " + e.message() + " [" + e.key_path() + "]";
  } catch (const DesignError& e) {
    d.failure = "design rejected (" + e.code() + "): " + e.what();
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

DesignEvaluation StudyProblem::to_evaluation(DesignMetrics m) const {
  DesignEvaluation d;
  d.evaluation = map_metrics(m.metric_values, m.metric_ok, m.failure);
  d.x = std::move(m.x);
  d.metric_values = std::move(m.metric_values);
  d.metric_ok = std::move(m.metric_ok);
  d.warnings = std::move(m.warnings);
  d.models = std::move(m.models);
  d.seconds = m.seconds;
  return d;
}

std::size_t StudyProblem::dimension() const { return shared_->continuous.size() + num_integer(); }
std::size_t StudyProblem::num_integer() const { return integers_ ? shared_->searched.size() : 0; }

std::vector<std::string> StudyProblem::variable_names() const {
  std::vector<std::string> names;
  for (std::size_t i : shared_->continuous) names.push_back(shared_->spec.variables[i].key);
  if (integers_)
    for (std::size_t k : shared_->searched) names.push_back(shared_->spec.variables[shared_->discrete[k]].key + " (index)");
  return names;
}

std::vector<double> StudyProblem::lower_bounds() const { return std::vector<double>(dimension(), 0.0); }
std::vector<double> StudyProblem::upper_bounds() const {
  std::vector<double> up(shared_->continuous.size(), 1.0);
  if (integers_)
    for (std::size_t k : shared_->searched)
      up.push_back(static_cast<double>(shared_->spec.variables[shared_->discrete[k]].values.size() - 1));
  return up;
}
std::size_t StudyProblem::num_objectives() const { return shared_->spec.objectives.size(); }
std::size_t StudyProblem::num_inequality() const { return shared_->inequality.size(); }
std::size_t StudyProblem::num_equality() const { return shared_->equality.size(); }

solvers::Evaluation StudyProblem::evaluate(std::span<const double> u) const {
  return evaluate_design(to_design(u)).evaluation;
}

}  // namespace rackopt::study
