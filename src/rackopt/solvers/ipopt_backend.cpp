// The Ipopt 3.11.9 backend (TNLP). Pitfalls handled here (docs/dependencies.md, "Ipopt 3.11"):
//  * Initialize("") so no ./ipopt.opt in the working directory changes a run;
//  * no gradient_approximation option in 3.11: grad f and the (dense)
//    constraint Jacobian come from our own finite differences, computed once
//    per iterate from one set of probes, which also count against the budget;
//    the Hessian is limited-memory;
//  * eval_jac_g is called once with values == nullptr for the structure;
//  * new_x == false means "same x as before": our point cache answers it;
//  * a failed evaluation returns false (Ipopt cuts the step back); at the
//    start point Ipopt then stops with Invalid_Number_Detected, which we
//    translate into a clear message;
//  * an exception in a callback would be swallowed (NonIpopt_Exception_Thrown):
//    every callback catches, stores the exception_ptr and returns false, the
//    intermediate callback then returns false (User_Requested_Stop), and we
//    rethrow after OptimizeTNLP; RethrowNonIpoptException(true) is only a
//    safety net;
//  * MUMPS is the only linear solver in Debian's build.
#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "rackopt/solvers/adapters.hpp"

namespace rackopt::solvers::detail {

namespace {

using Ipopt::Index;
using Ipopt::Number;

class TrackedNlp : public Ipopt::TNLP {
 public:
  TrackedNlp(EvaluationTracker& tracker, std::vector<double> x_start)
      : t_(tracker), x_start_(std::move(x_start)), n_(tracker.dimension()),
        m_(tracker.num_inequality() + tracker.num_equality()) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = static_cast<Index>(n_);
    m = static_cast<Index>(m_);
    nnz_jac_g = static_cast<Index>(n_ * m_);  // dense
    nnz_h_lag = 0;                            // limited-memory Hessian
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    std::copy(t_.lower().begin(), t_.lower().end(), x_l);
    std::copy(t_.upper().begin(), t_.upper().end(), x_u);
    for (std::size_t j = 0; j < m_; ++j) {
      // inequality: -inf < g <= 0 (Ipopt's default nlp_lower_bound_inf is -1e19)
      g_l[j] = j < t_.num_inequality() ? -1.0e20 : 0.0;
      g_u[j] = 0.0;
    }
    return true;
  }

  bool get_starting_point(Index, bool init_x, Number* x, bool, Number*, Number*, Index, bool, Number*) override {
    if (init_x) std::copy(x_start_.begin(), x_start_.end(), x);
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& obj_value) override {
    bool ok = false;
    t_.guard([&] {
      const Evaluation e = t_.at(x);
      if (e.ok()) {
        obj_value = e.objectives[0];
        ok = true;
      }
    });
    return ok;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    bool ok = false;
    t_.guard([&] {
      const Evaluation e = t_.at(x);
      if (e.ok()) {
        std::copy(e.inequality.begin(), e.inequality.end(), g);
        std::copy(e.equality.begin(), e.equality.end(), g + e.inequality.size());
        ok = true;
      }
    });
    return ok;
  }

  bool eval_grad_f(Index, const Number* x, bool, Number* grad_f) override {
    bool ok = false;
    t_.guard([&] {
      const Jacobian& j = t_.jacobian(x);
      if (j.center_ok) {
        std::copy(j.values.begin(), j.values.begin() + n_, grad_f);
        ok = true;
      }
    });
    return ok;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* iRow, Index* jCol, Number* values) override {
    if (values == nullptr) {
      // Structure only (once): dense, row-major.
      for (std::size_t r = 0; r < m_; ++r)
        for (std::size_t i = 0; i < n_; ++i) {
          iRow[r * n_ + i] = static_cast<Index>(r);
          jCol[r * n_ + i] = static_cast<Index>(i);
        }
      return true;
    }
    bool ok = false;
    t_.guard([&] {
      const Jacobian& j = t_.jacobian(x);
      if (j.center_ok) {
        std::copy(j.values.begin() + n_, j.values.begin() + (1 + m_) * n_, values);
        ok = true;
      }
    });
    return ok;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index, Number, Number, Number, Number, Number, Number, Number,
                             Number, Index, const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    // Stop requests and the clock are polled here too, so a run whose
    // evaluations all come from the cache still ends on time.
    return t_.guard([&] { t_.poll(); });
  }

  void finalize_solution(Ipopt::SolverReturn, Index, const Number*, const Number*, const Number*, Index,
                         const Number*, const Number*, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    // Neither the solver's x nor its return code is used: the tracker holds
    // the best point it saw, and OptimizeTNLP's status says how it ended.
  }

 private:
  EvaluationTracker& t_;
  std::vector<double> x_start_;
  std::size_t n_, m_;
};

const char* status_name(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "Unknown_Ipopt_Status";
}

template <class T>
void set_option(Ipopt::IpoptApplication& app, const std::string& name, const T& value) {
  bool ok = false;
  if constexpr (std::is_same_v<T, int>) ok = app.Options()->SetIntegerValue(name, value);
  else if constexpr (std::is_same_v<T, double>) ok = app.Options()->SetNumericValue(name, value);
  else ok = app.Options()->SetStringValue(name, value);
  // Unknown options only print a line and return false: make it loud.
  if (!ok) throw std::invalid_argument("Ipopt rejected option " + name);
}

// Why the tracker ended an Ipopt run, in the words of the solver message.
std::string halt_message(Halt halt) {
  switch (halt) {
    case Halt::kBudget: return "budget reached (solver.max_evaluations)";
    case Halt::kRequests: return "point-request cap reached";
    case Halt::kTime: return "time limit reached (solver.max_time)";
    case Halt::kStop: return "stopped";
    case Halt::kError:
    case Halt::kNone: break;
  }
  return "ended by an error";
}

}  // namespace

StartOutcome run_ipopt_start(EvaluationTracker& tracker, const SolverSettings& settings, std::vector<double> x_start,
                             int start) {
  tracker.begin_start(start);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->RethrowNonIpoptException(true);
  // "sb" must come first: it silences the banner printed by Initialize.
  set_option(*app, "sb", std::string("yes"));
  const SolverBackend& self = ipopt_backend();
  set_option(*app, "print_level", static_cast<int>(self.option(settings, "ipopt_print_level")));
  set_option(*app, "hessian_approximation", std::string("limited-memory"));
  set_option(*app, "linear_solver", std::string("mumps"));
  set_option(*app, "tol", self.option(settings, "ipopt_tol"));
  set_option(*app, "max_iter", static_cast<int>(self.option(settings, "ipopt_max_iterations")));
  // Ipopt's own feasibility test agrees with our re-check.
  set_option(*app, "constr_viol_tol", settings.constraint_tolerance);
  if (app->Initialize("") != Ipopt::Solve_Succeeded)
    throw std::runtime_error("Ipopt could not be initialized");

  Ipopt::SmartPtr<TrackedNlp> nlp = new TrackedNlp(tracker, std::move(x_start));
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(Ipopt::GetRawPtr(nlp)));
  tracker.rethrow_if_error();

  StartOutcome outcome;
  outcome.message = status_name(status);
  switch (status) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Search_Direction_Becomes_Too_Small:
    case Ipopt::Feasible_Point_Found:
      outcome.status = SolverStatus::kConverged;
      break;
    case Ipopt::Maximum_Iterations_Exceeded: outcome.status = SolverStatus::kMaxIterations; break;
    case Ipopt::Maximum_CpuTime_Exceeded: outcome.status = SolverStatus::kMaxTime; break;
    case Ipopt::Invalid_Option:
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
    case Ipopt::Invalid_Problem_Definition:
      throw std::invalid_argument(std::string("Ipopt rejected the problem: ") + outcome.message);
    default: outcome.status = SolverStatus::kSolverFailed; break;
  }
  if (tracker.start_point_failed())
    outcome.message += ": evaluation failed at the start point: " + tracker.start_point_message();
  if (tracker.halt() != Halt::kNone) {
    // Our callbacks ended the run (they return false once the tracker halts),
    // so Ipopt's own status describes that refusal (Invalid_Number_Detected,
    // User_Requested_Stop, ...), not why the run ended: say why instead.
    outcome.status.reset();
    outcome.message = halt_message(tracker.halt());
  }
  return outcome;
}

}  // namespace rackopt::solvers::detail

namespace rackopt::solvers::detail {

namespace {

class IpoptBackend final : public SolverBackend {
 public:
  std::string_view library() const override { return "ipopt"; }
  std::vector<BackendAlgorithm> algorithms() const override { return {}; }
  std::string default_algorithm() const override { return ""; }
  const std::vector<BackendOption>& options() const override {
    static const std::vector<BackendOption> table = {
        {"ipopt_tol", 1e-8, 0, 1e300, false, true, "Ipopt's tol: the convergence tolerance of the scaled KKT error"},
        {"ipopt_max_iterations", 3000, 1, 100000000, true, false, "Ipopt's max_iter"},
        {"ipopt_print_level", 0, 0, 12, true, false, "Ipopt's print_level (0 = silent)", true},
    };
    return table;
  }

  std::optional<SolverSettingsRefusal> check(const SolverSettings&, const ProblemShape& shape) const override {
    if (shape.equality > shape.dimension)
      return SolverSettingsRefusal{
          SolverSetting::kLibrary,
          "Ipopt needs at least as many variables as equality constraints; the problem has " +
              std::to_string(shape.equality) + " equalities for " + std::to_string(shape.dimension) +
              " variables (too few degrees of freedom)",
          ""};
    return std::nullopt;
  }

  SolverResult minimize(const Problem& problem, std::span<const double> x0, const SolverSettings& settings,
                        const SolverCallbacks& callbacks) const override {
    return run_multistart(problem, x0, settings, callbacks,
                          [&](EvaluationTracker& tracker, std::vector<double> x_start, int start) {
                            return run_ipopt_start(tracker, settings, std::move(x_start), start);
                          });
  }
};

}  // namespace

const SolverBackend& ipopt_backend() {
  static const IpoptBackend backend;
  return backend;
}

}  // namespace rackopt::solvers::detail
