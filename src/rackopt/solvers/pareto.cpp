#include "rackopt/solvers/pareto.hpp"

#include "rackopt/solvers/lockstep_runs.hpp"
#include "rackopt/solvers/solver_backend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

namespace rackopt::solvers {

bool dominates(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    throw std::invalid_argument("dominates: objective vectors of different sizes (" + std::to_string(a.size()) +
                                " and " + std::to_string(b.size()) + ")");
  bool strictly_better_somewhere = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] > b[i]) return false;
    if (a[i] < b[i]) strictly_better_somewhere = true;
  }
  return strictly_better_somewhere;
}

std::vector<std::size_t> non_dominated(const std::vector<std::vector<double>>& objective_vectors) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < objective_vectors.size(); ++i) {
    bool is_dominated = false;
    for (std::size_t j = 0; j < objective_vectors.size() && !is_dominated; ++j)
      is_dominated = j != i && dominates(objective_vectors[j], objective_vectors[i]);
    if (!is_dominated) kept.push_back(i);
  }
  return kept;
}

namespace {

// One scalarized sub-problem. Each evaluate() calls the original once, keeps
// that evaluation (so the front and the observer can report the original
// objectives without a second model call) and maps it to
//   objective   f_k (anchor k), (f_p - ideal_p)/range_p (eps) or sum w_i z_i (weighted)
//   inequality  the original ones, then (f_j - eps_j)/range_j for each bound (eps)
//   equality    the original ones.
class ScalarizedProblem : public Problem {
 public:
  struct Bound {
    std::size_t objective;
    double eps;
  };

  ScalarizedProblem(const Problem& original, std::vector<double> ideal, std::vector<double> range)
      : original_(original), m_(original.num_objectives()), ideal_(std::move(ideal)), range_(std::move(range)) {}

  static ScalarizedProblem anchor(const Problem& original, std::size_t k) {
    ScalarizedProblem p(original, std::vector<double>(original.num_objectives(), 0.0),
                        std::vector<double>(original.num_objectives(), 1.0));
    p.weights_.assign(original.num_objectives(), 0.0);
    p.weights_[k] = 1.0;  // raw f_k: ideal 0 and range 1 leave it unscaled
    return p;
  }
  static ScalarizedProblem weighted(const Problem& original, std::vector<double> weights, std::vector<double> ideal,
                                    std::vector<double> range) {
    ScalarizedProblem p(original, std::move(ideal), std::move(range));
    p.weights_ = std::move(weights);
    return p;
  }
  static ScalarizedProblem epsilon(const Problem& original, std::size_t primary, std::vector<Bound> bounds,
                                   std::vector<double> ideal, std::vector<double> range) {
    ScalarizedProblem p(original, std::move(ideal), std::move(range));
    p.weights_.assign(original.num_objectives(), 0.0);
    p.weights_[primary] = 1.0;
    p.bounds_ = std::move(bounds);
    return p;
  }

  std::size_t dimension() const override { return original_.dimension(); }
  std::size_t num_integer() const override { return original_.num_integer(); }
  std::vector<std::string> variable_names() const override { return original_.variable_names(); }
  std::vector<double> lower_bounds() const override { return original_.lower_bounds(); }
  std::vector<double> upper_bounds() const override { return original_.upper_bounds(); }
  std::size_t num_objectives() const override { return 1; }
  std::size_t num_inequality() const override { return original_.num_inequality() + bounds_.size(); }
  std::size_t num_equality() const override { return original_.num_equality(); }

  Evaluation evaluate(std::span<const double> x) const override {
    return scalarized(x, original_.evaluate(x));
  }
  // A sub-solve's batch (its finite-difference probes) goes to the original
  // problem as one batch too.
  std::vector<Evaluation> evaluate_batch(const std::vector<std::vector<double>>& xs) const override {
    std::vector<Evaluation> originals = original_.evaluate_batch(xs);
    std::vector<Evaluation> out;
    out.reserve(xs.size());
    for (std::size_t k = 0; k < xs.size(); ++k) out.push_back(scalarized(xs[k], std::move(originals[k])));
    return out;
  }

  // The sub-problem's evaluation from the original one at x (kept for
  // original_at).
  Evaluation scalarized(std::span<const double> x, Evaluation e) const {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      seen_.emplace(std::vector<double>(x.begin(), x.end()), e);
    }
    if (!e.ok()) return e;
    if (e.objectives.size() != m_) {
      Evaluation bad;
      bad.status = EvaluationStatus::kFailed;
      bad.message = "the problem declares " + std::to_string(m_) + " objectives but evaluate() returned " +
                    std::to_string(e.objectives.size());
      return bad;
    }
    double scalar = 0.0;
    for (std::size_t i = 0; i < m_; ++i)
      if (weights_[i] != 0.0) scalar += weights_[i] * (e.objectives[i] - ideal_[i]) / range_[i];
    std::vector<double> f = std::move(e.objectives);
    e.objectives = {scalar};
    for (const Bound& b : bounds_) e.inequality.push_back((f[b.objective] - b.eps) / range_[b.objective]);
    return e;  // a NaN anywhere is turned into a failed evaluation by the adapter
  }

  // The original evaluation at x if evaluate() saw x.
  std::optional<Evaluation> original_at(std::span<const double> x) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = seen_.find(std::vector<double>(x.begin(), x.end()));
    if (it == seen_.end()) return std::nullopt;
    return it->second;
  }

  ScalarizedProblem(const ScalarizedProblem& other)
      : original_(other.original_), m_(other.m_), ideal_(other.ideal_), range_(other.range_),
        weights_(other.weights_), bounds_(other.bounds_) {}

 private:
  const Problem& original_;
  std::size_t m_;
  std::vector<double> ideal_, range_, weights_;
  std::vector<Bound> bounds_;
  mutable std::mutex mutex_;
  mutable std::map<std::vector<double>, Evaluation> seen_;
};

std::string format_weights(const std::vector<double>& w) {
  std::string s = "w ";
  for (std::size_t i = 0; i < w.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", w[i]);
    s += (i ? "/" : "") + std::string(buf);
  }
  return s;
}

struct SubProblemSpec {
  std::string label;
  std::vector<double> weights;                   // weighted sum
  std::vector<ScalarizedProblem::Bound> bounds;  // eps-constraint
};

// The grid of sub-problems after the anchors, in warm-start order (each is a
// neighbour of the one before it).
std::vector<SubProblemSpec> grid(const ParetoSettings& s, std::size_t m, const std::vector<double>& ideal,
                                 const std::vector<double>& range) {
  std::vector<SubProblemSpec> out;
  const std::size_t points = s.points;
  if (s.method == Scalarization::kEpsilonConstraint) {
    std::vector<std::size_t> bounded;
    for (std::size_t j = 0; j < m; ++j)
      if (j != s.primary) bounded.push_back(j);
    auto eps = [&](std::size_t j, double t) { return ideal[j] + t * range[j]; };
    if (m == 2) {
      // eps levels strictly between ideal and nadir (the ends are the anchors),
      // from tight (next to the anchor of the bounded objective) to loose.
      for (std::size_t k = 1; k + 1 < points; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(points - 1);
        out.push_back({"eps " + std::to_string(k), {}, {{bounded[0], eps(bounded[0], t)}}});
      }
    } else {
      // L x L square grid of interior levels t = a/(L+1), L = floor(sqrt(points - 3)),
      // walked row by row in serpentine order.
      std::size_t levels = 0;
      while (points >= 3 && (levels + 1) * (levels + 1) <= points - 3) ++levels;
      for (std::size_t a = 1; a <= levels; ++a)
        for (std::size_t step = 1; step <= levels; ++step) {
          const std::size_t b = (a % 2 == 1) ? step : levels + 1 - step;
          const double ta = static_cast<double>(a) / static_cast<double>(levels + 1);
          const double tb = static_cast<double>(b) / static_cast<double>(levels + 1);
          out.push_back({"eps " + std::to_string(a) + "," + std::to_string(b),
                         {},
                         {{bounded[0], eps(bounded[0], ta)}, {bounded[1], eps(bounded[1], tb)}}});
        }
    }
  } else if (m == 2) {
    for (std::size_t k = 1; k + 1 < points; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(points - 1);
      std::vector<double> w{1.0 - t, t};
      out.push_back({format_weights(w), w, {}});
    }
  } else {
    // Simplex lattice w = (a, b, c)/n, a + b + c = n, the largest n with
    // (n+1)(n+2)/2 <= points; the three vertices are the anchors.
    std::size_t n = 1;
    while ((n + 2) * (n + 3) / 2 <= points) ++n;
    for (std::size_t a = n + 1; a-- > 0;)
      for (std::size_t step = 0; step <= n - a; ++step) {
        const std::size_t b = ((n - a) % 2 == 0) ? step : n - a - step;
        const std::size_t c = n - a - b;
        if (a == n || b == n || c == n) continue;
        const double dn = static_cast<double>(n);
        std::vector<double> w{static_cast<double>(a) / dn, static_cast<double>(b) / dn, static_cast<double>(c) / dn};
        out.push_back({format_weights(w), w, {}});
      }
  }
  return out;
}

}  // namespace

ParetoResult pareto_front(const Problem& problem, std::span<const double> x0, const ParetoSettings& settings,
                          const ParetoCallbacks& callbacks) {
  const std::size_t m = problem.num_objectives();
  if (settings.method == Scalarization::kPopulation) {
    const SolverBackend* backend = find_solver_backend(settings.solver.library);
    if (!backend || !backend->finds_fronts(settings.solver))
      throw std::invalid_argument("pareto_front: the population method needs an algorithm that finds fronts "
                                  "(pagmo's nsga2 or moead); '" + settings.solver.library + " " +
                                  settings.solver.algorithm + "' minimizes one objective: use eps_constraint or "
                                  "weighted_sum with it");
    if (settings.points < 2)
      throw std::invalid_argument("pareto_front needs points >= 2, got " + std::to_string(settings.points));
    if (!(settings.duplicate_tolerance >= 0.0) || !std::isfinite(settings.duplicate_tolerance))
      throw std::invalid_argument("pareto_front: duplicate_tolerance must be finite and >= 0");
    if (std::string msg = check_solver_settings(settings.solver, problem, x0); !msg.empty())
      throw std::invalid_argument("pareto_front: " + msg);
    return backend->front(problem, x0, settings, callbacks);
  }
  if (algorithm_finds_fronts(settings.solver))
    throw std::invalid_argument("pareto_front: " + settings.solver.algorithm +
                                " finds whole fronts; use it with the population method, or give the "
                                "scalarized sub-problems a single-objective algorithm");
  if (m != 2 && m != 3)
    throw std::invalid_argument("pareto_front needs 2 or 3 objectives; the problem has " + std::to_string(m));
  if (settings.points < 2)
    throw std::invalid_argument("pareto_front needs points >= 2 (the anchors), got " + std::to_string(settings.points));
  if (settings.primary >= m)
    throw std::invalid_argument("pareto_front: primary objective " + std::to_string(settings.primary) +
                                " out of range (the problem has " + std::to_string(m) + " objectives)");
  if (!(settings.duplicate_tolerance >= 0.0) || !std::isfinite(settings.duplicate_tolerance))
    throw std::invalid_argument("pareto_front: duplicate_tolerance must be finite and >= 0");

  // Refuse up front what a sub-problem would refuse half-way through.
  const std::vector<double> unit_ideal(m, 0.0), unit_range(m, 1.0);
  if (std::string msg = check_solver_settings(settings.solver, ScalarizedProblem::anchor(problem, 0), x0);
      !msg.empty())
    throw std::invalid_argument("pareto_front: " + msg);
  if (settings.method == Scalarization::kEpsilonConstraint) {
    std::vector<ScalarizedProblem::Bound> bounds;
    for (std::size_t j = 0; j < m; ++j)
      if (j != settings.primary) bounds.push_back({j, 0.0});
    const auto sample = ScalarizedProblem::epsilon(problem, settings.primary, bounds, unit_ideal, unit_range);
    if (std::string msg = check_solver_settings(settings.solver, sample, x0); !msg.empty())
      throw std::invalid_argument("pareto_front: the eps-constraint method bounds the other objectives with " +
                                  std::to_string(m - 1) + " inequality constraint(s): " + msg +
                                  "; or use Scalarization::kWeightedSum");
  }

  ParetoResult result;
  const double tol = settings.solver.constraint_tolerance;
  std::size_t reported = 0;  // evaluations reported to the observer so far
  bool stopped = false;
  std::vector<ParetoPoint> all;  // every solved sub-problem, in solve order

  auto solve = [&](const ScalarizedProblem& sub, const std::string& label,
                   std::span<const double> start) -> std::optional<ParetoPoint> {
    SolverCallbacks cb;
    // Whether the request fired is remembered here: the sub-solve's status
    // ranks no_feasible_point / all_failed above "stopped", and a stop during
    // an infeasible sub-problem must still end the whole front.
    if (callbacks.stop)
      cb.stop = [&] {
        if (!callbacks.stop()) return false;
        stopped = true;
        return true;
      };
    if (callbacks.observer)
      cb.observer = [&](const EvaluationRecord& rec) {
        EvaluationRecord out = rec;
        out.index = reported++;
        if (auto original = sub.original_at(rec.x)) out.evaluation = std::move(*original);
        callbacks.observer(label, out);
      };
    const SolverResult r = minimize(sub, start, settings.solver, cb);
    result.evaluations += r.evaluations;
    result.failed_evaluations += r.failed_evaluations;
    ++result.subproblems;
    if (r.status == SolverStatus::kStopped) stopped = true;
    std::optional<Evaluation> original = sub.original_at(r.x);
    if (!original) return std::nullopt;  // stopped before its first evaluation
    ParetoPoint p;
    p.x = r.x;
    p.evaluation = std::move(*original);
    p.label = label;
    p.feasible = is_feasible(p.evaluation, tol) && p.evaluation.objectives.size() == m;
    for (double f : p.evaluation.objectives) p.feasible = p.feasible && std::isfinite(f);
    return p;
  };

  // Anchors: each objective alone, all from x0. They do not depend on each
  // other, so they run in lockstep (lockstep_runs.hpp): each round's points
  // of every anchor go to the problem as one batch.
  std::vector<std::optional<ParetoPoint>> anchors(m);
  run_in_lockstep(
      m, m,
      [&](std::size_t k, LockstepChannel& channel) {
        if (stopped) return;
        const LockstepProblem through(problem, channel);
        anchors[k] = solve(ScalarizedProblem::anchor(through, k), "anchor " + std::to_string(k), x0);
      },
      [&](const std::vector<LockstepRequest>& round) {
        std::vector<std::vector<double>> us;
        for (const LockstepRequest& r : round) us.insert(us.end(), r.us->begin(), r.us->end());
        std::vector<Evaluation> got = problem.evaluate_batch(us);
        std::vector<std::vector<Evaluation>> replies;
        std::size_t next = 0;
        for (const LockstepRequest& r : round) {
          replies.emplace_back(std::make_move_iterator(got.begin() + static_cast<std::ptrdiff_t>(next)),
                               std::make_move_iterator(got.begin() + static_cast<std::ptrdiff_t>(next + r.us->size())));
          next += r.us->size();
        }
        return replies;
      });
  for (std::size_t k = 0; k < m; ++k)
    if (anchors[k]) all.push_back(*anchors[k]);
  bool anchors_complete = true;
  for (std::size_t k = 0; k < m; ++k) anchors_complete = anchors_complete && anchors[k] && anchors[k]->feasible;

  bool any_feasible_anchor = false;
  result.ideal.assign(m, std::numeric_limits<double>::infinity());
  result.nadir.assign(m, -std::numeric_limits<double>::infinity());
  for (const auto& a : anchors) {
    if (!a || !a->feasible) continue;
    any_feasible_anchor = true;
    for (std::size_t i = 0; i < m; ++i) {
      result.ideal[i] = std::min(result.ideal[i], a->evaluation.objectives[i]);
      result.nadir[i] = std::max(result.nadir[i], a->evaluation.objectives[i]);
    }
  }

  std::vector<double> range(m, 1.0);
  if (!any_feasible_anchor) {
    result.ideal.clear();
    result.nadir.clear();
  } else {
    // A range that vanishes (objectives that do not conflict) would divide
    // by zero; unit scaling keeps the sub-problems defined.
    for (std::size_t i = 0; i < m; ++i) {
      const double r = result.nadir[i] - result.ideal[i];
      if (r > 1e-12 * std::max(1.0, std::abs(result.ideal[i]))) range[i] = r;
    }
    // Warm start: the eps grid starts tight on the first bounded objective,
    // next to that objective's anchor; the weighted sum starts next to anchor 0.
    std::size_t first = 0;
    if (settings.method == Scalarization::kEpsilonConstraint) first = settings.primary == 0 ? 1 : 0;
    std::vector<double> start(x0.begin(), x0.end());
    if (anchors[first] && anchors[first]->feasible) start = anchors[first]->x;
    for (const SubProblemSpec& spec : grid(settings, m, result.ideal, range)) {
      if (stopped) break;
      const ScalarizedProblem sub =
          settings.method == Scalarization::kEpsilonConstraint
              ? ScalarizedProblem::epsilon(problem, settings.primary, spec.bounds, result.ideal, range)
              : ScalarizedProblem::weighted(problem, spec.weights, result.ideal, range);
      std::optional<ParetoPoint> p = solve(sub, spec.label, start);
      if (!p) continue;
      if (p->feasible) start = p->x;
      all.push_back(std::move(*p));
    }
  }

  // The distinct front of `all` so far: feasible, non-dominated, no
  // near-duplicates (within duplicate_tolerance * range), in the order
  // (primary, other objectives, solve order): indices into `all`.
  auto distinct_front = [&] {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].feasible) order.push_back(i);
    auto key = [&](std::size_t i) {
      std::vector<double> k{all[i].evaluation.objectives[settings.primary]};
      for (std::size_t j = 0; j < m; ++j)
        if (j != settings.primary) k.push_back(all[i].evaluation.objectives[j]);
      return k;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    std::vector<std::vector<double>> vectors;
    for (std::size_t i : order) vectors.push_back(all[i].evaluation.objectives);
    std::vector<bool> is_kept(order.size(), false);
    for (std::size_t k : non_dominated(vectors)) is_kept[k] = true;
    std::vector<std::size_t> front;
    for (std::size_t pos = 0; pos < order.size(); ++pos) {
      if (!is_kept[pos]) continue;
      const ParetoPoint& p = all[order[pos]];
      const bool duplicate = std::any_of(front.begin(), front.end(), [&](std::size_t f) {
        for (std::size_t i = 0; i < m; ++i)
          if (std::abs(p.evaluation.objectives[i] - all[f].evaluation.objectives[i]) >
              settings.duplicate_tolerance * range[i])
            return false;
        return true;
      });
      if (!duplicate) front.push_back(order[pos]);
    }
    return front;
  };

  // eps-constraint: a grid leaves gaps where sub-problems landed on the same
  // design or found none feasible. Fill them while the front is short: bound
  // the other objectives halfway between the two front points farthest from
  // each other's nearest neighbours and warm-start from one of them; a pair
  // is tried once, and at most twice the missing count of sub-problems run.
  if (settings.method == Scalarization::kEpsilonConstraint && any_feasible_anchor && !stopped) {
    std::vector<std::pair<std::size_t, std::size_t>> tried;
    const std::size_t first_count = distinct_front().size();
    const std::size_t attempts = first_count < settings.points ? 2 * (settings.points - first_count) : 0;
    for (std::size_t attempt = 0; attempt < attempts && !stopped; ++attempt) {
      const std::vector<std::size_t> front = distinct_front();
      if (front.size() >= settings.points || front.size() < 2) break;
      auto distance = [&](std::size_t a, std::size_t b) {
        double d = 0;
        for (std::size_t i = 0; i < m; ++i) {
          const double t = (all[a].evaluation.objectives[i] - all[b].evaluation.objectives[i]) / range[i];
          d += t * t;
        }
        return d;
      };
      // The untried pair (p, nearest neighbour of p) of largest distance.
      std::optional<std::pair<std::size_t, std::size_t>> widest;
      double widest_d = -1;
      for (std::size_t a : front) {
        std::size_t nearest = a;
        double nd = std::numeric_limits<double>::infinity();
        for (std::size_t b : front) {
          if (b == a) continue;
          const std::pair<std::size_t, std::size_t> pair{std::min(a, b), std::max(a, b)};
          if (std::find(tried.begin(), tried.end(), pair) != tried.end()) continue;
          const double d = distance(a, b);
          if (d < nd) {
            nd = d;
            nearest = b;
          }
        }
        if (nearest != a && nd > widest_d) {
          widest_d = nd;
          widest = std::pair<std::size_t, std::size_t>{std::min(a, nearest), std::max(a, nearest)};
        }
      }
      if (!widest) break;
      tried.push_back(*widest);
      const ParetoPoint& pa = all[widest->first];
      const ParetoPoint& pb = all[widest->second];
      std::vector<ScalarizedProblem::Bound> bounds;
      for (std::size_t j = 0; j < m; ++j)
        if (j != settings.primary)
          bounds.push_back({j, 0.5 * (pa.evaluation.objectives[j] + pb.evaluation.objectives[j])});
      const std::vector<double> start = pa.x;
      const ScalarizedProblem sub = ScalarizedProblem::epsilon(problem, settings.primary, bounds, result.ideal, range);
      std::optional<ParetoPoint> p = solve(sub, "eps fill " + std::to_string(attempt + 1), start);
      if (p) all.push_back(std::move(*p));
    }
  }

  const std::vector<std::size_t> kept = distinct_front();
  std::vector<bool> in_front(all.size(), false);
  for (std::size_t i : kept) in_front[i] = true;
  for (std::size_t i : kept) result.front.push_back(all[i]);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (in_front[i]) continue;
    (all[i].feasible ? result.dominated : result.infeasible).push_back(std::move(all[i]));
  }

  if (stopped)
    result.status = ParetoStatus::kStopped;
  else if (result.front.empty())
    result.status = ParetoStatus::kNoFeasiblePoint;
  else if (!anchors_complete)
    result.status = ParetoStatus::kAnchorInfeasible;
  else
    result.status = ParetoStatus::kOk;
  return result;
}

std::string_view method_title(Scalarization method) {
  switch (method) {
    case Scalarization::kEpsilonConstraint: return "eps-constraint";
    case Scalarization::kWeightedSum: return "weighted sum";
    case Scalarization::kPopulation: return "population search";
  }
  return "?";
}

std::string_view to_string(ParetoStatus status) {
  switch (status) {
    case ParetoStatus::kOk: return "ok";
    case ParetoStatus::kNoFeasiblePoint: return "no_feasible_point";
    case ParetoStatus::kAnchorInfeasible: return "anchor_infeasible";
    case ParetoStatus::kStopped: return "stopped";
  }
  return "?";
}

}  // namespace rackopt::solvers
