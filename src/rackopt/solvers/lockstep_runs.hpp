// Independent solver runs advanced together, so that their evaluations go
// to the executor as one batch: the anchors of a scalarized Pareto front
// (one run per objective) and the discrete combinations of an optimize or
// pareto study (one NLopt, Ipopt or pagmo run per combination) are such
// runs, and each asks for one point (or one finite-difference batch) at a
// time.
//
// Each run is a job on its own thread, but only one thread runs at any time:
// the coordinator passes a baton to the live jobs in job order; a job runs
// its solver until it asks for evaluations (LockstepChannel::evaluate) or
// ends, then hands the baton back. When every live job has asked or ended,
// the coordinator serves all the requests at once (`serve`, on the calling
// thread) and the next round begins. So:
//  * a round holds the next request of every live job, in job order: what
//    the jobs see and the order of everything they do (their observers
//    record designs) depend on the jobs alone, never on who evaluates the
//    batch or how fast: the record is the same on any executor;
//  * the solver libraries never run concurrently (Ipopt's MUMPS is not
//    thread-safe), and a job may touch what the coordinator owns (the study's
//    ledger) while it holds the baton;
//  * at most `width` jobs are live; the next job starts when one ends (in a
//    fixed order, so `width` is part of the record's order, not a tuning of
//    the machine).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "rackopt/solvers/problem.hpp"

namespace rackopt::solvers {

// What a job uses to reach the coordinator.
class LockstepChannel {
 public:
  virtual ~LockstepChannel() = default;
  // The evaluations of `us` (solver vectors), result i for us[i]: waits for
  // the round's batch. Throws LockstepAbandoned when the coordinator gave up
  // the round (another job or the batch threw); the job must then end.
  virtual std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& us) = 0;
};

// Thrown into a waiting job when the run is abandoned; never escapes
// run_in_lockstep.
struct LockstepAbandoned {};

// One request of a round: job `job` asks for the evaluations of `us`.
struct LockstepRequest {
  std::size_t job = 0;
  const std::vector<std::vector<double>>* us = nullptr;
};

// Runs jobs 0 .. jobs-1, at most `width` (>= 1) at once, in lockstep.
// `serve` gets each round's requests in job order and returns one
// evaluation vector per request. Rethrows the first exception of `serve` or
// of a job (in job order) after every job has ended.
void run_in_lockstep(std::size_t jobs, std::size_t width, const std::function<void(std::size_t, LockstepChannel&)>& job,
                     const std::function<std::vector<std::vector<Evaluation>>(
                         const std::vector<LockstepRequest>&)>& serve);

// A Problem whose evaluations go through a channel: the shape of `shape`
// (bounds, counts, names), the values from the coordinator's batch.
class LockstepProblem final : public Problem {
 public:
  LockstepProblem(const Problem& shape, LockstepChannel& channel) : shape_(shape), channel_(channel) {}

  std::size_t dimension() const override { return shape_.dimension(); }
  std::vector<std::string> variable_names() const override { return shape_.variable_names(); }
  std::vector<double> lower_bounds() const override { return shape_.lower_bounds(); }
  std::vector<double> upper_bounds() const override { return shape_.upper_bounds(); }
  std::size_t num_objectives() const override { return shape_.num_objectives(); }
  std::size_t num_inequality() const override { return shape_.num_inequality(); }
  std::size_t num_equality() const override { return shape_.num_equality(); }
  std::size_t num_integer() const override { return shape_.num_integer(); }
  Evaluation evaluate(std::span<const double> u) const override;
  std::vector<Evaluation> evaluate_batch(const std::vector<std::vector<double>>& us) const override;

 private:
  const Problem& shape_;
  LockstepChannel& channel_;
};

}  // namespace rackopt::solvers
