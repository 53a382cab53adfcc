#include "rackopt/study/recorded_problem.hpp"

#include <algorithm>

namespace rackopt::study {

solvers::Evaluation RecordedProblem::evaluate(std::span<const double> u) const {
  return evaluate_batch({std::vector<double>(u.begin(), u.end())}).front();
}

std::vector<solvers::Evaluation> RecordedProblem::evaluate_batch(const std::vector<std::vector<double>>& us) const {
  settle_pending();
  std::vector<std::vector<double>> xs;
  xs.reserve(us.size());
  for (const auto& u : us) xs.push_back(problem_.to_design(u));
  return accept(us, ledger_.obtain_batch(problem_, xs));
}

std::vector<solvers::Evaluation> RecordedProblem::accept(const std::vector<std::vector<double>>& us,
                                                         std::vector<Obtained> got) const {
  settle_pending();
  std::vector<solvers::Evaluation> out;
  out.reserve(us.size());
  for (std::size_t k = 0; k < us.size(); ++k) {
    out.push_back(got[k].design.evaluation);
    pending_.push_back(Pending{bits_key(us[k]), std::move(got[k])});
  }
  return out;
}

void RecordedProblem::observed(const solvers::EvaluationRecord& rec, const std::string& sub_label) const {
  const std::string key = bits_key(rec.x);
  const auto it = std::find_if(pending_.begin(), pending_.end(), [&](const Pending& p) { return p.u_key == key; });
  if (it == pending_.end()) return;
  // Reports come in evaluation order: what was evaluated before this one and
  // not reported is recorded first, as before it.
  for (auto before = pending_.begin(); before != it; ++before) ledger_.settle(before->obtained, label_, false);
  const std::string label = sub_label.empty() ? label_ : (label_.empty() ? sub_label : label_ + ": " + sub_label);
  ledger_.settle(it->obtained, label, rec.gradient_probe);
  pending_.erase(pending_.begin(), it + 1);
}

void RecordedProblem::settle_pending() const {
  for (const Pending& p : pending_) ledger_.settle(p.obtained, label_, false);
  pending_.clear();
}

}  // namespace rackopt::study
