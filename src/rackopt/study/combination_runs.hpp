// The discrete combinations of an optimize or pareto study as solver runs
// in lockstep (lockstep_runs.hpp): run c works on the combination's view
// through its own RecordedProblem (its record label), and each round's
// designs, every run's request together, go to the ledger as one batch, so
// an executor with several workers evaluates the combinations side by side.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rackopt/study/evaluation_ledger.hpp"
#include "rackopt/solvers/lockstep_runs.hpp"
#include "rackopt/study/recorded_problem.hpp"
#include "rackopt/study/study_problem.hpp"

namespace rackopt::study {

// Runs at once at most: fixed, so that the record's order does not depend
// on the machine; enough to keep an MPI job of a few dozen ranks busy with
// the finite-difference batches of 16 runs.
inline constexpr std::size_t kCombinationRunsAtOnce = 16;

// The views a study's solver runs work on: every combination of `base`
// (for_combination), or the one that searches the discrete variables as
// integers when the spec's algorithm does (searches_discrete_as_integers).
std::vector<StudyProblem> solver_views(const StudyProblem& base);

class CombinationRuns {
 public:
  // One run per view (a combination of `base`, or the view that searches
  // every combination as integers), run c labelled by `label(views[c])`.
  CombinationRuns(EvaluationLedger& ledger, const StudyProblem& base, std::vector<StudyProblem> views,
                  const std::function<std::string(const StudyProblem&)>& label);

  std::size_t size() const { return views_.size(); }
  const StudyProblem& view(std::size_t c) const { return views_[c]; }
  const RecordedProblem& recorded(std::size_t c) const { return *recorded_[c]; }

  // Runs `run(c, problem)` for every combination in lockstep; `problem` is
  // what the run's solver evaluates (recorded through run c's
  // RecordedProblem; the run reports its solver's observations to
  // recorded(c) and settles it when done). An evaluation that gave up on
  // Ctrl-C (rackopt::Interrupted) ends every run: what the runs had
  // evaluated is recorded, the ledger is marked stopped and this returns.
  // Rethrows anything else a run or the ledger threw.
  void run(const std::function<void(std::size_t, const solvers::Problem&)>& run);

 private:
  std::vector<std::vector<solvers::Evaluation>> serve(const std::vector<solvers::LockstepRequest>& round);

  EvaluationLedger& ledger_;
  const StudyProblem& base_;
  std::vector<StudyProblem> views_;
  std::vector<std::unique_ptr<RecordedProblem>> recorded_;
};

}  // namespace rackopt::study
