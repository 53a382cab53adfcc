#include "rackopt/solvers/evaluation_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <sstream>
#include <stdexcept>

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
  return at_batch({std::vector<double>(x_in, x_in + n_)}, gradient_probe).front();
}

std::vector<Evaluation> EvaluationTracker::at_batch(const std::vector<std::vector<double>>& xs_in,
                                                    bool gradient_probe) {
  // Checked before the memo: a solver cycling on memoized points must still
  // see the stop request, the clock and a hard cap (docs/solvers.md, "Budget").
  if (halt_ != Halt::kNone) throw RunHalted{halt_ == Halt::kError ? Halt::kStop : halt_};
  poll();
  std::vector<Evaluation> out(xs_in.size());
  std::vector<std::vector<double>> xs = xs_in;
  std::vector<bool> answered(xs.size(), false);
  // New distinct points in order, and for each batch point the new point it is.
  std::vector<std::vector<double>> fresh;
  std::vector<std::size_t> fresh_of(xs.size(), 0);
  std::map<std::vector<double>, std::size_t> fresh_index;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    std::vector<double>& x = xs[k];
    // Models never see a point outside the box (NEWUOA and PRAXIS may step
    // out, Ipopt relaxes bounds by 1e-8 relative).
    bool finite = true;  // no NaN (an infinite coordinate just clamps to its bound)
    for (std::size_t i = 0; i < n_; ++i) {
      finite = finite && !std::isnan(x[i]);
      x[i] = std::clamp(x[i], lower_[i], upper_[i]);
    }
    if (requests_ >= request_cap_) throw RunHalted{Halt::kRequests};
    ++requests_;
    if (!finite) {
      // A solver that lost its way (NaN step): never hand NaN to the model;
      // the failure steers the solver back like any failed design.
      out[k].status = EvaluationStatus::kFailed;
      out[k].message = "the solver proposed a point with a NaN coordinate (not evaluated)";
      answered[k] = true;
    } else if (auto hit = memo_.find(x); hit != memo_.end()) {
      out[k] = hit->second;
      answered[k] = true;
    } else if (auto seen = fresh_index.find(x); seen != fresh_index.end()) {
      fresh_of[k] = seen->second;
    } else {
      fresh_of[k] = fresh.size();
      fresh_index.emplace(x, fresh.size());
      fresh.push_back(x);
    }
  }
  if (fresh.empty()) return out;

  const std::size_t room = settings_.max_evaluations > evaluations_ ? settings_.max_evaluations - evaluations_ : 0;
  if (room == 0) throw RunHalted{Halt::kBudget};
  const bool cut = fresh.size() > room;
  if (cut) fresh.resize(room);

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Evaluation> results = problem_.evaluate_batch(fresh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
                         static_cast<double>(fresh.size());
  if (results.size() != fresh.size())
    throw std::logic_error("evaluate_batch returned " + std::to_string(results.size()) + " evaluations for " +
                           std::to_string(fresh.size()) + " points");

  for (std::size_t j = 0; j < fresh.size(); ++j) {
    const std::vector<double>& x = fresh[j];
    Evaluation& e = results[j];
    e = sanitized(std::move(e));
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
  }
  if (cut) throw RunHalted{Halt::kBudget};
  for (std::size_t k = 0; k < xs.size(); ++k)
    if (!answered[k]) out[k] = results[fresh_of[k]];
  return out;
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
  std::vector<double> center;
  jac.center_ok = stacked(at(xc.data()), center);
  if (jac.center_ok) {
    // Each variable's probe plan: the step(s) to take now, and for a forward
    // difference the other side to try when the first probe fails.
    struct Plan {
      double first = 0, second = 0;  // steps to evaluate in the first batch (second: central only)
      double fallback = 0;           // forward: the other side, evaluated only if `first` failed
    };
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    std::vector<Plan> plans(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const double range = upper_[i] - lower_[i];
      // A step below ~16 ulp of |x| is rounding noise or rounds to no step
      // at all (a variable with a tiny range far from 0); at most half the
      // range, so the side with more room always fits.
      const double magnitude = std::max({std::abs(xc[i]), std::abs(lower_[i]), std::abs(upper_[i])});
      const double h = std::min(std::max(settings_.gradient_step * range, 16.0 * kEps * magnitude), 0.5 * range);
      const bool plus_inside = xc[i] + h <= upper_[i];
      const bool minus_inside = xc[i] - h >= lower_[i];
      Plan& p = plans[i];
      if (settings_.central_differences && plus_inside && minus_inside) {
        p.first = h;
        p.second = -h;
      } else if (plus_inside || minus_inside) {
        // Forward difference, flipped inward at the upper bound; if the
        // probe fails, the other side (when inside the box) is tried.
        p.first = plus_inside ? h : -h;
        if (plus_inside && minus_inside) p.fallback = -p.first;
      } else if (upper_[i] - xc[i] >= xc[i] - lower_[i]) {
        // Rounding left neither side a full step: go to the farther bound
        // (at least half the range away).
        p.first = upper_[i] - xc[i];
      } else {
        p.first = lower_[i] - xc[i];
      }
    }
    // The probe point of step s in variable i, and the step actually taken
    // (after rounding and clamping; 0 = no move, no information).
    auto probe_at = [&](std::size_t i, double s, double& actual) {
      std::vector<double> probe = xc;
      probe[i] = std::clamp(xc[i] + s, lower_[i], upper_[i]);
      actual = probe[i] - xc[i];
      return probe;
    };
    struct Probe {
      std::size_t variable;
      double actual;
      std::vector<double> values;
      bool ok = false;
    };
    auto run_batch = [&](const std::vector<std::pair<std::size_t, double>>& steps) {
      std::vector<Probe> probes;
      std::vector<std::vector<double>> points;
      for (const auto& [i, s] : steps) {
        double actual = 0;
        std::vector<double> p = probe_at(i, s, actual);
        probes.push_back({i, actual, {}, false});
        if (actual != 0.0) points.push_back(std::move(p));
      }
      const std::vector<Evaluation> es = at_batch(points, true);
      std::size_t next = 0;
      for (Probe& p : probes)
        if (p.actual != 0.0) p.ok = stacked(es[next++], p.values);
      return probes;
    };
    std::vector<std::pair<std::size_t, double>> first_steps;
    for (std::size_t i = 0; i < n_; ++i) {
      first_steps.emplace_back(i, plans[i].first);
      if (plans[i].second != 0) first_steps.emplace_back(i, plans[i].second);
    }
    std::vector<Probe> probes = run_batch(first_steps);
    std::vector<std::pair<std::size_t, double>> fallback_steps;
    for (const Probe& p : probes)
      if (!p.ok && plans[p.variable].fallback != 0) fallback_steps.emplace_back(p.variable, plans[p.variable].fallback);
    if (!fallback_steps.empty()) {
      std::vector<Probe> more = run_batch(fallback_steps);
      probes.insert(probes.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    // Per variable: the successful probe on each side (the first one kept).
    std::vector<const Probe*> plus_side(n_, nullptr), minus_side(n_, nullptr);
    for (const Probe& p : probes) {
      if (!p.ok) continue;
      auto& slot = p.actual > 0 ? plus_side[p.variable] : minus_side[p.variable];
      if (!slot) slot = &p;
    }
    for (std::size_t i = 0; i < n_; ++i) {
      const Probe* hp = plus_side[i];
      const Probe* hm = minus_side[i];
      for (std::size_t r = 0; r < rows; ++r) {
        double d = 0.0;  // both sides failed: no information, report a flat slope
        if (hp && hm) d = (hp->values[r] - hm->values[r]) / (hp->actual - hm->actual);
        else if (hp) d = (hp->values[r] - center[r]) / hp->actual;
        else if (hm) d = (hm->values[r] - center[r]) / hm->actual;
        jac.values[r * n_ + i] = d;
      }
    }
  }
  jacobian_ = std::move(jac);
  jacobian_x_ = std::move(xc);
  jacobian_valid_ = true;
  return jacobian_;
}

std::optional<SolverStatus> EvaluationTracker::ending_status() const {
  if (evaluations_ > 0 && !any_ok()) return SolverStatus::kAllFailed;
  if (evaluations_ > 0 && !any_feasible()) return SolverStatus::kNoFeasiblePoint;
  // A halt by an error was rethrown by the caller; every other halt has a status.
  if (halt_ != Halt::kNone) return halt_status(halt_).value_or(SolverStatus::kSolverFailed);
  return std::nullopt;
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
