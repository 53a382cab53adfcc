// An optimum whose wear life is an active constraint reports that life's
// discretization error: the best design evaluated once more with twice the
// profile points (study/wear_discretization_check.hpp), in report.md and in
// summary.json's explanation.
#include "rackopt/study/wear_discretization_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/study/study_runner.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "rackopt/wear/wear_life.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt::study {
namespace {

// A lighter pinion needs a narrower face, which shortens the wear life: the
// life floor binds at the optimum (about 33 mm; 25 y at 40 mm is 30.6 y).
const std::string kStudy = R"(study: {name: wear floor, kind: optimize, seed: 1}
problem: gantry_axis.yaml
variables:
  pinion.face_width: {lower: 15 mm, upper: 60 mm, start: 40 mm}
objectives: [pinion_mass]
constraints:
  - {metric: wear_life, min: 25 yr}
solver: {algorithm: LN_COBYLA, max_evaluations: 80, xtol_rel: 1e-6}
)";

std::string read(const std::string& path) {
  std::ifstream f(path);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

TEST(WearDiscretizationReport, ActiveWearLifeCarriesOneRefinement) {
  const std::string problems = std::string(RACKOPT_SOURCE_DIR) + "/problems";
  const StudySpec spec = studyfile::load_study_text(kStudy, "wear_floor.yaml", problems);
  RunOptions o;
  o.out_dir = test_support::scratch_path("wear_discretization");
  const StudyResult r = run_study(spec, o);
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  const std::string md = read(o.out_dir + "/report.md");
  std::filesystem::remove_all(o.out_dir);
  ASSERT_TRUE(r.best && r.best->feasible) << r.status;
  ASSERT_TRUE(r.explanation);
  ASSERT_EQ(r.explanation->constraints.size(), 1u);
  const ConstraintStatus& c = r.explanation->constraints[0];
  ASSERT_TRUE(c.active);
  ASSERT_TRUE(c.discretization);
  const DiscretizationError& d = *c.discretization;
  const Drive best = load_problem(problems + "/gantry_axis.yaml",
                                  {"pinion.face_width=" + std::to_string(r.best->x[0] * 1e3) + " mm"});
  EXPECT_EQ(d.setting, "wear.profile_points");
  EXPECT_EQ(d.points, best.wear.profile_points);
  EXPECT_EQ(d.refined_points, 2 * best.wear.profile_points);
  // The refined value is the life of the same design with twice the points.
  Drive refined = best;
  refined.wear.profile_points = d.refined_points;
  const double life_s = WearModel(refined).life().life_years * kSecondsPerYear;
  EXPECT_NEAR(d.refined_value / life_s, 1.0, 1e-6);
  EXPECT_NEAR(d.relative_error, (c.value - d.refined_value) / d.refined_value, 1e-12);
  EXPECT_LT(std::abs(d.relative_error), 5e-3);  // the default is converged to 0.5 % (docs/accuracy.md)
  EXPECT_NE(md.find("discretization error"), std::string::npos) << md;
  EXPECT_NE(md.find("wear.profile_points " + std::to_string(d.points) + " -> " + std::to_string(d.refined_points)),
            std::string::npos);
  EXPECT_NE(rep.summary_json.find("\"discretization\""), std::string::npos);
  EXPECT_NE(rep.summary_json.find("\"relative_error\""), std::string::npos);
}

// Only wear lives are refined: an optimum bound by another metric has none.
TEST(WearDiscretizationReport, OtherActiveConstraintsHaveNone) {
  EXPECT_TRUE(is_wear_life_metric("wear_life_at_R"));
  EXPECT_TRUE(is_wear_life_metric("wear_life"));
  EXPECT_FALSE(is_wear_life_metric("contact_ratio"));
}

}  // namespace
}  // namespace rackopt::study
