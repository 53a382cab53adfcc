// The FE rows of docs/accuracy.md and docs/performance.md: the FE reference
// tier's own discretisation error (three levels, observed order, Richardson
// extrapolation), what it costs, and the analytic model's error against it.
// Prints Markdown.
//
//   ./build/fe_accuracy [--table levels|compare|window|all] [--problems a,b,...]
//                       [--positions N] [--levels 0,1,2] [--threads T]
//                       [--max-pair-level L] [--time-limit S]
//
//   levels   per problem: K at the middle of the single- and of the double-pair
//            zone, and the pinion and rack single-tooth compliances at the
//            pitch point, at each level; order, Richardson value, each level's
//            error against it; elements and wall time.
//            (default problems: gantry_axis, rack_railway)
//   compare  per problem: compare_with_fe (fe_comparison.hpp) at N positions
//            over one mesh period at the first of --levels: the analytic
//            model's K, load shares and single-tooth compliances against FE
//            (rigid rack body in the analytic model, the FE rack segment held
//            at its base), the force the last load step reached, the time per
//            position of both. (default problems: every problems/*.yaml)
//   window   per problem: the secant K over load windows 0.2-0.6, 0.2-1.0 and
//            0.5-1.0 of the last step, one ccx run with four steps.
//            (default problems: gantry_axis, rack_railway)
//
// --max-pair-level: the levels table solves pair positions only up to level
// L (a level-2 pair position is ~40 000 elements and 20-40 ccx iterations);
// --time-limit: seconds per ccx solve (default 3600).
// Problems are names in problems/ (without .yaml) or paths. --threads runs
// that many FE solves at once (each ccx single-threaded; Gmsh meshing is
// serialized inside the library). Times are wall times of each solve.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/fe/mesh_position_fe.hpp"
#include "rackopt/fe/richardson.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace {

using namespace rackopt;
using namespace rackopt::fe;

struct Args {
  std::string table = "all";
  std::vector<std::string> problems;
  int positions = 6;
  std::vector<int> levels = {0, 1, 2};
  int threads = 1;
  int max_pair_level = 2;           // levels table: pair positions only up to this level
  double time_limit_seconds = 3600; // per ccx solve
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t a = 0;
  while (a <= s.size()) {
    const std::size_t b = std::min(s.find(',', a), s.size());
    if (b > a) out.push_back(s.substr(a, b - a));
    a = b + 1;
  }
  return out;
}

std::string problem_path(const std::string& name) {
  if (name.find('/') != std::string::npos || name.ends_with(".yaml")) return name;
  return std::string(RACKOPT_SOURCE_DIR) + "/problems/" + name + ".yaml";
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::vector<std::string> all_problems() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(RACKOPT_SOURCE_DIR) + "/problems")) {
    if (e.path().extension() == ".yaml") out.push_back(e.path().stem().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Runs the jobs on `threads` threads, in order of submission.
void run_jobs(std::vector<std::function<void()>>& jobs, int threads) {
  std::atomic<std::size_t> next{0};
  std::mutex err_mutex;
  std::string first_error;
  auto worker = [&] {
    for (std::size_t k; (k = next++) < jobs.size();) {
      try {
        jobs[k]();
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(err_mutex);
        if (first_error.empty()) first_error = e.what();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (!first_error.empty()) throw std::runtime_error(first_error);
}

Drive rigid_rack(Drive d) {
  d.effects.rack_span = RackSpanModel::kRigid;
  return d;
}

// Travel at the middle of the longest stretch of the first mesh period with
// `pairs` pairs in mesh (NaN if none).
double zone_middle(const MeshStiffnessModel& model, double pitch, std::size_t pairs) {
  const int n = 400;
  double best_len = 0, best_mid = NAN, run_start = NAN;
  for (int k = 0; k <= n; ++k) {
    const double X = pitch * (1.0 + k / static_cast<double>(n));
    const bool in = k < n && model.at(X).pairs.size() == pairs;
    if (in && std::isnan(run_start)) run_start = X;
    if (!in && !std::isnan(run_start)) {
      if (X - run_start > best_len) {
        best_len = X - run_start;
        best_mid = 0.5 * (run_start + X);
      }
      run_start = NAN;
    }
  }
  return best_mid;
}

// ---- levels ------------------------------------------------------------------------

struct LevelValue {
  double value = NAN;
  int elements = 0;
  double seconds = 0;
  std::string failed;  // why there is no value (a failed or skipped solve)
};

void levels_table(const std::vector<std::string>& problems, const std::vector<int>& levels, const Args& args) {
  struct Quantity {
    std::string problem, name;
    std::vector<LevelValue> at;  // per level
  };
  std::vector<Quantity> q;
  std::vector<std::function<void()>> jobs;
  std::mutex mu;
  for (const std::string& name : problems) {
    const Drive d = load_problem(problem_path(name));
    const MeshStiffnessModel model(rigid_rack(d));
    const double pitch = M_PI * d.pinion.module;
    const double s_p = model.geometry().path.s_pitch;
    const double X1 = zone_middle(model, pitch, 1), X2 = zone_middle(model, pitch, 2);
    const std::size_t first = q.size();
    char label[96];
    std::snprintf(label, sizeof label, "K, single-pair zone (X = %.3f p)", X1 / pitch);
    q.push_back({stem(name), std::isnan(X1) ? "" : label, {}});
    std::snprintf(label, sizeof label, "K, double-pair zone (X = %.3f p)", X2 / pitch);
    q.push_back({stem(name), std::isnan(X2) ? "" : label, {}});
    std::snprintf(label, sizeof label, "pinion tooth compliance, s = s_P = %.2f mm", s_p * 1e3);
    q.push_back({stem(name), label, {}});
    std::snprintf(label, sizeof label, "rack tooth compliance, s = s_P");
    q.push_back({stem(name), label, {}});
    for (std::size_t k = first; k < q.size(); ++k) q[k].at.resize(levels.size());
    // Finest level first: the longest solves start first and the threads stay busy.
    for (std::size_t li = levels.size(); li-- > 0;) {
      FeOptions o;
      o.level = levels[li];
      o.ccx.time_limit_seconds = args.time_limit_seconds;
      for (int which = 0; which < 4; ++which) {
        if (q[first + which].name.empty()) continue;
        if (which < 2 && o.level > args.max_pair_level) {
          q[first + static_cast<std::size_t>(which)].at[li].failed = "not run (--max-pair-level)";
          continue;
        }
        jobs.push_back([&q, &mu, d, o, which, first, li, X1, X2, s_p] {
          LevelValue v;
          try {
          if (which < 2) {
            const FePosition p = fe_mesh_position(d, which == 0 ? X1 : X2, o);
            v = {p.stiffness, p.elements, p.seconds, {}};
          } else {
            const ToothComplianceFe c =
                fe_tooth_compliance(d, which == 2 ? ToothMember::kPinion : ToothMember::kRack, s_p, o);
            v = {c.compliance, c.elements, c.seconds, {}};
          }
          } catch (const std::exception& e) {
            v.failed = e.what();
            v.failed = v.failed.substr(0, v.failed.find('\n'));
          }
          std::lock_guard<std::mutex> lock(mu);
          q[first + static_cast<std::size_t>(which)].at[li] = v;
          std::fprintf(stderr, "  level %d, quantity %d: %.6g (%d elements, %.1f s) %s\n", o.level, which, v.value,
                       v.elements, v.seconds, v.failed.c_str());
        });
      }
    }
  }
  run_jobs(jobs, args.threads);

  std::printf("| problem | quantity | level | elements | value | wall s | error vs Richardson |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Quantity& x : q) {
    if (x.name.empty()) continue;
    std::vector<double> v;
    for (const LevelValue& l : x.at) v.push_back(l.value);
    // 7 printed digits in ccx's .dat: differences below ~1e-6 are not resolved.
    RichardsonEstimate e;
    bool have = v.size() >= 3 && std::all_of(v.begin(), v.end(), [](double y) { return std::isfinite(y); });
    if (have) e = richardson(v, 2.0, 1e-6);
    const bool stiffness = x.name[0] == 'K';
    for (std::size_t li = 0; li < x.at.size(); ++li) {
      if (!x.at[li].failed.empty()) {
        std::printf("| %s | %s | %d | | – | | %s |\n", x.problem.c_str(), x.name.c_str(), levels[li],
                    x.at[li].failed.c_str());
        continue;
      }
      char err[32] = "–";
      if (have && !std::isnan(e.relative_error[li])) std::snprintf(err, sizeof err, "%.2e", e.relative_error[li]);
      std::printf("| %s | %s | %d | %d | %.6g %s | %.1f | %s |\n", x.problem.c_str(), x.name.c_str(), levels[li],
                  x.at[li].elements, stiffness ? x.at[li].value : x.at[li].value * 1e9,
                  stiffness ? "N/m" : "e-9 m/N", x.at[li].seconds, err);
    }
    if (!have && x.at.size() >= 2 && std::isfinite(x.at[0].value) && std::isfinite(x.at[1].value)) {
      std::printf("| %s | %s | 0 → 1 | | %+.2e | | (no third level) |\n", x.problem.c_str(), x.name.c_str(),
                  x.at[1].value / x.at[0].value - 1);
    }
    if (have) {
      std::printf("| %s | %s | Richardson | | %.6g %s | | order %.2f, %s |\n", x.problem.c_str(), x.name.c_str(),
                  stiffness ? e.extrapolated : e.extrapolated * 1e9, stiffness ? "N/m" : "e-9 m/N", e.order,
                  to_string(e.status).c_str());
    }
  }
}

// ---- compare -----------------------------------------------------------------------

// The analytic model against FE (fe_comparison.hpp: rigid rack body in the
// analytic model, FE rack segment held at its base; errors (analytic - FE) / FE,
// share errors analytic - FE).
void compare_table(const std::vector<std::string>& problems, int positions, int level, int threads,
                   double time_limit) {
  struct Row {
    std::string problem;
    double load = 0;
    FeComparison c;
  };
  std::vector<Row> rows;
  for (const std::string& name : problems) {
    const Drive d = load_problem(problem_path(name));
    FeComparisonOptions opt;
    opt.positions = positions;
    opt.fe.level = level;
    opt.fe.ccx.time_limit_seconds = time_limit;
    opt.threads = static_cast<unsigned>(threads);
    std::fprintf(stderr, "  comparing %s ...\n", stem(name).c_str());
    rows.push_back({stem(name), d.load.force, compare_with_fe(d, opt)});
  }

  std::printf("Summary (level %d, %d positions over one mesh period, errors of the analytic model against FE: "
              "(analytic − FE) / FE, shares analytic − FE; compliances at every pair's contact at every position):\n\n",
              level, positions);
  std::printf("| problem | K error max | K error mean | share error max | pinion compliance error max | "
              "rack compliance error max | F₂ / load.force | FE s per position (mesh + teeth) | "
              "analytic s per position | FE / analytic time |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const FeComparisonSummary& s = r.c.summary;
    double emax = 0, esum = 0, fmin = INFINITY, fmax = 0, pmax = 0, rmax = 0;
    for (const ComparedPosition& p : r.c.rows) {
      if (std::abs(p.k_error) > std::abs(emax)) emax = p.k_error;
      esum += p.k_error;
      fmin = std::min(fmin, p.fe_force / r.load);
      fmax = std::max(fmax, p.fe_force / r.load);
      for (const ComparedPair& q : p.pairs) {
        if (std::abs(q.pinion_error) > std::abs(pmax)) pmax = q.pinion_error;
        if (std::abs(q.rack_error) > std::abs(rmax)) rmax = q.rack_error;
      }
    }
    std::printf("| %s | %+.3f | %+.3f | %.3f | %+.3f | %+.3f | %.2f–%.2f | %.1f (%.1f + %.1f) | %.2e | %.1e |\n",
                r.problem.c_str(), emax, esum / static_cast<double>(r.c.rows.size()), s.max_share_error, pmax, rmax,
                fmin, fmax, s.fe_seconds_per_position, s.fe_mesh_seconds_per_position,
                s.fe_seconds_per_position - s.fe_mesh_seconds_per_position, s.analytic_seconds_per_position,
                s.time_ratio);
  }

  std::printf("\nPer position (K in N/m; shares and compliance errors per pair, nearest the pinion tip first):\n\n");
  std::printf("| problem | X − X₀ [p] | K_FE | K_an | K error | shares FE | shares analytic | pinion error | "
              "rack error | F₂ / load.force | elements | mesh solve s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    for (const ComparedPosition& p : r.c.rows) {
      std::string sf, sa, pe, re;
      char b[40];
      for (const ComparedPair& q : p.pairs) {
        const char* sep = sf.empty() ? "" : " / ";
        std::snprintf(b, sizeof b, "%s%.3f", sep, q.share_fe);
        sf += b;
        std::snprintf(b, sizeof b, "%s%.3f", sep, q.share_analytic);
        sa += b;
        if (q.pinion_compared) {
          std::snprintf(b, sizeof b, "%s%+.3f", sep, q.pinion_error);
        } else {
          std::snprintf(b, sizeof b, "%sn/a", sep);  // contact off the pinion's involute
        }
        pe += b;
        std::snprintf(b, sizeof b, "%s%+.3f", sep, q.rack_error);
        re += b;
      }
      std::printf("| %s | %.3f | %.4g | %.4g | %+.3f | %s | %s | %s | %s | %.3f | %d | %.1f |\n", r.problem.c_str(),
                  (p.travel - r.c.period_start) / r.c.pitch, p.k_fe, p.k_analytic, p.k_error, sf.c_str(), sa.c_str(),
                  pe.c_str(), re.c_str(), p.fe_force / r.load, p.elements, p.fe_mesh_seconds);
    }
  }
}

// ---- window ------------------------------------------------------------------------

void window_table(const std::vector<std::string>& problems, int level, int threads, double time_limit) {
  struct Row {
    std::string problem, zone;
    double X = 0, pitch = 0, rb = 0;
    FePosition p;
  };
  std::vector<Row> rows;
  for (const std::string& name : problems) {
    const Drive d = load_problem(problem_path(name));
    const MeshStiffnessModel model(rigid_rack(d));
    const double pitch = M_PI * d.pinion.module;
    const double rb = model.geometry().pinion.base_radius;
    rows.push_back({stem(name), "single", zone_middle(model, pitch, 1), pitch, rb, {}});
    rows.push_back({stem(name), "double", zone_middle(model, pitch, 2), pitch, rb, {}});
  }
  std::vector<std::function<void()>> jobs;
  for (Row& r : rows) {
    if (std::isnan(r.X)) continue;
    jobs.push_back([&r, level, time_limit] {
      FeOptions o;
      o.level = level;
      o.ccx.time_limit_seconds = time_limit;
      MeshPositionTuning t;
      t.step_fractions = {0.2, 0.5, 0.6, 1.0};
      r.p = fe_mesh_position(load_problem(problem_path(r.problem)), r.X, o, t);
    });
  }
  run_jobs(jobs, threads);
  std::printf("| problem | zone | X / p | F / load.force at the steps | K 0.2–0.6 [N/m] | K 0.2–1.0 | K 0.5–1.0 | "
              "K 0.5–1.0 / K 0.2–0.6 − 1 | K 0.2–1.0 / K 0.2–0.6 − 1 | tangent K at 0.55 / at 0.35 − 1 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    if (std::isnan(r.X)) continue;
    const auto& th = r.p.step_rotations;
    const auto& F = r.p.step_forces;
    const double load = r.p.force / r.p.load_fraction;
    const auto k = [&](int a, int b) { return (F[b] - F[a]) / (r.rb * (th[b] - th[a])); };
    std::string fr;
    char b[32];
    for (double f : F) {
      std::snprintf(b, sizeof b, "%s%.3f", fr.empty() ? "" : " / ", f / load);
      fr += b;
    }
    std::printf("| %s | %s | %.3f | %s | %.5g | %.5g | %.5g | %+.2e | %+.2e | %+.2e |\n", r.problem.c_str(),
                r.zone.c_str(), r.X / r.pitch - 1, fr.c_str(), k(0, 2), k(0, 3), k(1, 3), k(1, 3) / k(0, 2) - 1,
                k(0, 3) / k(0, 2) - 1, k(1, 2) / k(0, 1) - 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Args a;
    for (int i = 1; i < argc; ++i) {
      const std::string k = argv[i];
      const auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(k + " needs a value");
        return argv[++i];
      };
      if (k == "--table") a.table = value();
      else if (k == "--problems") a.problems = split(value());
      else if (k == "--positions") a.positions = std::stoi(value());
      else if (k == "--levels") {
        a.levels.clear();
        for (const std::string& l : split(value())) a.levels.push_back(std::stoi(l));
      } else if (k == "--threads") a.threads = std::stoi(value());
      else if (k == "--max-pair-level") a.max_pair_level = std::stoi(value());
      else if (k == "--time-limit") a.time_limit_seconds = std::stod(value());
      else throw std::invalid_argument("unknown option " + k + " (see the comment at the top of bench/fe_accuracy.cpp)");
    }
    if (a.positions < 1 || a.threads < 1 || a.levels.empty()) throw std::invalid_argument("bad --positions/--threads/--levels");
    const std::vector<std::string> two = {"gantry_axis", "rack_railway"};
    const auto start = std::chrono::steady_clock::now();
    if (a.table == "levels" || a.table == "all") {
      std::printf("### FE levels: discretisation error and cost\n\n");
      levels_table(a.problems.empty() ? two : a.problems, a.levels, a);
      std::printf("\n");
    }
    if (a.table == "window" || a.table == "all") {
      std::printf("### Load window of the secant K (level %d)\n\n", a.levels.front());
      window_table(a.problems.empty() ? two : a.problems, a.levels.front(), a.threads, a.time_limit_seconds);
      std::printf("\n");
    }
    if (a.table == "compare" || a.table == "all") {
      std::printf("### Analytic model against FE\n\n");
      compare_table(a.problems.empty() ? all_problems() : a.problems, a.positions, a.levels.front(), a.threads,
                    a.time_limit_seconds);
      std::printf("\n");
    }
    std::fprintf(stderr, "fe_accuracy: %.0f s\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fe_accuracy: %s\n", e.what());
    return 1;
  }
  return 0;
}
