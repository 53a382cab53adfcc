#include "rackopt/study/evaluation_ledger.hpp"

#include "rackopt/core/parallel_for.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace rackopt::study {

namespace {

// Shown once each; a sweep over a region with undercut would otherwise list
// one warning per design.
constexpr std::size_t kMaxWarnings = 20;

}  // namespace

std::string bits_key(std::span<const double> x) {
  std::string k(x.size() * sizeof(double), '\0');
  if (!x.empty()) std::memcpy(k.data(), x.data(), k.size());
  return k;
}

EvaluationLedger::EvaluationLedger(const StudySpec& spec, const RunOptions& options, StudyProblem& base)
    : spec_(spec),
      options_(options),
      base_(base),
      threads_(resolve_threads(options.threads)),
      executor_(options.executor ? options.executor : std::shared_ptr<DesignExecutor>(make_thread_executor(threads_))) {}

void EvaluationLedger::open_store(const std::string& path) {
  record::StoreOptions store_options;
  store_options.fingerprint_format = kStudyFingerprintFormat;
  // The units of the record's real columns (docs/recorder.md, "Queries").
  for (const auto& v : spec_.variables) {
    const std::string_view unit = si_unit(v.kind);
    store_options.units[v.key] = unit.empty() ? "-" : std::string(unit);  // "-" as for the metrics
  }
  for (const auto& m : spec_.all_metrics())
    store_options.units[metrics::to_string(m)] = std::string(metrics::find_metric(m.name).unit);
  store_.emplace(record::EvaluationStore::open(path, study_fingerprint(spec_), base_.variable_keys(), options_.resume,
                                               store_options));
  // Rows of earlier runs have ids up to this one (a row removed for a bad
  // checksum leaves a gap, so not size()).
  preexisting_rows_ = store_->last_id();
  result_.damaged_records = store_->damaged_rows_removed();
  result_.unchecked_records = store_->unchecked_rows();
  store_->set_meta("status", "running");
  store_->set_meta("kind", kind_name(spec_.kind));
  store_->set_meta("study", spec_.name);
}

bool EvaluationLedger::stop_requested() {
  if (!stopped_ && options_.stop && options_.stop()) stopped_ = true;
  return stopped_;
}

// The same metric doubles through the same mapping give bit-identical
// numbers, so a resumed solver sees what it saw before.
DesignEvaluation EvaluationLedger::rebuild(const record::RecordedEvaluation& r) const {
  DesignEvaluation d;
  d.x = r.x;
  const auto& labels = base_.metric_labels();
  d.metric_values.assign(labels.size(), 0.0);
  d.metric_ok.assign(labels.size(), false);
  for (const auto& [name, value] : r.metrics) {
    const auto it = std::find(labels.begin(), labels.end(), name);
    if (it == labels.end()) continue;
    const auto i = static_cast<std::size_t>(it - labels.begin());
    d.metric_values[i] = value;
    d.metric_ok[i] = true;
  }
  d.evaluation = base_.map_metrics(d.metric_values, d.metric_ok, r.message);
  d.warnings = r.warnings;
  d.models = r.models;
  if (!r.ok && d.evaluation.ok()) {
    // Recorded as failed although every metric is present: trust the record.
    d.evaluation = solvers::Evaluation{};
    d.evaluation.status = solvers::EvaluationStatus::kFailed;
    d.evaluation.message = r.message;
  }
  return d;
}

std::optional<Obtained> EvaluationLedger::lookup(std::span<const double> x) {
  std::optional<record::RecordedEvaluation> r = store_->find(x);
  if (!r) return std::nullopt;
  Obtained o{rebuild(*r), Origin::kRepeat, r->id};
  if (r->id <= preexisting_rows_ && counted_rows_.insert(r->id).second) o.origin = Origin::kReused;
  return o;
}

std::optional<DesignEvaluation> EvaluationLedger::recorded(std::span<const double> x) const {
  std::optional<record::RecordedEvaluation> r = store_->find(x);
  if (!r) return std::nullopt;
  return rebuild(*r);
}

Obtained EvaluationLedger::obtain(const StudyProblem& p, std::span<const double> x) {
  return std::move(obtain_batch(p, {std::vector<double>(x.begin(), x.end())}).front());
}

std::vector<Obtained> EvaluationLedger::obtain_batch(const StudyProblem& p,
                                                     const std::vector<std::vector<double>>& xs) {
  std::vector<std::optional<Obtained>> got(xs.size());
  std::vector<std::vector<double>> missing;
  std::vector<std::size_t> where;
  // A design asked for twice in one batch (runs in lockstep that start from
  // the same point) is evaluated once; the later copies are repeats, as
  // they would be had the batch come one design at a time.
  std::map<std::string, std::size_t> first_of;
  std::vector<std::pair<std::size_t, std::size_t>> repeats;  // (k, the earlier k it repeats)
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const auto [it, fresh] = first_of.emplace(bits_key(xs[k]), k);
    if (!fresh) {
      repeats.push_back({k, it->second});
      continue;
    }
    got[k] = lookup(xs[k]);
    if (!got[k]) {
      missing.push_back(xs[k]);
      where.push_back(k);
    }
  }
  if (!missing.empty()) {
    std::vector<DesignEvaluation> fresh = executor_->evaluate(p, missing, threads_);
    for (std::size_t j = 0; j < where.size(); ++j) got[where[j]] = Obtained{std::move(fresh[j]), Origin::kNew, 0};
  }
  for (const auto& [k, earlier] : repeats) got[k] = Obtained{got[earlier]->design, Origin::kRepeat, got[earlier]->id};
  std::vector<Obtained> out;
  out.reserve(xs.size());
  for (auto& o : got) out.push_back(std::move(*o));
  return out;
}

void EvaluationLedger::settle(const Obtained& o, const std::string& label, bool gradient_probe, bool ranks) {
  if (o.origin == Origin::kRepeat) return;
  const DesignEvaluation& d = o.design;
  std::int64_t id = o.id;
  if (o.origin == Origin::kNew) {
    id = append(d, label, gradient_probe);
  } else {
    ++result_.reused_evaluations;
  }
  id_of_.emplace(bits_key(d.x), id);
  // New and reused alike, at the design's first use: a resumed run lists
  // the warnings in the order of an uninterrupted one.
  for (const auto& w : d.warnings) add_warning(w);
  tally_.add(d.warnings, id);
  ++result_.evaluations;
  if (!d.evaluation.ok()) ++result_.failed_evaluations;
  track(d, label, ranks);
  if (options_.progress) {
    Progress pr;
    pr.done = result_.evaluations;
    pr.budget = std::max(budget_, pr.done);
    pr.failed = result_.failed_evaluations;
    if (best_) pr.best = best_->objectives.empty() ? std::optional<double>() : best_->objectives[0];
    pr.phase = phase_;
    options_.progress(pr);
  }
}

DesignResult EvaluationLedger::to_result(const DesignEvaluation& d, const std::string& label) const {
  DesignResult r;
  r.x = d.x;
  r.metric_labels = base_.metric_labels();
  r.metric_values = d.metric_values;
  r.metric_ok = d.metric_ok;
  r.ok = d.evaluation.ok();
  r.max_violation = solvers::max_violation(d.evaluation);
  r.feasible = solvers::is_feasible(d.evaluation, spec_.solver.constraint_tolerance);
  r.message = d.evaluation.message;
  r.warnings = d.warnings;
  r.label = label;
  if (const auto it = id_of_.find(bits_key(d.x)); it != id_of_.end()) r.evaluation_id = it->second;
  r.objectives = own_objectives(d);
  return r;
}

std::vector<double> EvaluationLedger::own_objectives(const DesignEvaluation& d) const {
  std::vector<double> out;
  const auto& labels = base_.metric_labels();
  for (const auto& o : spec_.objectives) {
    const auto i = static_cast<std::size_t>(
        std::find(labels.begin(), labels.end(), metrics::to_string(o.metric)) - labels.begin());
    out.push_back(i < d.metric_values.size() ? d.metric_values[i] : 0.0);
  }
  return out;
}

std::optional<DesignResult> EvaluationLedger::best_of_tag(std::size_t t) const {
  const auto it = tag_best_.find(t);
  return it == tag_best_.end() ? std::nullopt : it->second;
}

std::optional<DesignResult> EvaluationLedger::least_infeasible_of_tag(std::size_t t) const {
  const auto it = tag_least_.find(t);
  return it == tag_least_.end() ? std::nullopt : it->second;
}

std::vector<std::string> EvaluationLedger::warnings() const {
  std::vector<std::string> w = warnings_;
  if (dropped_warnings_ > 0)
    w.push_back("... and " + std::to_string(dropped_warnings_) + " more distinct model warnings");
  return w;
}

std::int64_t EvaluationLedger::append(const DesignEvaluation& d, const std::string& label, bool gradient_probe) {
  record::RecordedEvaluation e;
  e.phase = label;
  e.x = d.x;
  e.objectives = d.evaluation.objectives;
  e.inequality = d.evaluation.inequality;
  e.equality = d.evaluation.equality;
  const auto& labels = base_.metric_labels();
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (d.metric_ok[i]) e.metrics.emplace_back(labels[i], d.metric_values[i]);
  e.ok = d.evaluation.ok();
  e.message = d.evaluation.message;
  e.gradient_probe = gradient_probe;
  e.seconds = std::isfinite(d.seconds) ? d.seconds : 0.0;
  e.warnings = d.warnings;
  e.models = d.models;
  return store_->append(e);
}

std::vector<std::size_t> EvaluationLedger::tags_ranked() const {
  std::set<std::size_t> tags;
  for (const auto& entry : tag_best_) tags.insert(entry.first);
  for (const auto& entry : tag_least_) tags.insert(entry.first);
  return {tags.begin(), tags.end()};
}

void EvaluationLedger::add_warning(const std::string& w) {
  if (!warning_set_.insert(w).second) return;
  if (warnings_.size() < kMaxWarnings) {
    warnings_.push_back(w);
  } else {
    ++dropped_warnings_;
  }
}

// Best feasible (by the minimized objective 0, first wins ties), least
// infeasible (smallest violation among ok designs) and the history.
void EvaluationLedger::track(const DesignEvaluation& d, const std::string& label, bool ranks) {
  const solvers::Evaluation& e = d.evaluation;
  if (e.ok()) any_ok_ = true;
  const bool has_objective = !spec_.objectives.empty();
  const std::size_t tag = tagger_ ? tagger_(d.x) : 0;
  if (ranks && e.ok()) {
    if (solvers::is_feasible(e, spec_.solver.constraint_tolerance)) {
      const double f = has_objective ? e.objectives[0] : 0.0;
      if (!best_ || (has_objective && f < best_scaled_)) {
        best_ = to_result(d, label);
        best_scaled_ = f;
        best_tag_ = tag;
      }
      auto& tb = tag_best_[tag];
      if (!tb || (has_objective && f < tag_best_scaled_[tag])) {
        tb = to_result(d, label);
        tag_best_scaled_[tag] = f;
      }
    } else {
      const double v = solvers::max_violation(e);
      if (!least_ || v < least_->max_violation) least_ = to_result(d, label);
      auto& tl = tag_least_[tag];
      if (!tl || v < tl->max_violation) tl = to_result(d, label);
    }
  }
  if (spec_.kind == StudyKind::kPareto && solvers::is_feasible(e, spec_.solver.constraint_tolerance)) {
    // The solver minimizes value / scale (negated when maximized): times the
    // scale is the minimized value in its own unit.
    std::vector<double> v = e.objectives;
    for (std::size_t i = 0; i < v.size(); ++i) v[i] *= base_.objective_scales()[i];
    feasible_objectives_.emplace_back(result_.best_history.size(), std::move(v));
  }
  const bool maximize = has_objective && spec_.objectives[0].maximize;
  double h = maximize ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  if (best_ && has_objective) h = best_->objectives[0];
  result_.best_history.push_back(h);
}

}  // namespace rackopt::study
