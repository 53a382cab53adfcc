// Hypervolume against evaluations for each front method on the shipped
// Pareto studies; prints the Markdown table of docs/accuracy.md ("Pareto
// fronts: hypervolume against evaluations").
//
//   ./build/front_methods            both studies (about 2 min on one core)
//   ./build/front_methods 3          studies/ship_lift_wear_tradeoff.yaml only
//   ./build/front_methods 4          studies/ship_lift_four_objectives.yaml only
//
// Every method of a study is measured in ONE box, so that the numbers
// compare: from the best value of each objective over every feasible design
// any method evaluated to a reference point 10 % of the range beyond the
// worst value over the union of the methods' fronts. The hypervolume after
// k evaluations is that of every feasible design evaluated so far (the
// record of the run, read back from its evaluation store), a fraction of the
// box; the "front" column is the delivered front's own.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/solvers/front_quality.hpp"
#include "rackopt/solvers/pareto.hpp"
#include "rackopt/study/study_problem.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace {

using namespace rackopt;

struct Method {
  std::string name;
  std::vector<std::string> overrides;
};

struct Run {
  std::string method;
  std::size_t evaluations = 0;
  double seconds = 0;
  std::vector<std::vector<double>> feasible_in_order;  // minimized own units
  std::vector<std::size_t> feasible_row;                // its 0-based row in the record
  std::vector<std::vector<double>> front;               // minimized own units
};

std::vector<double> minimized(const study::StudySpec& spec, const std::vector<std::pair<std::string, double>>& m) {
  std::vector<double> v;
  for (const auto& o : spec.objectives)
    for (const auto& [label, value] : m)
      if (label == o.label) v.push_back(o.maximize ? -value : value);
  return v;
}

Run run(const std::string& study_file, const Method& method) {
  const study::StudySpec spec = studyfile::load_study_file(study_file, method.overrides);
  const std::string out = (std::filesystem::temp_directory_path() / ("rackopt_front_methods_" + method.name)).string();
  std::filesystem::remove_all(out);
  study::RunOptions options;
  options.out_dir = out;
  options.threads = 1;
  const auto t0 = std::chrono::steady_clock::now();
  const study::StudyResult r = study::run_study(spec, options);
  Run result;
  result.method = method.name;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.evaluations = r.evaluations;
  study::StudyProblem p(spec);
  auto store = record::EvaluationStore::open(r.database_path, study::study_fingerprint(spec), p.variable_keys(), true,
                                             {.fingerprint_format = study::kStudyFingerprintFormat});
  const std::vector<record::RecordedEvaluation> rows = store.all();
  for (std::size_t row = 0; row < rows.size(); ++row) {
    const record::RecordedEvaluation& e = rows[row];
    bool feasible = e.ok;
    for (double g : e.inequality) feasible = feasible && g <= spec.solver.constraint_tolerance;
    for (double h : e.equality) feasible = feasible && std::abs(h) <= spec.solver.constraint_tolerance;
    const std::vector<double> v = minimized(spec, e.metrics);
    if (feasible && v.size() == spec.objectives.size()) {
      result.feasible_in_order.push_back(v);
      result.feasible_row.push_back(row);
    }
  }
  for (const study::DesignResult& d : r.front) {
    std::vector<double> v;
    for (std::size_t i = 0; i < spec.objectives.size(); ++i)
      v.push_back(spec.objectives[i].maximize ? -d.objectives[i] : d.objectives[i]);
    result.front.push_back(v);
  }
  std::filesystem::remove_all(out);
  return result;
}

double fraction(const std::vector<std::vector<double>>& points, const std::vector<double>& ideal,
                const std::vector<double>& ref) {
  double box = 1;
  for (std::size_t k = 0; k < ref.size(); ++k) box *= ref[k] - ideal[k];
  return solvers::hypervolume(points, ref) / box;
}

void table(const std::string& title, const std::string& study_file, const std::vector<Method>& methods,
           const std::vector<std::size_t>& checkpoints) {
  std::vector<Run> runs;
  for (const Method& m : methods) {
    std::fprintf(stderr, "%s: %s ...\n", title.c_str(), m.name.c_str());
    runs.push_back(run(study_file, m));
  }
  const std::size_t n_obj = runs.front().front.empty() ? 0 : runs.front().front[0].size();
  std::vector<double> ideal(n_obj, std::numeric_limits<double>::infinity());
  std::vector<double> worst(n_obj, -std::numeric_limits<double>::infinity());
  for (const Run& r : runs) {
    for (const auto& v : r.feasible_in_order)
      for (std::size_t k = 0; k < n_obj; ++k) ideal[k] = std::min(ideal[k], v[k]);
    for (const auto& v : r.front)
      for (std::size_t k = 0; k < n_obj; ++k) worst[k] = std::max(worst[k], v[k]);
  }
  std::vector<double> ref(n_obj);
  for (std::size_t k = 0; k < n_obj; ++k) ref[k] = worst[k] + 0.1 * (worst[k] - ideal[k]);

  std::printf("\n%s\n\n| method | evaluations | wall s |", title.c_str());
  for (std::size_t c : checkpoints) std::printf(" HV after %zu |", c);
  std::printf(" HV, all evaluations | HV, delivered front (points) |\n|---|---|---|");
  for (std::size_t i = 0; i < checkpoints.size(); ++i) std::printf("---|");
  std::printf("---|---|\n");
  for (const Run& r : runs) {
    std::printf("| %s | %zu | %.1f |", r.method.c_str(), r.evaluations, r.seconds);
    for (std::size_t c : checkpoints) {
      if (c > r.evaluations) {
        std::printf(" – |");
        continue;
      }
      std::vector<std::vector<double>> first;
      for (std::size_t i = 0; i < r.feasible_in_order.size() && r.feasible_row[i] < c; ++i)
        first.push_back(r.feasible_in_order[i]);
      std::printf(" %.3f |", fraction(first, ideal, ref));
    }
    std::printf(" %.3f | %.3f (%zu) |\n", fraction(r.feasible_in_order, ideal, ref), fraction(r.front, ideal, ref),
                r.front.size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "all";
  const std::string studies = std::string(RACKOPT_SOURCE_DIR) + "/studies/";
  if (which == "all" || which == "3") {
    table("ship_lift_wear_tradeoff.yaml (3 objectives, 2 module values; 20 points)",
          studies + "ship_lift_wear_tradeoff.yaml",
          {{"eps_constraint (COBYLA, 40 per sub-problem)", {}},
           {"weighted_sum (COBYLA, 40 per sub-problem)", {"pareto.method=weighted_sum"}},
           {"nsga2 (population 24, the module as an integer, 1200 in one run)",
            {"solver.library=pagmo", "solver.algorithm=nsga2", "solver.max_evaluations=1200", "pareto.method=population"}},
           {"moead (population 24, 600 per module)",
            {"solver.library=pagmo", "solver.algorithm=moead", "solver.max_evaluations=600", "pareto.method=population"}}},
          {200, 400, 800, 1200});
  }
  if (which == "all" || which == "4") {
    table("ship_lift_four_objectives.yaml (4 objectives, 24 points)", studies + "ship_lift_four_objectives.yaml",
          {{"nsga2 (population 48, as shipped)", {}},
           {"moead (population 48)", {"solver.algorithm=moead"}},
           {"nsga2 (population 24)", {"solver.population=24"}}},
          {250, 500, 1000, 1500});
  }
  return 0;
}
