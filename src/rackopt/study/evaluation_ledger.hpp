// The evaluation ledger of one study run: every design goes through it. It
// looks a design up in the evaluation store (--resume), records a new one,
// counts evaluations (new, reused, failed), keeps the best feasible and the
// least infeasible design (overall and per discrete combination), the
// best-so-far history, the model warnings in first-use order, and reports
// progress. The kind drivers (study_kind_drivers.hpp) only decide WHICH
// designs to evaluate; the ledger makes a resumed run equal an
// uninterrupted one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/study/design_executor.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/study/warning_groups.hpp"

namespace rackopt::study {

// The bytes of x: the exact key of a design (no rounding, -0 != +0).
std::string bits_key(std::span<const double> x);

// Where a design's result came from.
enum class Origin {
  kNew,     // evaluated now: append to the store, count
  kReused,  // recorded by an earlier (interrupted) run: count as reused
  kRepeat,  // already counted in this run (another sub-solve asked for it again)
};

struct Obtained {
  DesignEvaluation design;
  Origin origin = Origin::kNew;
  std::int64_t id = 0;  // its id in the store when recorded before (kReused, kRepeat of one); 0 for kNew
};

class EvaluationLedger {
 public:
  // `options.threads` 0 = all cores. `base` maps metrics to objectives.
  EvaluationLedger(const StudySpec& spec, const RunOptions& options, StudyProblem& base);

  // Opens (or, with options.resume, reopens) the store at `path`; throws
  // std::runtime_error when it holds another study's results.
  void open_store(const std::string& path);

  record::EvaluationStore& store() { return *store_; }
  StudyResult& result() { return result_; }
  unsigned threads() const { return threads_; }
  void set_budget(std::size_t b) { budget_ = b; }
  void set_phase(std::string p) { phase_ = std::move(p); }
  // Later designs are ranked within the combination (tag) `of` names for
  // each (best_of_tag); without a tagger every design has tag 0.
  void set_tagger(std::function<std::size_t(std::span<const double>)> of) { tagger_ = std::move(of); }

  // Latched: once the user asked to stop, every later poll says so.
  bool stop_requested();
  // Latches the stop: an evaluation gave up part-way (rackopt::Interrupted,
  // a Monte Carlo that noticed Ctrl-C); nothing of it is recorded and the
  // study ends as stopped, its report written.
  void mark_stopped() { stopped_ = true; }
  bool stopped() const { return stopped_; }

  // x from the store, counted as reused at its first use in this run
  // (driving thread only); nullopt when not recorded.
  std::optional<Obtained> lookup(std::span<const double> x);
  // The recorded result of x without counting it (x was counted when it was
  // evaluated).
  std::optional<DesignEvaluation> recorded(std::span<const double> x) const;
  // From the store, else evaluated now (not yet recorded: settle does that).
  Obtained obtain(const StudyProblem& p, std::span<const double> x);
  // The same for independent designs, result i for xs[i]: store lookups in
  // order on this thread, the rest in one batch on the executor.
  std::vector<Obtained> obtain_batch(const StudyProblem& p, const std::vector<std::vector<double>>& xs);
  DesignExecutor& executor() { return *executor_; }

  // Records (when new) and counts (unless a repeat) one design; `ranks`
  // false keeps it out of best / least infeasible (a sweep's start design).
  void settle(const Obtained& o, const std::string& label, bool gradient_probe, bool ranks = true);

  DesignResult to_result(const DesignEvaluation& d, const std::string& label) const;

  const std::optional<DesignResult>& best() const { return best_; }
  const std::optional<DesignResult>& least_infeasible() const { return least_; }
  bool any_ok() const { return any_ok_; }
  std::size_t best_tag() const { return best_tag_; }
  // Best feasible / least infeasible design recorded under tag t.
  std::optional<DesignResult> best_of_tag(std::size_t t) const;
  std::optional<DesignResult> least_infeasible_of_tag(std::size_t t) const;
  // The tags of every ranked design so far (feasible or not), ascending.
  std::vector<std::size_t> tags_ranked() const;

  // pareto: every feasible design counted so far, in order, with its
  // objectives minimized in their own units (front_summary.hpp).
  const std::vector<FeasibleObjectives>& feasible_objectives() const { return feasible_objectives_; }
  // The distinct model warnings in first-use order, at most a screenful
  // plus a line counting the rest.
  std::vector<std::string> warnings() const;
  // Every settled design's warnings by kind (warning_groups.hpp).
  const WarningTally& warning_tally() const { return tally_; }

 private:
  // The recorded evaluation turned back into what the solver saw.
  DesignEvaluation rebuild(const record::RecordedEvaluation& r) const;
  std::vector<double> own_objectives(const DesignEvaluation& d) const;
  // Records d; returns its id in the store.
  std::int64_t append(const DesignEvaluation& d, const std::string& label, bool gradient_probe);
  void add_warning(const std::string& w);
  void track(const DesignEvaluation& d, const std::string& label, bool ranks);

  const StudySpec& spec_;
  const RunOptions& options_;
  StudyProblem& base_;
  unsigned threads_;
  std::shared_ptr<DesignExecutor> executor_;
  std::optional<record::EvaluationStore> store_;
  std::int64_t preexisting_rows_ = 0;
  std::set<std::int64_t> counted_rows_;
  StudyResult result_;
  std::size_t budget_ = 0;
  std::string phase_;
  bool stopped_ = false;
  std::optional<DesignResult> best_, least_;
  double best_scaled_ = 0;
  std::size_t best_tag_ = 0;
  std::function<std::size_t(std::span<const double>)> tagger_;
  std::map<std::size_t, std::optional<DesignResult>> tag_best_, tag_least_;
  std::map<std::size_t, double> tag_best_scaled_;
  bool any_ok_ = false;
  std::vector<FeasibleObjectives> feasible_objectives_;
  std::set<std::string> warning_set_;
  std::vector<std::string> warnings_;
  std::size_t dropped_warnings_ = 0;
  WarningTally tally_;
  // The store id of every design settled in this run, by bits_key: the
  // evaluation a DesignResult names.
  std::map<std::string, std::int64_t> id_of_;
};

}  // namespace rackopt::study
