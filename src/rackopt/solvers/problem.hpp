// The optimization problem as every solver adapter sees it (pagmo's shape):
// a value type with bounds, counts and evaluate(x). Solvers know nothing of
// gears; the study layer builds a Problem from named metrics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace rackopt::solvers {

// kFailed: the models rejected the design (impossible geometry, a metric that
// could not be computed). The adapter records it with its message, steers the
// solver away from it and carries on; a failed evaluation never stops a run.
enum class EvaluationStatus { kOk, kFailed };

// One evaluation of a design x. Everything is minimized / bounded above:
//   objectives[i]  minimized
//   inequality[j] <= 0 feasible
//   equality[k]   == 0 feasible (within SolverSettings::constraint_tolerance)
// For kOk every vector has the size the Problem declares and every value is
// finite (a Problem that cannot keep that promise returns kFailed instead).
// For kFailed the vectors may be empty; `message` says why.
struct Evaluation {
  std::vector<double> objectives;
  std::vector<double> inequality;
  std::vector<double> equality;
  EvaluationStatus status = EvaluationStatus::kOk;
  std::string message;

  bool ok() const { return status == EvaluationStatus::kOk; }
};

// Largest constraint violation of an evaluation: max(0, g_j, |h_k|) over all
// constraints; +inf for a failed evaluation.
double max_violation(const Evaluation& e);

// True when e is ok and max_violation(e) <= tolerance.
bool is_feasible(const Evaluation& e, double tolerance);

class Problem {
 public:
  virtual ~Problem() = default;

  virtual std::size_t dimension() const = 0;
  // Names for messages and records; default "x0", "x1", ...
  virtual std::vector<std::string> variable_names() const;
  // Finite box bounds, lower[i] < upper[i] (adapters check and refuse others).
  virtual std::vector<double> lower_bounds() const = 0;
  virtual std::vector<double> upper_bounds() const = 0;

  // The last num_integer() variables take whole values only, between whole
  // bounds (pagmo's convention): an index into a list of discrete values,
  // searched by the algorithms that handle integers (BackendAlgorithm::
  // integers) and refused by the others.
  virtual std::size_t num_integer() const { return 0; }

  virtual std::size_t num_objectives() const { return 1; }
  virtual std::size_t num_inequality() const { return 0; }
  virtual std::size_t num_equality() const { return 0; }

  // Evaluates the design. Must be deterministic (same x, same result) and
  // callable from several threads at once. A bad design is reported as
  // kFailed, not thrown; anything thrown is a bug or an abort request and is
  // carried out of the solver by the adapter (never swallowed, never
  // crossing a C callback frame).
  virtual Evaluation evaluate(std::span<const double> x) const = 0;

  // Evaluates independent designs, result i for xs[i]: what evaluate(xs[i])
  // gives, for every i, whatever executes them (threads, MPI ranks). The
  // adapters hand a batch whenever the points do not depend on each other
  // (finite-difference probes, a population's generation). The default calls
  // evaluate() in order; a Problem that owns an executor overrides it.
  virtual std::vector<Evaluation> evaluate_batch(const std::vector<std::vector<double>>& xs) const;
};

// Called by adapters after every evaluation they make (including the ones
// made for finite-difference gradients), in evaluation order, on the thread
// that runs the solver. `index` counts from 0 over the whole run.
struct EvaluationRecord {
  std::size_t index = 0;
  std::vector<double> x;
  Evaluation evaluation;
  int start = 0;                  // multistart number (0 = the given x0)
  bool gradient_probe = false;    // made for a finite-difference gradient
  double seconds = 0;             // wall time of this evaluation
};
using EvaluationObserver = std::function<void(const EvaluationRecord&)>;

// Polled before every point a solver asks for (memo hits included);
// returning true stops the run cleanly (the result then holds the best point
// so far, status "stopped").
using StopRequest = std::function<bool()>;

}  // namespace rackopt::solvers
