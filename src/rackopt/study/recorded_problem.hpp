// The Problem handed to the solvers in an optimize or pareto study: a
// StudyProblem whose evaluations go through the evaluation ledger (taken
// from the store on --resume; batches on the ledger's executor) and are
// recorded when the solver adapter reports them, since only then is it
// known whether a point was a finite-difference probe. Used on the driving
// thread only.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rackopt/solvers/solver.hpp"
#include "rackopt/study/evaluation_ledger.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::study {

class RecordedProblem final : public solvers::Problem {
 public:
  RecordedProblem(EvaluationLedger& ledger, const StudyProblem& problem) : ledger_(ledger), problem_(problem) {}
  ~RecordedProblem() override = default;

  // The record's phase label of the evaluations that follow.
  void set_label(std::string label) { label_ = std::move(label); }

  std::size_t dimension() const override { return problem_.dimension(); }
  std::vector<std::string> variable_names() const override { return problem_.variable_names(); }
  std::vector<double> lower_bounds() const override { return problem_.lower_bounds(); }
  std::vector<double> upper_bounds() const override { return problem_.upper_bounds(); }
  std::size_t num_objectives() const override { return problem_.num_objectives(); }
  std::size_t num_inequality() const override { return problem_.num_inequality(); }
  std::size_t num_equality() const override { return problem_.num_equality(); }
  std::size_t num_integer() const override { return problem_.num_integer(); }

  solvers::Evaluation evaluate(std::span<const double> u) const override;
  std::vector<solvers::Evaluation> evaluate_batch(const std::vector<std::vector<double>>& us) const override;
  // What evaluate_batch(us) does once the designs are obtained (got[k] for
  // us[k], e.g. by one ledger batch over several runs in lockstep): the
  // evaluations, kept pending until the adapter reports them.
  std::vector<solvers::Evaluation> accept(const std::vector<std::vector<double>>& us, std::vector<Obtained> got) const;

  // The adapter's report of the evaluation just made; `sub_label` names the
  // sub-problem of a Pareto front ("anchor 1", "eps 3"), empty otherwise.
  void observed(const solvers::EvaluationRecord& rec, const std::string& sub_label) const;

  // Evaluations the adapter made but did not report (it stopped): still
  // recorded, in evaluation order, so nothing computed is lost.
  void settle_pending() const;

 private:
  struct Pending {
    std::string u_key;
    Obtained obtained;
  };
  EvaluationLedger& ledger_;
  const StudyProblem& problem_;
  std::string label_;
  // Evaluated, not yet reported: at most one batch, in evaluation order.
  mutable std::vector<Pending> pending_;
};

}  // namespace rackopt::study
