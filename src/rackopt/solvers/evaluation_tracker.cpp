#include "rackopt/solvers/evaluation_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace rackopt::solvers::detail {

namespace {

bool same_point(const std::vector<double>& a, const std::vector<double>& b) {
  // Bitwise equality: solvers pass back the very same doubles.
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

std::string describe_point(const std::vector<double>& x) {
  std::ostringstream out;
  out.precision(10);
  out << '[';
  for (std::size_t i = 0; i < x.size(); ++i) out << (i ? ", " : "") << x[i];
  out << ']';
  return out.str();
}

}  // namespace

std::optional<SolverStatus> halt_status(Halt h) {
  switch (h) {
    case Halt::kBudget:
    case Halt::kRequests: return SolverStatus::kMaxEvaluations;
    case Halt::kTime: return SolverStatus::kMaxTime;
    case Halt::kStop: return SolverStatus::kStopped;
    case Halt::kNone:
    case Halt::kError: break;
  }
  return std::nullopt;
}

std::size_t max_point_requests(const SolverSettings& settings) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  const std::size_t n = settings.max_evaluations;
  if (n > (kMax - 1000) / 10) return kMax;
  return 10 * n + 1000;
}

EvaluationTracker::EvaluationTracker(const Problem& problem, const SolverSettings& settings,
                                     const SolverCallbacks& callbacks, std::vector<double> x0_clamped)
    : problem_(problem),
      settings_(settings),
      callbacks_(callbacks),
      n_(problem.dimension()),
      ni_(problem.num_inequality()),
      ne_(problem.num_equality()),
      lower_(problem.lower_bounds()),
      upper_(problem.upper_bounds()),
      x0_(std::move(x0_clamped)),
      started_(std::chrono::steady_clock::now()),
      request_cap_(max_point_requests(settings)) {}

void EvaluationTracker::begin_start(int start) {
  start_ = start;
  start_first_index_ = evaluations_;
  start_point_failed_ = false;
  start_point_message_.clear();
}

void EvaluationTracker::poll() const {
  if (callbacks_.stop && callbacks_.stop()) throw RunHalted{Halt::kStop};
  if (settings_.max_seconds > 0) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (elapsed >= settings_.max_seconds) throw RunHalted{Halt::kTime};
  }
}

Evaluation EvaluationTracker::sanitized(Evaluation e) const {
  if (!e.ok()) {
    if (e.message.empty()) e.message = "evaluation failed (no message given)";
    return e;
  }
  auto fail = [&e](std::string why) {
    e.status = EvaluationStatus::kFailed;
    e.message = std::move(why);
  };
  auto check = [&](const std::vector<double>& v, std::size_t expected, const char* what) {
    if (!e.ok()) return;
    if (v.size() != expected) {
      fail(std::string("evaluate() returned ") + std::to_string(v.size()) + " " + what + " values, the problem declares " +
           std::to_string(expected));
      return;
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (!std::isfinite(v[k])) {
        std::ostringstream msg;
        msg << "non-finite " << what << " " << k << " (" << v[k] << ") treated as a failed evaluation";
        fail(msg.str());
        return;
      }
    }
  };
  // Only objective 0 is minimized, but every declared objective must be
  // finite: a NaN anywhere means the model did not really succeed.
  check(e.objectives, problem_.num_objectives(), "objective");
  check(e.inequality, ni_, "inequality");
  check(e.equality, ne_, "equality");
  return e;
}

Evaluation EvaluationTracker::at(const double* x_in, bool gradient_probe) {
  std::vector<double> x(x_in, x_in + n_);
  // Models never see a point outside the box (NEWUOA and PRAXIS may step out,
  // Ipopt relaxes bounds by 1e-8 relative).
  bool finite = true;  // no NaN (an infinite coordinate just clamps to its bound)
  for (std::size_t i = 0; i < n_; ++i) {
    finite = finite && !std::isnan(x[i]);
    x[i] = std::clamp(x[i], lower_[i], upper_[i]);
  }

  // Checked before the memo: a solver cycling on memoized points must still
  // see the stop request, the clock and a hard cap (docs/solvers.md, "Budget").
  if (halt_ != Halt::kNone) throw RunHalted{halt_ == Halt::kError ? Halt::kStop : halt_};
  poll();
  if (requests_ >= request_cap_) throw RunHalted{Halt::kRequests};
  ++requests_;
  if (!finite) {
    // A solver that lost its way (NaN step): never hand NaN to the model;
    // the failure steers the solver back like any failed design.
    Evaluation e;
    e.status = EvaluationStatus::kFailed;
    e.message = "the solver proposed a point with a NaN coordinate (not evaluated)";
    return e;
  }
  if (auto hit = memo_.find(x); hit != memo_.end()) return hit->second;

  if (evaluations_ >= settings_.max_evaluations) throw RunHalted{Halt::kBudget};

  const auto t0 = std::chrono::steady_clock::now();
  Evaluation e = sanitized(problem_.evaluate(std::span<const double>(x)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::size_t index = evaluations_;
  record(x, e);
  if (gradient_probe) ++probes_;
  if (index == start_first_index_ && !e.ok()) {
    start_point_failed_ = true;
    start_point_message_ = e.message;
  }

  if (memo_.size() < kMemoLimit) memo_.emplace(x, e);

  if (callbacks_.observer) {
    EvaluationRecord rec;
    rec.index = index;
    rec.x = x;
    rec.evaluation = e;
    rec.start = start_;
    rec.gradient_probe = gradient_probe;
    rec.seconds = seconds;
    callbacks_.observer(rec);
  }
  return e;
}

void EvaluationTracker::record(const std::vector<double>& x, const Evaluation& e) {
  ++evaluations_;
  if (!has_x0_evaluation_ && same_point(x, x0_)) {
    x0_eval_ = e;
    has_x0_evaluation_ = true;
  }
  if (!e.ok()) {
    ++failed_;
    if (first_failure_.empty()) first_failure_ = "at x=" + describe_point(x) + ": " + e.message;
  } else {
    ++ok_evaluations_;
    const double f = e.objectives[0];
    best_objective_seen_ = std::min(best_objective_seen_, f);
    worst_objective_seen_ = std::max(worst_objective_seen_, f);
    for (double g : e.inequality) largest_constraint_seen_ = std::max(largest_constraint_seen_, std::abs(g));
    for (double h : e.equality) largest_constraint_seen_ = std::max(largest_constraint_seen_, std::abs(h));

    const double violation = max_violation(e);
    if (violation <= settings_.constraint_tolerance) {
      if (!has_feasible_ || f < best_eval_.objectives[0]) {
        has_feasible_ = true;
        best_x_ = x;
        best_eval_ = e;
      }
    }
    if (!has_ok_ || violation < least_violation_ ||
        (violation == least_violation_ && f < least_infeasible_eval_.objectives[0])) {
      has_ok_ = true;
      least_violation_ = violation;
      least_infeasible_x_ = x;
      least_infeasible_eval_ = e;
    }
  }
  best_history_.push_back(has_feasible_ ? best_eval_.objectives[0] : std::numeric_limits<double>::infinity());
}

double EvaluationTracker::penalty_objective() const {
  // No finite value seen yet: nothing to scale by; any finite number keeps
  // the solver's arithmetic sane and later successes will look better than
  // this only if they are below it (documented in docs/solvers.md).
  if (ok_evaluations_ == 0) return 1.0e6;
  double margin = 0.1 * (worst_objective_seen_ - best_objective_seen_) + 0.1 * std::abs(worst_objective_seen_);
  if (!(margin > 0)) margin = 1.0;
  return worst_objective_seen_ + margin;
}

double EvaluationTracker::penalty_constraint() const { return std::max(1.0, 10.0 * largest_constraint_seen_); }

bool EvaluationTracker::stacked(const Evaluation& e, std::vector<double>& out) const {
  if (!e.ok()) return false;
  out.clear();
  out.push_back(e.objectives[0]);
  out.insert(out.end(), e.inequality.begin(), e.inequality.end());
  out.insert(out.end(), e.equality.begin(), e.equality.end());
  return true;
}

const Jacobian& EvaluationTracker::jacobian(const double* x_in) {
  std::vector<double> xc(x_in, x_in + n_);
  for (std::size_t i = 0; i < n_; ++i) xc[i] = std::clamp(xc[i], lower_[i], upper_[i]);
  if (jacobian_valid_ && same_point(xc, jacobian_x_)) return jacobian_;

  const std::size_t rows = 1 + ni_ + ne_;
  Jacobian jac;
  jac.rows = rows;
  jac.values.assign(rows * n_, 0.0);
  std::vector<double> center, plus, minus;
  jac.center_ok = stacked(at(xc.data()), center);
  if (jac.center_ok) {
    std::vector<double> probe = xc;
    // Evaluates the stacked vector at xc + s*e_i clamped into the box;
    // returns the step actually taken (after rounding and clamping) or 0
    // when the probe failed or did not move x (no information).
    auto take = [&](std::size_t i, double s, std::vector<double>& out) -> double {
      probe[i] = std::clamp(xc[i] + s, lower_[i], upper_[i]);
      const double actual = probe[i] - xc[i];
      const bool ok = actual != 0.0 && stacked(at(probe.data(), true), out);
      probe[i] = xc[i];
      return ok ? actual : 0.0;
    };
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    for (std::size_t i = 0; i < n_; ++i) {
      const double range = upper_[i] - lower_[i];
      // A step below ~16 ulp of |x| is rounding noise or rounds to no step
      // at all (a variable with a tiny range far from 0); at most half the
      // range, so the side with more room always fits.
      const double magnitude = std::max({std::abs(xc[i]), std::abs(lower_[i]), std::abs(upper_[i])});
      const double h = std::min(std::max(settings_.gradient_step * range, 16.0 * kEps * magnitude), 0.5 * range);
      const bool plus_inside = xc[i] + h <= upper_[i];
      const bool minus_inside = xc[i] - h >= lower_[i];
      double hp = 0, hm = 0;
      if (settings_.central_differences && plus_inside && minus_inside) {
        hp = take(i, h, plus);
        hm = take(i, -h, minus);
      } else if (plus_inside || minus_inside) {
        // Forward difference, flipped inward at the upper bound; if the
        // probe fails, the other side (when inside the box) is tried.
        if (plus_inside) {
          hp = take(i, h, plus);
          if (hp == 0 && minus_inside) hm = take(i, -h, minus);
        } else {
          hm = take(i, -h, minus);
          if (hm == 0 && plus_inside) hp = take(i, h, plus);
        }
      } else if (upper_[i] - xc[i] >= xc[i] - lower_[i]) {
        // Rounding left neither side a full step: go to the farther bound
        // (at least half the range away).
        hp = take(i, upper_[i] - xc[i], plus);
      } else {
        hm = take(i, lower_[i] - xc[i], minus);
      }
      for (std::size_t r = 0; r < rows; ++r) {
        double d = 0.0;  // both sides failed: no information, report a flat slope
        if (hp != 0 && hm != 0) d = (plus[r] - minus[r]) / (hp - hm);
        else if (hp != 0) d = (plus[r] - center[r]) / hp;
        else if (hm != 0) d = (minus[r] - center[r]) / hm;
        jac.values[r * n_ + i] = d;
      }
    }
  }
  jacobian_ = std::move(jac);
  jacobian_x_ = std::move(xc);
  jacobian_valid_ = true;
  return jacobian_;
}

void EvaluationTracker::fill_result(SolverResult& result) const {
  if (has_feasible_) {
    result.x = best_x_;
    result.evaluation = best_eval_;
    result.feasible = true;
  } else if (has_ok_) {
    result.x = least_infeasible_x_;
    result.evaluation = least_infeasible_eval_;
    result.feasible = false;
  } else {
    result.x = x0_;
    if (has_x0_evaluation_) {
      result.evaluation = x0_eval_;
    } else {
      result.evaluation = Evaluation{};
      result.evaluation.status = EvaluationStatus::kFailed;
      result.evaluation.message = evaluations_ == 0 ? std::string("x0 was not evaluated")
                                                    : "x0 was not evaluated; all " + std::to_string(evaluations_) +
                                                          " evaluations failed, the first " + first_failure_;
    }
    result.feasible = false;
  }
  result.evaluations = evaluations_;
  result.failed_evaluations = failed_;
  result.gradient_evaluations = probes_;
  result.best_history = best_history_;
}

}  // namespace rackopt::solvers::detail
