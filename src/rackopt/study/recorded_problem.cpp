#include "rackopt/study/recorded_problem.hpp"

namespace rackopt::study {

solvers::Evaluation RecordedProblem::evaluate(std::span<const double> u) const {
  settle_pending();
  const std::vector<double> x = problem_.to_design(u);
  pending_.emplace(Pending{bits_key(u), ledger_.obtain(problem_, x)});
  return pending_->obtained.design.evaluation;
}

void RecordedProblem::observed(const solvers::EvaluationRecord& rec, const std::string& sub_label) const {
  if (!pending_ || pending_->u_key != bits_key(rec.x)) return;
  const std::string label = sub_label.empty() ? label_ : (label_.empty() ? sub_label : label_ + ": " + sub_label);
  Pending p = std::move(*pending_);
  pending_.reset();
  ledger_.settle(p.obtained, label, rec.gradient_probe);
}

void RecordedProblem::settle_pending() const {
  if (!pending_) return;
  Pending p = std::move(*pending_);
  pending_.reset();
  ledger_.settle(p.obtained, label_, false);
}

}  // namespace rackopt::study
