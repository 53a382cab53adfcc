// The FE rows of docs/accuracy.md and docs/performance.md: the FE reference
// tier's own discretisation error (three levels, observed order, Richardson
// extrapolation), what it costs, and the analytic model's error against it.
// Prints Markdown.
//
//   ./build/fe_accuracy [--table levels|compare|window|all] [--problems a,b,...]
//                       [--positions N] [--levels 0,1,2] [--threads T]
//
//   levels   per problem: K at the middle of the single- and of the double-pair
//            zone, and the pinion and rack single-tooth compliances at the
//            pitch point, at each level; order, Richardson value, each level's
//            error against it; elements and wall time.
//            (default problems: gantry_axis, rack_railway)
//   compare  per problem: N positions over one mesh period at level 0 (the
//            first of --levels): FE K and load shares against the analytic
//            model with a rigid rack body (the body the FE rack segment sits
//            on is held at its base: MeshStiffnessModel's rack_span = rigid),
//            the single-tooth compliances at three contacts, the force the
//            last load step reached, and the analytic model's time per position.
//            (default problems: every problems/*.yaml)
//   window   per problem: the secant K over load windows 0.2-0.6, 0.2-1.0 and
//            0.5-1.0 of the last step, one ccx run with four steps.
//            (default problems: gantry_axis, rack_railway)
//
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

// Median wall time [s] of the analytic model at one position (model built once, as a curve does).
double analytic_seconds_per_position(const MeshStiffnessModel& model, double pitch) {
  std::vector<double> t;
  for (int rep = 0; rep < 21; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    double sink = 0;
    for (int k = 0; k < 100; ++k) sink += model.at(pitch * (1 + k / 100.0)).stiffness;
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 100);
    if (!(sink > 0)) throw std::runtime_error("analytic stiffness not positive");
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// ---- levels ------------------------------------------------------------------------

struct LevelValue {
  double value = NAN;
  int elements = 0;
  double seconds = 0;
};

void levels_table(const std::vector<std::string>& problems, const std::vector<int>& levels, int threads) {
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
    for (std::size_t li = 0; li < levels.size(); ++li) {
      FeOptions o;
      o.level = levels[li];
      for (int which = 0; which < 4; ++which) {
        if (q[first + which].name.empty()) continue;
        jobs.push_back([&q, &mu, d, o, which, first, li, X1, X2, s_p] {
          LevelValue v;
          if (which < 2) {
            const FePosition p = fe_mesh_position(d, which == 0 ? X1 : X2, o);
            v = {p.stiffness, p.elements, p.seconds};
          } else {
            const ToothComplianceFe c =
                fe_tooth_compliance(d, which == 2 ? ToothMember::kPinion : ToothMember::kRack, s_p, o);
            v = {c.compliance, c.elements, c.seconds};
          }
          std::lock_guard<std::mutex> lock(mu);
          q[first + static_cast<std::size_t>(which)].at[li] = v;
          std::fprintf(stderr, "  level %d, quantity %d: %.6g (%d elements, %.1f s)\n", o.level, which, v.value,
                       v.elements, v.seconds);
        });
      }
    }
  }
  run_jobs(jobs, threads);

  std::printf("| problem | quantity | level | elements | value | wall s | error vs Richardson |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Quantity& x : q) {
    if (x.name.empty()) continue;
    std::vector<double> v;
    for (const LevelValue& l : x.at) v.push_back(l.value);
    // 7 printed digits in ccx's .dat: differences below ~1e-6 are not resolved.
    RichardsonEstimate e;
    bool have = v.size() >= 3;
    if (have) e = richardson(v, 2.0, 1e-6);
    const bool stiffness = x.name[0] == 'K';
    for (std::size_t li = 0; li < x.at.size(); ++li) {
      char err[32] = "–";
      if (have && !std::isnan(e.relative_error[li])) std::snprintf(err, sizeof err, "%.2e", e.relative_error[li]);
      std::printf("| %s | %s | %d | %d | %.6g %s | %.1f | %s |\n", x.problem.c_str(), x.name.c_str(), levels[li],
                  x.at[li].elements, stiffness ? x.at[li].value : x.at[li].value * 1e9,
                  stiffness ? "N/m" : "e-9 m/N", x.at[li].seconds, err);
    }
    if (have) {
      std::printf("| %s | %s | Richardson | | %.6g %s | | order %.2f, %s |\n", x.problem.c_str(), x.name.c_str(),
                  stiffness ? e.extrapolated : e.extrapolated * 1e9, stiffness ? "N/m" : "e-9 m/N", e.order,
                  to_string(e.status).c_str());
    }
  }
}

// ---- compare -----------------------------------------------------------------------

void compare_table(const std::vector<std::string>& problems, int positions, int level, int threads) {
  struct Row {
    std::string problem;
    std::vector<FePosition> fe;
    std::vector<MeshState> an;
    std::vector<ToothComplianceFe> pinion, rack;
    double analytic_s = 0;
    double pitch = 0;
  };
  std::vector<Row> rows(problems.size());
  std::vector<std::function<void()>> jobs;
  FeOptions o;
  o.level = level;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    Row& row = rows[i];
    const Drive d = load_problem(problem_path(problems[i]));
    const MeshStiffnessModel model(rigid_rack(d));
    row.problem = stem(problems[i]);
    row.pitch = M_PI * d.pinion.module;
    row.analytic_s = analytic_seconds_per_position(model, row.pitch);
    row.fe.resize(static_cast<std::size_t>(positions));
    for (int k = 0; k < positions; ++k) {
      // Offset by a quarter step so no position sits on a pair's entry or exit.
      const double X = row.pitch * (1 + (k + 0.25) / positions);
      row.an.push_back(model.at(X));
      jobs.push_back([&row, d, o, X, k] { row.fe[static_cast<std::size_t>(k)] = fe_mesh_position(d, X, o); });
    }
    const ContactPath& path = model.geometry().path;
    const double span = path.s_end - path.s_start;
    const std::vector<double> s_list = {path.s_start + 0.02 * span, path.s_pitch, path.s_end - 0.02 * span};
    row.pinion.resize(s_list.size());
    row.rack.resize(s_list.size());
    for (std::size_t k = 0; k < s_list.size(); ++k) {
      const double s = std::max(s_list[k], 1e-3 * span);
      jobs.push_back([&row, d, o, s, k] { row.pinion[k] = fe_tooth_compliance(d, ToothMember::kPinion, s, o); });
      jobs.push_back([&row, d, o, s, k] { row.rack[k] = fe_tooth_compliance(d, ToothMember::kRack, s, o); });
    }
  }
  run_jobs(jobs, threads);

  std::printf("Per position (level %d; K error = (K_an - K_FE) / K_FE; shares: FE / analytic, nearest the pinion "
              "tip first):\n\n",
              level);
  std::printf("| problem | X / p | pairs | K_FE [N/m] | K_an [N/m] | K error | shares FE | shares analytic | "
              "F2 / load.force | ccx runs | elements | wall s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    for (std::size_t k = 0; k < r.fe.size(); ++k) {
      const FePosition& f = r.fe[k];
      const MeshState& a = r.an[k];
      std::string sf, sa;
      char b[32];
      for (const FePair& p : f.pairs) {
        std::snprintf(b, sizeof b, "%s%.3f", sf.empty() ? "" : " / ", p.load_share);
        sf += b;
      }
      for (const PairState& p : a.pairs) {
        std::snprintf(b, sizeof b, "%s%.3f", sa.empty() ? "" : " / ", p.load_share);
        sa += b;
      }
      std::printf("| %s | %.3f | %zu | %.4g | %.4g | %+.3f | %s | %s | %.3f | %d | %d | %.1f |\n", r.problem.c_str(),
                  f.travel / r.pitch - 1, f.pairs.size(), f.stiffness, a.stiffness,
                  a.stiffness / f.stiffness - 1, sf.c_str(), sa.c_str(), f.load_fraction, f.ccx_runs, f.elements,
                  f.seconds);
    }
  }

  std::printf("\nSummary (errors of the analytic model against FE, level %d):\n\n", level);
  std::printf("| problem | positions | K error max | K error mean | K_an mean / K_FE mean | share error max | "
              "pinion compliance an/FE | rack compliance an/FE | F2 / load.force | FE s per position | "
              "analytic s per position | FE / analytic time |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    double emax = 0, esum = 0, kf = 0, ka = 0, smax = 0, fmin = INFINITY, fmax = 0, tsum = 0;
    for (std::size_t k = 0; k < r.fe.size(); ++k) {
      const FePosition& f = r.fe[k];
      const MeshState& a = r.an[k];
      const double e = a.stiffness / f.stiffness - 1;
      if (std::abs(e) > std::abs(emax)) emax = e;
      esum += e;
      kf += f.stiffness;
      ka += a.stiffness;
      if (f.pairs.size() == a.pairs.size()) {
        for (std::size_t j = 0; j < f.pairs.size(); ++j) {
          smax = std::max(smax, std::abs(a.pairs[j].load_share - f.pairs[j].load_share));
        }
      }
      fmin = std::min(fmin, f.load_fraction);
      fmax = std::max(fmax, f.load_fraction);
      tsum += f.seconds;
    }
    const auto range = [](const std::vector<ToothComplianceFe>& v) {
      double lo = INFINITY, hi = 0;
      for (const auto& c : v) {
        lo = std::min(lo, c.analytic / c.compliance);
        hi = std::max(hi, c.analytic / c.compliance);
      }
      char b[32];
      std::snprintf(b, sizeof b, "%.3f–%.3f", lo, hi);
      return std::string(b);
    };
    const double n = static_cast<double>(r.fe.size());
    std::printf("| %s | %zu | %+.3f | %+.3f | %.3f | %.3f | %s | %s | %.2f–%.2f | %.1f | %.2e | %.1e |\n",
                r.problem.c_str(), r.fe.size(), emax, esum / n, ka / kf, smax, range(r.pinion).c_str(),
                range(r.rack).c_str(), fmin, fmax, tsum / n, r.analytic_s, tsum / n / r.analytic_s);
  }

  std::printf("\nSingle-tooth compliances (level %d, e-9 m/N for the face width; contacts at 2 %% of the path from "
              "its start, the pitch point, 2 %% from its end):\n\n",
              level);
  std::printf("| problem | member | s [mm] | FE | analytic | analytic / FE | elements | wall s |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    for (const auto* v : {&r.pinion, &r.rack}) {
      for (const ToothComplianceFe& c : *v) {
        std::printf("| %s | %s | %.2f | %.4g | %.4g | %.3f | %d | %.1f |\n", r.problem.c_str(),
                    c.member == ToothMember::kPinion ? "pinion" : "rack", c.s * 1e3, c.compliance * 1e9,
                    c.analytic * 1e9, c.analytic / c.compliance, c.elements, c.seconds);
      }
    }
  }
}

// ---- window ------------------------------------------------------------------------

void window_table(const std::vector<std::string>& problems, int level, int threads) {
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
    jobs.push_back([&r, level] {
      FeOptions o;
      o.level = level;
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
      else throw std::invalid_argument("unknown option " + k + " (see the comment at the top of bench/fe_accuracy.cpp)");
    }
    if (a.positions < 1 || a.threads < 1 || a.levels.empty()) throw std::invalid_argument("bad --positions/--threads/--levels");
    const std::vector<std::string> two = {"gantry_axis", "rack_railway"};
    const auto start = std::chrono::steady_clock::now();
    if (a.table == "levels" || a.table == "all") {
      std::printf("### FE levels: discretisation error and cost\n\n");
      levels_table(a.problems.empty() ? two : a.problems, a.levels, a.threads);
      std::printf("\n");
    }
    if (a.table == "window" || a.table == "all") {
      std::printf("### Load window of the secant K (level %d)\n\n", a.levels.front());
      window_table(a.problems.empty() ? two : a.problems, a.levels.front(), a.threads);
      std::printf("\n");
    }
    if (a.table == "compare" || a.table == "all") {
      std::printf("### Analytic model against FE\n\n");
      compare_table(a.problems.empty() ? all_problems() : a.problems, a.positions, a.levels.front(), a.threads);
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
