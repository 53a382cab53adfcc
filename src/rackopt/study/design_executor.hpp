// Who evaluates a batch of designs: this process's threads, or the ranks of
// an MPI job. Drivers and solvers hand batches of independent designs (a
// sweep chunk, finite-difference probes, a population's generation) to the
// evaluation ledger, which takes what the store holds and gives the rest to
// its DesignExecutor. An executor only computes: recording, counting and
// order stay with the ledger on the calling thread, so the record and the
// results are the same on every executor and worker count.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rackopt/study/study_problem.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt::study {

class DesignExecutor {
 public:
  virtual ~DesignExecutor() = default;

  // Result i is problem.evaluate_design(xs[i]) with its objective scales,
  // bit for bit, whoever computes it. `inner_threads` is what a single
  // design may use for its own Monte Carlo (metric options' threads) when
  // the batch is one design. Throws what evaluate_design throws (bugs only:
  // a design the models reject is a failed evaluation).
  virtual std::vector<DesignEvaluation> evaluate(const StudyProblem& problem,
                                                 const std::vector<std::vector<double>>& xs,
                                                 unsigned inner_threads) = 0;
  // The Monte Carlo samples of a reliability study's design `x`, spread
  // over the workers, each computing its share after the same set-up
  // (WearReliabilityOptions::sample_executor); empty when this executor adds
  // nothing to the calling process's own threads (the default).
  virtual decltype(WearReliabilityOptions::sample_executor) reliability_samples(const StudyProblem& problem,
                                                                             std::span<const double> x);
  // Workers that compute at once (threads or ranks).
  virtual unsigned workers() const = 0;
  // "1 thread", "2 threads", "2 MPI ranks": for the report.
  virtual std::string describe() const = 0;
};

// Threads of this process (resolve_threads: 0 = every core). One design,
// or one thread, runs on the calling thread.
std::unique_ptr<DesignExecutor> make_thread_executor(unsigned threads);

}  // namespace rackopt::study
