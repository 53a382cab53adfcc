#include "rackopt/study/study_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "rackopt/core/interrupt.hpp"
#include "rackopt/core/parallel_for.hpp"
#include "rackopt/doe/samplers.hpp"
#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/best_design_curve.hpp"
#include "rackopt/study/fe_verification.hpp"
#include "rackopt/study/fidelity_settings.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::study {

namespace {

using Clock = std::chrono::steady_clock;

// Shown once each; a sweep over a region with undercut would otherwise list
// one warning per design.
constexpr std::size_t kMaxWarnings = 20;

std::string bits_key(std::span<const double> x) {
  std::string k(x.size() * sizeof(double), '\0');
  if (!x.empty()) std::memcpy(k.data(), x.data(), k.size());
  return k;
}

InputError study_error(const StudySpec& spec, const std::string& key, const std::string& message) {
  return InputError(SourceMark{spec.file, 0, 0}, key, message);
}

unsigned resolve_threads(unsigned requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? hw : 1;
}

// Where a design's result came from.
enum class Origin {
  kNew,     // evaluated now: append to the store, count
  kReused,  // recorded by an earlier (interrupted) run: count as reused
  kRepeat,  // already counted in this run (another sub-solve asked for it again)
};

struct Obtained {
  DesignEvaluation design;
  Origin origin = Origin::kNew;
};

class Runner {
 public:
  Runner(const StudySpec& spec, const RunOptions& options, StudyProblem& base)
      : spec_(spec), options_(options), base_(base), threads_(resolve_threads(options.threads)) {}

  void open_store(const std::string& path) {
    store_.emplace(record::EvaluationStore::open(path, study_fingerprint(spec_), base_.variable_keys(), options_.resume));
    preexisting_rows_ = static_cast<std::int64_t>(store_->size());
    store_->set_meta("status", "running");
    store_->set_meta("kind", kind_name(spec_.kind));
    store_->set_meta("study", spec_.name);
  }

  record::EvaluationStore& store() { return *store_; }
  StudyResult& result() { return result_; }
  unsigned threads() const { return threads_; }
  void set_budget(std::size_t b) { budget_ = b; }
  void set_phase(std::string p) { phase_ = std::move(p); }

  // Latched: once the user asked to stop, every later poll says so.
  bool stop_requested() {
    if (!stopped_ && options_.stop && options_.stop()) stopped_ = true;
    return stopped_;
  }
  bool stopped() const { return stopped_; }

  // The recorded evaluation turned back into what the solver saw: the same
  // metric doubles through the same mapping give bit-identical numbers.
  DesignEvaluation rebuild(const record::RecordedEvaluation& r) const {
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
    if (!r.ok && d.evaluation.ok()) {
      // Recorded as failed although every metric is present: trust the record.
      d.evaluation = solvers::Evaluation{};
      d.evaluation.status = solvers::EvaluationStatus::kFailed;
      d.evaluation.message = r.message;
    }
    return d;
  }

  // Looks x up in the store (driving thread only).
  std::optional<Obtained> lookup(std::span<const double> x) {
    std::optional<record::RecordedEvaluation> r = store_->find(x);
    if (!r) return std::nullopt;
    Obtained o{rebuild(*r), Origin::kRepeat};
    if (r->id <= preexisting_rows_ && counted_rows_.insert(r->id).second) o.origin = Origin::kReused;
    return o;
  }

  // The recorded result of x without counting it (x was counted when it was
  // evaluated).
  std::optional<DesignEvaluation> recorded(std::span<const double> x) const {
    std::optional<record::RecordedEvaluation> r = store_->find(x);
    if (!r) return std::nullopt;
    return rebuild(*r);
  }

  Obtained obtain(const StudyProblem& p, std::span<const double> x) {
    if (auto o = lookup(x)) return std::move(*o);
    return Obtained{p.evaluate_design(x, threads_), Origin::kNew};
  }

  // Records (when new) and counts (unless a repeat) one design.
  void settle(const Obtained& o, const std::string& label, bool gradient_probe, bool ranks = true) {
    if (o.origin == Origin::kRepeat) return;
    const DesignEvaluation& d = o.design;
    if (o.origin == Origin::kNew) {
      append(d, label, gradient_probe);
    } else {
      ++result_.reused_evaluations;
    }
    // New and reused alike, at the design's first use: a resumed run lists
    // the warnings in the order of an uninterrupted one.
    for (const auto& w : d.warnings) add_warning(w);
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

  DesignResult to_result(const DesignEvaluation& d, const std::string& label) const {
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
    r.objectives = own_objectives(d);
    return r;
  }

  std::vector<double> own_objectives(const DesignEvaluation& d) const {
    std::vector<double> out;
    const auto& labels = base_.metric_labels();
    for (const auto& o : spec_.objectives) {
      const auto i = static_cast<std::size_t>(
          std::find(labels.begin(), labels.end(), metrics::to_string(o.metric)) - labels.begin());
      out.push_back(i < d.metric_values.size() ? d.metric_values[i] : 0.0);
    }
    return out;
  }

  const std::optional<DesignResult>& best() const { return best_; }
  const std::optional<DesignResult>& least_infeasible() const { return least_; }
  bool any_ok() const { return any_ok_; }
  std::size_t best_tag() const { return best_tag_; }
  // Best feasible / least infeasible design recorded under tag t.
  std::optional<DesignResult> best_of_tag(std::size_t t) const {
    const auto it = tag_best_.find(t);
    return it == tag_best_.end() ? std::nullopt : it->second;
  }
  std::optional<DesignResult> least_infeasible_of_tag(std::size_t t) const {
    const auto it = tag_least_.find(t);
    return it == tag_least_.end() ? std::nullopt : it->second;
  }
  void set_tag(std::size_t t) { tag_ = t; }

  std::vector<std::string> warnings() const {
    std::vector<std::string> w = warnings_;
    if (dropped_warnings_ > 0)
      w.push_back("... and " + std::to_string(dropped_warnings_) + " more distinct model warnings");
    return w;
  }

 private:
  void append(const DesignEvaluation& d, const std::string& label, bool gradient_probe) {
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
    store_->append(e);
  }

  void add_warning(const std::string& w) {
    if (!warning_set_.insert(w).second) return;
    if (warnings_.size() < kMaxWarnings) {
      warnings_.push_back(w);
    } else {
      ++dropped_warnings_;
    }
  }

  // Best feasible (by the minimized objective 0, first wins ties), least
  // infeasible (smallest violation among ok designs) and the history.
  void track(const DesignEvaluation& d, const std::string& label, bool ranks) {
    const solvers::Evaluation& e = d.evaluation;
    if (e.ok()) any_ok_ = true;
    const bool has_objective = !spec_.objectives.empty();
    if (ranks && e.ok()) {
      if (solvers::is_feasible(e, spec_.solver.constraint_tolerance)) {
        const double f = has_objective ? e.objectives[0] : 0.0;
        if (!best_ || (has_objective && f < best_scaled_)) {
          best_ = to_result(d, label);
          best_scaled_ = f;
          best_tag_ = tag_;
        }
        auto& tb = tag_best_[tag_];
        if (!tb || (has_objective && f < tag_best_scaled_[tag_])) {
          tb = to_result(d, label);
          tag_best_scaled_[tag_] = f;
        }
      } else {
        const double v = solvers::max_violation(e);
        if (!least_ || v < least_->max_violation) least_ = to_result(d, label);
        auto& tl = tag_least_[tag_];
        if (!tl || v < tl->max_violation) tl = to_result(d, label);
      }
    }
    const bool maximize = has_objective && spec_.objectives[0].maximize;
    double h = maximize ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    if (best_ && has_objective) h = best_->objectives[0];
    result_.best_history.push_back(h);
  }

  const StudySpec& spec_;
  const RunOptions& options_;
  StudyProblem& base_;
  unsigned threads_;
  std::optional<record::EvaluationStore> store_;
  std::int64_t preexisting_rows_ = 0;
  std::set<std::int64_t> counted_rows_;
  StudyResult result_;
  std::size_t budget_ = 0;
  std::string phase_;
  bool stopped_ = false;
  std::optional<DesignResult> best_, least_;
  double best_scaled_ = 0;
  std::size_t best_tag_ = 0, tag_ = 0;
  std::map<std::size_t, std::optional<DesignResult>> tag_best_, tag_least_;
  std::map<std::size_t, double> tag_best_scaled_;
  bool any_ok_ = false;
  std::set<std::string> warning_set_;
  std::vector<std::string> warnings_;
  std::size_t dropped_warnings_ = 0;
};

// The Problem handed to the solvers: a StudyProblem whose evaluations go
// through the store (resume) and are recorded when the adapter reports them
// (only then is gradient_probe known). Used on the driving thread only.
class RecordedProblem final : public solvers::Problem {
 public:
  RecordedProblem(Runner& runner, const StudyProblem& problem) : runner_(runner), problem_(problem) {}
  ~RecordedProblem() override = default;

  void set_label(std::string label) { label_ = std::move(label); }

  std::size_t dimension() const override { return problem_.dimension(); }
  std::vector<std::string> variable_names() const override { return problem_.variable_names(); }
  std::vector<double> lower_bounds() const override { return problem_.lower_bounds(); }
  std::vector<double> upper_bounds() const override { return problem_.upper_bounds(); }
  std::size_t num_objectives() const override { return problem_.num_objectives(); }
  std::size_t num_inequality() const override { return problem_.num_inequality(); }
  std::size_t num_equality() const override { return problem_.num_equality(); }

  solvers::Evaluation evaluate(std::span<const double> u) const override {
    settle_pending();
    const std::vector<double> x = problem_.to_design(u);
    pending_.emplace(Pending{bits_key(u), runner_.obtain(problem_, x)});
    return pending_->obtained.design.evaluation;
  }

  // The adapter's report of the evaluation just made.
  void observed(const solvers::EvaluationRecord& rec, const std::string& sub_label) const {
    if (!pending_ || pending_->u_key != bits_key(rec.x)) return;
    const std::string label = sub_label.empty() ? label_ : (label_.empty() ? sub_label : label_ + ": " + sub_label);
    Pending p = std::move(*pending_);
    pending_.reset();
    runner_.settle(p.obtained, label, rec.gradient_probe);
  }

  // An evaluation the adapter made but did not report (it stopped): still
  // recorded, so nothing computed is lost.
  void settle_pending() const {
    if (!pending_) return;
    Pending p = std::move(*pending_);
    pending_.reset();
    runner_.settle(p.obtained, label_, false);
  }

 private:
  struct Pending {
    std::string u_key;
    Obtained obtained;
  };
  Runner& runner_;
  const StudyProblem& problem_;
  std::string label_;
  mutable std::optional<Pending> pending_;
};

std::string combination_phase(const StudyProblem& p) {
  if (p.num_combinations() <= 1) return "";
  return "combination " + std::to_string(p.combination() + 1) + "/" + std::to_string(p.num_combinations()) + " (" +
         p.combination_label() + ")";
}

// Evaluates designs in parallel; results by index. Exceptions (bugs, store
// errors are not possible here) are carried to the calling thread.
void evaluate_parallel(const StudyProblem& p, const std::vector<std::vector<double>>& xs,
                       const std::vector<std::size_t>& which, std::vector<std::optional<DesignEvaluation>>& out,
                       unsigned threads) {
  parallel_for(which.size(), threads, [&](std::size_t k) { out[which[k]] = p.evaluate_design(xs[which[k]], 1); });
}

std::vector<std::vector<double>> sweep_points(const StudySpec& spec) {
  const auto& vars = spec.variables;
  if (vars.empty()) throw study_error(spec, "variables", "a sweep needs at least one design variable");
  try {
    if (spec.sweep.method == SweepSpec::Method::kGrid) {
      std::vector<std::vector<double>> levels;
      for (const auto& v : vars) {
        if (v.discrete()) {
          levels.push_back(v.values);
        } else {
          levels.push_back(doe::linspace_levels(v.lower, v.upper, v.levels > 0 ? v.levels : spec.sweep.levels));
        }
      }
      return doe::full_grid(levels, spec.sweep.max_points);
    }
    if (spec.sweep.points > spec.sweep.max_points)
      throw std::invalid_argument(std::to_string(spec.sweep.points) + " points exceed sweep.max_points = " +
                                  std::to_string(spec.sweep.max_points));
    std::vector<double> lo, hi;
    for (const auto& v : vars) {
      lo.push_back(v.lower);
      hi.push_back(v.upper);
    }
    std::vector<std::vector<double>> pts =
        spec.sweep.method == SweepSpec::Method::kSobol ? doe::sobol_points(lo, hi, spec.sweep.points, spec.seed)
                                                       : doe::latin_hypercube(lo, hi, spec.sweep.points, spec.seed);
    // Discrete variables: the nearest allowed value (the lower one on a tie).
    for (auto& p : pts) {
      for (std::size_t i = 0; i < vars.size(); ++i) {
        if (!vars[i].discrete()) continue;
        const auto& vals = vars[i].values;
        double best = vals.front();
        for (double v : vals)
          if (std::abs(v - p[i]) < std::abs(best - p[i])) best = v;
        p[i] = best;
      }
    }
    return pts;
  } catch (const std::invalid_argument& e) {
    throw study_error(spec, "sweep", std::string("cannot build the sweep: ") + e.what());
  }
}

// Objective-0 order in the metric's own sense (then the other objectives).
bool front_less(const DesignResult& a, const DesignResult& b) {
  for (std::size_t i = 0; i < a.objectives.size(); ++i) {
    if (a.objectives[i] < b.objectives[i]) return true;
    if (b.objectives[i] < a.objectives[i]) return false;
  }
  return false;
}

}  // namespace

StudyResult run_study(const StudySpec& spec, const RunOptions& options) {
  const auto t0 = Clock::now();

  // ---- set-up checks: everything that can be refused before a file is written
  StudyProblem base(spec);
  const std::size_t n_obj = spec.objectives.size();
  if (spec.kind == StudyKind::kOptimize && n_obj != 1)
    throw study_error(spec, "objectives", "an optimize study needs exactly one objective, found " +
                                              std::to_string(n_obj) + " (use kind: pareto for 2 or 3)");
  if (spec.kind == StudyKind::kPareto && (n_obj < 2 || n_obj > 3))
    throw study_error(spec, "objectives",
                      "a pareto study needs 2 or 3 objectives, found " + std::to_string(n_obj));
  const bool enumerates = spec.kind == StudyKind::kOptimize || spec.kind == StudyKind::kPareto;
  if (enumerates && base.num_combinations() > spec.max_discrete_combinations) {
    std::string names;
    for (std::size_t i : base.discrete_indices())
      names += (names.empty() ? "" : ", ") + spec.variables[i].key + " (" +
               std::to_string(spec.variables[i].values.size()) + " values)";
    throw study_error(spec, "variables",
                      "the discrete variables " + names + " give " + std::to_string(base.num_combinations()) +
                          " combinations, more than max_discrete_combinations = " +
                          std::to_string(spec.max_discrete_combinations) +
                          "; use fewer values or make some of them continuous");
  }
  {
    // The start design must be a drive the loader accepts, and the metrics
    // must be configured (wear section, duty, allowables): set-up errors.
    std::optional<Drive> start_drive;
    try {
      start_drive.emplace(base.drive_at(base.start_design()));
    } catch (const DesignError&) {
      // An impossible start design is a failed evaluation, not a set-up error.
    }
    if (start_drive) metrics::check_metric_requests(*start_drive, base.metric_requests(), spec.metric_options);
  }
  solvers::SolverSettings solver = spec.solver;
  solver.seed = spec.seed;
  if (spec.kind == StudyKind::kOptimize && base.dimension() > 0) {
    const std::string msg = solvers::check_solver_settings(solver, base, base.start_unit());
    if (!msg.empty()) throw study_error(spec, "solver", msg);
  }
  std::vector<std::vector<double>> points;
  if (spec.kind == StudyKind::kSweep) points = sweep_points(spec);

  // ---- store
  std::filesystem::create_directories(options.out_dir.empty() ? "." : options.out_dir);
  const std::filesystem::path out = options.out_dir.empty() ? std::filesystem::path(".") : std::filesystem::path(options.out_dir);
  const std::string db_path = (out / "evaluations.sqlite").string();
  const std::string csv_path = (out / "evaluations.csv").string();
  Runner run(spec, options, base);
  run.open_store(db_path);
  StudyResult& result = run.result();

  // ---- the start design: the scale of automatic objectives, and the design
  // of evaluate/reliability. A sweep without automatic scales skips it.
  bool needs_start = spec.kind != StudyKind::kSweep;
  for (const auto& o : spec.objectives) needs_start = needs_start || o.scale <= 0;
  const std::size_t combos = base.num_combinations();
  std::size_t budget = needs_start ? 1 : 0;
  switch (spec.kind) {
    case StudyKind::kSweep: budget += points.size(); break;
    case StudyKind::kOptimize: budget += combos * (base.dimension() > 0 ? spec.solver.max_evaluations : 1); break;
    case StudyKind::kPareto:
      budget += combos * (base.dimension() > 0 ? spec.pareto.points * spec.solver.max_evaluations : 1);
      break;
    default: break;
  }
  run.set_budget(budget);

  std::optional<Obtained> start;
  if (needs_start && !run.stop_requested()) {
    run.set_phase("start");
    const std::vector<double> x = base.start_design();
    // The scales come from the metric values only, so a rebuilt record and a
    // fresh evaluation give the same scales.
    start = run.lookup(x);
    try {
      // One evaluation, nothing of it recorded before it ends: Ctrl-C ends
      // a long one (a Monte Carlo life at R and its fit) at once.
      const ImmediateStopScope immediate;
      if (!start) start = Obtained{base.evaluate_design(x, run.threads()), Origin::kNew};
    } catch (const Interrupted&) {
      // Ctrl-C inside one long evaluation (a Monte Carlo life at R): nothing
      // of it is recorded; the study stops and --resume evaluates it again.
      run.stop_requested();
    }
  }
  if (start) {
    base.set_objective_scales_from(start->design);
    start->design.evaluation = base.map_metrics(start->design.metric_values, start->design.metric_ok,
                                                start->design.evaluation.message);
    run.settle(*start, "start", false, spec.kind != StudyKind::kSweep);
  }

  std::string status;
  switch (spec.kind) {
    case StudyKind::kEvaluate:
    case StudyKind::kReliability: {
      if (!start) {
        status = "stopped";
        break;
      }
      result.best = run.to_result(start->design, "start");
      status = start->design.evaluation.ok() ? "ok" : "all_failed";
      if (spec.kind == StudyKind::kReliability && start->design.evaluation.ok() && run.stop_requested()) {
        status = "stopped";  // the reliability analysis did not run
      } else if (spec.kind == StudyKind::kReliability && start->design.evaluation.ok()) {
        try {
          const Drive design = base.drive_at(start->design.x);
          WearReliabilityOptions wo = wear_reliability_options(design);
          wo.samples = spec.metric_options.reliability_samples;
          wo.seed = spec.metric_options.reliability_seed;
          wo.threads = run.threads();
          if (spec.metric_options.bootstrap_replicates > 0)
            wo.bootstrap_replicates = spec.metric_options.bootstrap_replicates;
          wo.stop = options.stop;  // thread-safe (polled by the sampling workers)
          // Everything recorded is committed; the analysis itself is not
          // recorded (--resume redoes it): Ctrl-C may end it at once.
          run.store().flush();
          const ImmediateStopScope immediate;
          result.reliability = std::make_shared<const WearReliabilityResult>(run_wear_reliability(design, wo));
        } catch (const Interrupted&) {
          run.stop_requested();  // latch: the study stopped; --resume redoes the Monte Carlo
          status = "stopped";
        } catch (const std::runtime_error& e) {  // DesignError or InputError: the summary is still written
          status = "all_failed";
          result.solver_message = std::string("wear reliability: ") + e.what();
        }
      }
      break;
    }

    case StudyKind::kSweep: {
      run.set_phase("sweep");
      const std::size_t chunk = std::max<std::size_t>(8, 8 * static_cast<std::size_t>(run.threads()));
      for (std::size_t begin = 0; begin < points.size(); begin += chunk) {
        if (run.stop_requested()) break;
        const std::size_t end = std::min(points.size(), begin + chunk);
        const std::size_t n = end - begin;
        // Per chunk: store hits and in-chunk duplicates on this thread, the
        // rest in parallel, then everything recorded in sampler order (so the
        // store and the result do not depend on the thread count).
        std::vector<std::vector<double>> xs(points.begin() + static_cast<std::ptrdiff_t>(begin),
                                            points.begin() + static_cast<std::ptrdiff_t>(end));
        std::vector<std::optional<Obtained>> got(n);
        std::vector<std::optional<DesignEvaluation>> fresh(n);
        std::vector<std::size_t> misses;
        std::unordered_map<std::string, std::size_t> first_in_chunk;
        std::vector<std::size_t> duplicate_of(n, SIZE_MAX);
        for (std::size_t k = 0; k < n; ++k) {
          const std::string key = bits_key(xs[k]);
          if (auto it = first_in_chunk.find(key); it != first_in_chunk.end()) {
            duplicate_of[k] = it->second;
            continue;
          }
          first_in_chunk.emplace(key, k);
          got[k] = run.lookup(xs[k]);
          if (!got[k]) misses.push_back(k);
        }
        evaluate_parallel(base, xs, misses, fresh, run.threads());
        for (std::size_t k = 0; k < n; ++k) {
          const std::string label = "sweep " + std::to_string(begin + k);
          const std::size_t j = duplicate_of[k] != SIZE_MAX ? duplicate_of[k] : k;
          Obtained o = got[j] ? *got[j] : Obtained{*fresh[j], Origin::kNew};
          if (j != k) o.origin = Origin::kRepeat;
          run.settle(o, label, false);  // ranks: progress and history show the best so far
          result.sweep_points.push_back(run.to_result(o.design, label));
        }
      }
      status = run.stopped() ? "stopped" : "ok";
      if (n_obj > 0) {
        const bool maximize = spec.objectives[0].maximize;
        for (const DesignResult& p : result.sweep_points) {
          if (!p.feasible) continue;
          if (!result.best || (maximize ? p.objectives[0] > result.best->objectives[0]
                                        : p.objectives[0] < result.best->objectives[0]))
            result.best = p;
        }
      }
      // A sweep without objectives has no best; the least infeasible point
      // only means something when no point is feasible.
      const bool any_feasible = std::any_of(result.sweep_points.begin(), result.sweep_points.end(),
                                            [](const DesignResult& p) { return p.feasible; });
      if (!result.best && !any_feasible) {
        for (const DesignResult& p : result.sweep_points)
          if (p.ok && (!result.least_infeasible || p.max_violation < result.least_infeasible->max_violation))
            result.least_infeasible = p;
      }
      if (!result.sweep_points.empty()) result.sensitivity = sweep_sensitivity(spec, result.sweep_points);
      if (!result.sweep_points.empty() && !run.stopped()) {
        bool any_ok = false;
        for (const auto& p : result.sweep_points) any_ok = any_ok || p.ok;
        if (!any_ok) status = "all_failed";
      }
      break;
    }

    case StudyKind::kOptimize: {
      std::vector<std::string> statuses(combos);
      std::string messages;
      for (std::size_t c = 0; c < combos; ++c) {
        if (run.stop_requested()) break;
        const StudyProblem p = base.for_combination(c);
        const std::string phase = combination_phase(p);
        run.set_phase(phase.empty() ? "optimize" : phase);
        run.set_tag(c);
        RecordedProblem rp(run, p);
        rp.set_label(phase.empty() ? "optimize" : phase);
        if (p.dimension() == 0) {
          // Every variable discrete: the enumeration is the optimization.
          const std::vector<double> x = p.to_design({});
          run.settle(run.obtain(p, x), phase.empty() ? "optimize" : phase, false);
          statuses[c] = "converged";
          continue;
        }
        solvers::SolverCallbacks cb;
        cb.observer = [&rp](const solvers::EvaluationRecord& rec) { rp.observed(rec, ""); };
        cb.stop = [&run] { return run.stop_requested(); };
        const solvers::SolverResult sr = solvers::minimize(rp, p.start_unit(), solver, cb);
        rp.settle_pending();
        statuses[c] = sr.status;
        if (!messages.empty()) messages += "; ";
        messages += (phase.empty() ? "" : phase + ": ") + sr.solver_message;
      }
      result.solver_message = messages;
      if (run.stopped()) {
        status = "stopped";
      } else if (!run.best()) {
        status = run.any_ok() ? "no_feasible_point" : "all_failed";
      } else {
        status = statuses[std::min(run.best_tag(), combos - 1)];
        if (status == "no_feasible_point" || status == "all_failed" || status.empty()) status = "converged";
      }
      result.best = run.best();
      if (combos > 1) {
        for (std::size_t c = 0; c < combos; ++c) {
          CombinationOutcome co;
          co.label = base.for_combination(c).combination_label();
          co.status = statuses[c];
          co.best = run.best_of_tag(c);
          if (!co.best) co.least_infeasible = run.least_infeasible_of_tag(c);
          result.per_combination.push_back(std::move(co));
        }
      }
      if (result.best && !run.stopped()) result.explanation = explain_optimum(base, result.best->x, run.threads());
      break;
    }

    case StudyKind::kPareto: {
      solvers::ParetoSettings ps = spec.pareto;
      ps.solver = solver;
      std::vector<DesignResult> candidates;
      std::vector<std::string> statuses;
      for (std::size_t c = 0; c < combos; ++c) {
        if (run.stop_requested()) break;
        const StudyProblem p = base.for_combination(c);
        const std::string phase = combination_phase(p);
        run.set_phase(phase.empty() ? "pareto" : phase);
        RecordedProblem rp(run, p);
        rp.set_label(phase);
        if (p.dimension() == 0) {
          const std::vector<double> x = p.to_design({});
          const Obtained o = run.obtain(p, x);
          run.settle(o, phase, false);
          const DesignResult d = run.to_result(o.design, phase);
          if (d.feasible) candidates.push_back(d);
          statuses.push_back(d.feasible ? "ok" : "no_feasible_point");
          continue;
        }
        solvers::ParetoCallbacks cb;
        cb.observer = [&rp, &run, &phase](const std::string& label, const solvers::EvaluationRecord& rec) {
          run.set_phase(phase.empty() ? label : phase + ": " + label);
          rp.observed(rec, label);
        };
        cb.stop = [&run] { return run.stop_requested(); };
        solvers::ParetoResult pr;
        const std::size_t before = result.evaluations;
        try {
          pr = solvers::pareto_front(rp, p.start_unit(), ps, cb);
        } catch (const std::invalid_argument& e) {
          if (result.evaluations != before) throw;
          throw study_error(spec, "solver", e.what());
        }
        rp.settle_pending();
        statuses.push_back(pr.status);
        for (const solvers::ParetoPoint& fp : pr.front) {
          const std::vector<double> x = p.to_design(fp.x);
          const std::string label = phase.empty() ? fp.label : phase + ": " + fp.label;
          std::optional<DesignEvaluation> o = run.recorded(x);
          const DesignEvaluation d = o ? *o : p.evaluate_design(x, run.threads());
          DesignResult r = run.to_result(d, label);
          if (r.feasible) candidates.push_back(std::move(r));
        }
      }
      // Merge the combinations' fronts: dominance on the minimized (scaled)
      // objectives equals dominance in the metrics' own senses.
      std::vector<std::vector<double>> vectors;
      for (const auto& d : candidates) {
        std::vector<double> v;
        for (std::size_t i = 0; i < n_obj; ++i) {
          const double s = base.objective_scales()[i];
          v.push_back((spec.objectives[i].maximize ? -d.objectives[i] : d.objectives[i]) / s);
        }
        vectors.push_back(std::move(v));
      }
      std::vector<std::vector<double>> kept_vectors;
      for (std::size_t i : solvers::non_dominated(vectors)) {
        result.front.push_back(candidates[i]);
        kept_vectors.push_back(vectors[i]);
      }
      std::vector<std::size_t> order(result.front.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return front_less(result.front[a], result.front[b]); });
      {
        std::vector<DesignResult> f;
        std::vector<std::vector<double>> v;
        for (std::size_t i : order) {
          f.push_back(result.front[i]);
          v.push_back(kept_vectors[i]);
        }
        result.front = std::move(f);
        kept_vectors = std::move(v);
      }
      if (!result.front.empty()) {
        // Chosen: closest to the ideal point (or least weighted sum) with every
        // objective normalized to [0, 1] over the front.
        std::vector<double> ideal(n_obj, std::numeric_limits<double>::infinity()),
            nadir(n_obj, -std::numeric_limits<double>::infinity());
        for (const auto& v : kept_vectors)
          for (std::size_t i = 0; i < n_obj; ++i) {
            ideal[i] = std::min(ideal[i], v[i]);
            nadir[i] = std::max(nadir[i], v[i]);
          }
        const bool weighted = spec.choose_weights.size() == n_obj;
        double best_score = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < kept_vectors.size(); ++k) {
          double score = 0;
          for (std::size_t i = 0; i < n_obj; ++i) {
            const double range = nadir[i] - ideal[i];
            const double t = range > 0 ? (kept_vectors[k][i] - ideal[i]) / range : 0.0;
            score += weighted ? spec.choose_weights[i] * t : t * t;
          }
          if (score < best_score) {
            best_score = score;
            result.chosen = k;
          }
        }
        result.best = result.front[*result.chosen];
      }
      if (run.stopped()) {
        status = "stopped";
      } else if (result.front.empty()) {
        status = run.any_ok() ? "no_feasible_point" : "all_failed";
      } else {
        status = combos == 1 && !statuses.empty() ? statuses[0] : "ok";
      }
      break;
    }
  }

  if (spec.kind != StudyKind::kSweep && !result.best && run.least_infeasible())
    result.least_infeasible = run.least_infeasible();
  if (result.best && result.best->ok) {
    try {
      result.best_drive = std::make_shared<const Drive>(base.drive_at(result.best->x));
    } catch (const std::exception&) {
      // An ok design has a drive; nothing to plot otherwise.
    }
  }
  attach_best_design_curve(spec, result);
  result.status = status;
  result.warnings = run.warnings();
  try {
    result.fidelity = fidelity_settings(base.drive_at(result.best ? result.best->x : base.start_design()), spec);
  } catch (const std::exception&) {
    // A design the loader refuses has no settings to show; the report says none.
  }
  result.database_path = db_path;
  result.evaluations_csv_path = csv_path;

  record::EvaluationStore& store = run.store();
  store.set_meta("status", run.stopped() ? "stopped" : "finished");
  store.set_meta("result_status", status);
  record::write_evaluations_csv(store, base.variable_keys(), base.metric_labels(), csv_path);
  verify_best_design_by_fe(spec, options, result);
  result.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return result;
}

}  // namespace rackopt::study
