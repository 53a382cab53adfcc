// Explaining an optimum: a sizing problem whose cost is linear in the
// supports per metre (cost = ... + per_support x supports_per_metre), with a
// floor on supports per metre. At the optimum the floor binds, the span is
// inside its box, and the multiplier is exactly the support price: one more
// support per metre costs per_support per metre of rack.
#include "rackopt/study/optimum_explanation.hpp"

#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt::study {
namespace {

const std::string kStudy = R"(study: {name: explain, kind: optimize, seed: 1}
problem: gantry_axis.yaml
variables:
  pinion.module: {values: [4 mm, 5 mm]}
  rack.span: {lower: 0.25 m, upper: 2 m, start: 0.5 m}
objectives: [cost_per_metre]
constraints:
  - {metric: supports_per_metre, min: 1.25}
metric_options:
  cost: {rack_per_kg: 4, pinion_per_kg: 25, per_support: 15}
solver: {algorithm: LN_COBYLA, max_evaluations: 200, xtol_rel: 1e-8}
)";

TEST(OptimumExplanation, MultiplierOfALinearCostIsThePriceOfTheConstrainedQuantity) {
  const std::string problems = std::string(RACKOPT_SOURCE_DIR) + "/problems";
  const StudySpec spec = studyfile::load_study_text(kStudy, "explain.yaml", problems);
  RunOptions o;
  o.out_dir = test_support::scratch_path("explain");
  const StudyResult r = run_study(spec, o);
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  std::ifstream md_file(o.out_dir + "/report.md");
  const std::string md((std::istreambuf_iterator<char>(md_file)), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(o.out_dir);
  ASSERT_TRUE(r.best && r.best->feasible) << r.status;
  // The report explains the optimum (the runner computed it; the report only shows it).
  for (const char* section : {"### Why this optimum", "### Best design per combination", "## Fidelity settings",
                              "**active**", "No continuous variable is at a bound"})
    EXPECT_NE(md.find(section), std::string::npos) << section;
  for (const char* key : {"\"explanation\"", "\"per_combination\"", "\"fidelity\"", "\"bound_sensitivity\""})
    EXPECT_NE(rep.summary_json.find(key), std::string::npos) << key;
  EXPECT_NEAR(r.best->x[1], 0.8, 1e-5);  // span at the floor 1/1.25 m

  ASSERT_TRUE(r.explanation);
  const OptimumExplanation& e = *r.explanation;
  EXPECT_EQ(e.objective, "cost_per_metre");
  ASSERT_EQ(e.constraints.size(), 1u);
  const ConstraintStatus& c = e.constraints[0];
  EXPECT_TRUE(c.active);
  EXPECT_EQ(c.side, "min");
  ASSERT_TRUE(c.bound_sensitivity);
  // d cost*/d (supports per metre floor) = per_support, exactly for a cost
  // linear in 1/span (finite differences of 1/span: second-order error).
  EXPECT_NEAR(*c.bound_sensitivity, 15.0, 15.0 * 1e-3);
  EXPECT_LT(e.kkt_residual, 1e-6);
  ASSERT_EQ(e.gradient_variables.size(), 1u);
  EXPECT_EQ(e.gradient_variables[0], "rack.span");
  // d cost / d span = -15 / span^2 = -23.44 per metre at 0.8 m; central
  // differences with h = 1 % of the 1.75 m range err by about
  // h^2/6 x 90/span^4 = 0.011.
  ASSERT_TRUE(e.objective_gradient[0]);
  EXPECT_NEAR(*e.objective_gradient[0], -15.0 / (0.8 * 0.8), 0.02);
  EXPECT_FALSE(e.variables[1].at_lower || e.variables[1].at_upper);
  EXPECT_EQ(e.variables[1].difference, "central");

  // Both modules reported, the cheaper one is the optimum.
  ASSERT_EQ(r.per_combination.size(), 2u);
  EXPECT_EQ(r.per_combination[0].label, "pinion.module=4 mm");
  ASSERT_TRUE(r.per_combination[0].best && r.per_combination[1].best);
  const double c4 = r.per_combination[0].best->objectives[0], c5 = r.per_combination[1].best->objectives[0];
  EXPECT_EQ(r.best->objectives[0], std::min(c4, c5));
  EXPECT_NE(c4, c5);

  // Fidelity settings in effect.
  bool quadrature = false;
  for (const auto& [k, v] : r.fidelity) quadrature = quadrature || (k == "numerics.quadrature_order" && v == "16");
  EXPECT_TRUE(quadrature);
}

// A sweep's report ranks the variables by their Sobol indices.
TEST(OptimumExplanation, SweepReportRanksTheVariables) {
  std::string text = kStudy;
  text.replace(text.find("kind: optimize"), 14, "kind: sweep");
  text += "sweep: {method: grid, levels: 4}\n";
  const StudySpec spec = studyfile::load_study_text(text, "sweep.yaml", std::string(RACKOPT_SOURCE_DIR) + "/problems");
  RunOptions o;
  o.out_dir = test_support::scratch_path("explain_sweep");
  const StudyResult r = run_study(spec, o);
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  std::ifstream md_file(o.out_dir + "/report.md");
  const std::string md((std::istreambuf_iterator<char>(md_file)), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(o.out_dir);
  ASSERT_EQ(r.sweep_points.size(), 8u);
  EXPECT_NE(md.find("## Sensitivity over the design box"), std::string::npos);
  EXPECT_NE(rep.summary_json.find("\"sensitivity\""), std::string::npos);
  EXPECT_FALSE(r.explanation);  // only optimize studies are explained
}

}  // namespace
}  // namespace rackopt::study
