// Study files -> StudySpec: the shipped studies load, units convert, and
// every rule of docs/studies.md refuses bad input at the right file:line:column.
#include "rackopt/studyfile/study_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "studyfile_test_support.hpp"
#include "support/input_error_expectations.hpp"
#include "support/text_position.hpp"

namespace rackopt::study {
namespace {

const std::string kSource = RACKOPT_SOURCE_DIR;
using test::kStudies;
using test::load;
constexpr double kPi = 3.14159265358979323846;

using test_support::position_of;

// Loads `text` expecting an InputError at file:line:column `where` whose key
// path is `key` and whose text contains every one of `parts`.
void expect_error(const std::string& text, const std::string& where, const std::string& key,
                  const std::vector<std::string>& parts, const std::vector<std::string>& overrides = {}) {
  test_support::expect_input_error([&] { (void)load(text, overrides); },
                                   {.mark = where, .key = key, .in_what = parts});
}

std::string t(const std::string& where) { return "t.yaml:" + where; }

const std::string kHead =
    "study: {kind: optimize}\n"
    "problem: ../problems/rack_railway.yaml\n";

// A valid optimize study; tests append or replace sections.
const std::string kOptimize = kHead +
                              "variables:\n"
                              "  pinion.pressure_angle: {lower: 17 deg, upper: 25 deg, start: 20 deg}\n"
                              "objectives: [stiffness_fluctuation]\n";

// ------------------------------------------------------------------ shipped

TEST(StudyLoader, ShippedStudiesLoad) {
  for (const char* name : {"rack_railway_sizing.yaml", "ship_lift_wear_tradeoff.yaml", "spall_severity_sweep.yaml",
                           "ship_lift_reliability.yaml", "ship_lift_four_objectives.yaml"}) {
    SCOPED_TRACE(name);
    StudySpec s;
    ASSERT_NO_THROW(s = studyfile::load_study_file(kStudies + "/" + name)) << name;
    EXPECT_FALSE(s.name.empty());
    EXPECT_FALSE(s.variables.empty());
    EXPECT_FALSE(s.all_metrics().empty());
  }
}

TEST(StudyLoader, RailwaySizingContent) {
  const StudySpec s = studyfile::load_study_file(kStudies + "/rack_railway_sizing.yaml");
  EXPECT_EQ(s.kind, StudyKind::kOptimize);
  ASSERT_EQ(s.objectives.size(), 1u);
  EXPECT_EQ(s.objectives[0].label, "stiffness_fluctuation");
  ASSERT_EQ(s.variables.size(), 4u);
  EXPECT_EQ(s.variables[0].key, "pinion.pressure_angle");
  EXPECT_DOUBLE_EQ(s.variables[0].lower, 17 * kPi / 180);
  EXPECT_TRUE(s.variables[1].discrete());
  // The problem file next to the study, whatever the current directory.
  EXPECT_EQ(s.problem_path, kSource + "/problems/rack_railway.yaml");
  EXPECT_EQ(s.solver.algorithm, "LN_COBYLA");
  EXPECT_FALSE(s.solver.central_differences);
}

TEST(StudyLoader, ShipLiftSwitchesTheRackToACaseHardenedProfile) {
  const StudySpec s = studyfile::load_study_file(kStudies + "/ship_lift_wear_tradeoff.yaml");
  EXPECT_EQ(s.kind, StudyKind::kPareto);
  ASSERT_EQ(s.objectives.size(), 3u);
  EXPECT_TRUE(s.objectives[0].maximize);
  EXPECT_EQ(s.objectives[0].label, "wear_life_at_R(0.9)");
  ASSERT_EQ(s.problem_overrides.size(), 1u);
  EXPECT_EQ(s.problem_overrides[0].rfind("wear.rack_hardness=", 0), 0u) << s.problem_overrides[0];
  EXPECT_EQ(s.variables[0].key, "wear.rack_hardness.case_depth");
  EXPECT_EQ(s.variables[0].unit, "mm");
  EXPECT_EQ(s.pareto.points, 20u);
  EXPECT_EQ(s.pareto.primary, 0u);
}

TEST(StudyLoader, SpallSweepDeclaresItsFault) {
  const StudySpec s = studyfile::load_study_file(kStudies + "/spall_severity_sweep.yaml");
  EXPECT_EQ(s.kind, StudyKind::kSweep);
  EXPECT_EQ(s.sweep.method, SweepSpec::Method::kGrid);
  ASSERT_EQ(s.variables.size(), 3u);
  EXPECT_EQ(s.variables[0].key, "faults[0].depth");
  EXPECT_DOUBLE_EQ(s.variables[0].lower, 0.5e-3);
  EXPECT_DOUBLE_EQ(s.variables[1].upper, 15e-3);
  EXPECT_EQ(s.variables[2].key, "faults[0].width");
  EXPECT_EQ(s.variables[2].levels, 4);
}

// -------------------------------------------------------------------- values

TEST(StudyLoader, UnitsAreConvertedToSI) {
  const std::string text = kOptimize + "constraints:\n  - {metric: min_stiffness_ks(200), min: 400 MN/m}\n"
                                       "  - {metric: contact_ratio, min: 1.3, max: 2}\n"
                                       "  - {metric: supports_per_metre, max: 0.5 1/m}\n"
                                       "  - {metric: mean_stiffness, equals: 2e8, scale: 10 MN/m}\n";
  const StudySpec s = load(text);
  const DesignVariable& v = s.variables.at(0);
  EXPECT_EQ(v.kind, QuantityKind::kAngle);
  EXPECT_EQ(v.unit, "deg");
  EXPECT_NEAR(v.lower, 17 * kPi / 180, 1e-15);
  EXPECT_NEAR(v.upper, 25 * kPi / 180, 1e-15);
  EXPECT_NEAR(*v.start, 20 * kPi / 180, 1e-15);
  ASSERT_EQ(s.constraints.size(), 4u);
  EXPECT_EQ(s.constraints[0].label, "min_stiffness_ks(200)");
  EXPECT_DOUBLE_EQ(*s.constraints[0].min, 4e8);
  EXPECT_FALSE(s.constraints[0].max.has_value());
  EXPECT_DOUBLE_EQ(*s.constraints[1].max, 2.0);
  EXPECT_DOUBLE_EQ(*s.constraints[2].max, 0.5);   // 1/m: the metric's own SI unit
  EXPECT_DOUBLE_EQ(*s.constraints[3].equals, 2e8);  // bare stiffness: N/m
  EXPECT_DOUBLE_EQ(s.constraints[3].scale, 1e7);
  // Defaults.
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.solver.library, "nlopt");
  EXPECT_EQ(s.solver.max_evaluations, 1000u);
  EXPECT_EQ(s.metric_options.reliability_seed, 1);
}

TEST(StudyLoader, ShorthandBoundsAndUnits) {
  const StudySpec s = load(kHead +
                           "variables:\n"
                           "  rack.span: [120 cm, 3 m]\n"
                           "  mounting.clearance: [1, 2 mm]\n"
                           "  pinion.profile_shift: [-0.2, 0.4]\n"
                           "objectives: [stiffness_fluctuation]\n");
  ASSERT_EQ(s.variables.size(), 3u);
  EXPECT_DOUBLE_EQ(s.variables[0].lower, 1.2);
  EXPECT_DOUBLE_EQ(s.variables[0].upper, 3.0);
  EXPECT_EQ(s.variables[0].unit, "cm");  // the unit of the lower bound
  EXPECT_FALSE(s.variables[0].start.has_value());
  EXPECT_DOUBLE_EQ(s.variables[1].lower, 1e-3);  // bare length: mm
  EXPECT_EQ(s.variables[1].unit, "mm");
  EXPECT_EQ(s.variables[2].kind, QuantityKind::kDimensionless);
  EXPECT_EQ(s.variables[2].unit, "");
}

TEST(StudyLoader, DiscreteValuesAreSortedAndDistinct) {
  const StudySpec s = load(kHead +
                           "variables:\n"
                           "  pinion.module: {values: [32 mm, 20 mm, 2.5 cm], start: 25 mm}\n"
                           "  pinion.teeth: {values: [18, 14, 16]}\n"
                           "objectives: [stiffness_fluctuation]\n");
  const DesignVariable& m = s.variables.at(0);
  ASSERT_TRUE(m.discrete());
  ASSERT_EQ(m.values.size(), 3u);
  EXPECT_DOUBLE_EQ(m.values[0], 0.020);
  EXPECT_DOUBLE_EQ(m.values[1], 0.025);
  EXPECT_DOUBLE_EQ(m.values[2], 0.032);
  EXPECT_DOUBLE_EQ(m.lower, 0.020);
  EXPECT_DOUBLE_EQ(m.upper, 0.032);
  EXPECT_EQ(*m.start, m.values[1]);
  EXPECT_EQ(m.unit, "mm");  // the first value as written
  const DesignVariable& z = s.variables.at(1);
  EXPECT_EQ(z.kind, QuantityKind::kCount);
  EXPECT_EQ(z.values, (std::vector<double>{14, 16, 18}));

  const std::string dup = kHead +
                          "variables:\n"
                          "  pinion.module: {values: [20 mm, 25 mm, 2 cm]}\n"
                          "objectives: [stiffness_fluctuation]\n";
  expect_error(dup, t(position_of(dup, "2 cm")), "variables.pinion.module.values[2]", {"listed twice"});
  const std::string fractional = kHead +
                                 "variables:\n"
                                 "  pinion.teeth: {values: [14, 16.5]}\n"
                                 "objectives: [stiffness_fluctuation]\n";
  expect_error(fractional, t(position_of(fractional, "16.5")), "variables.pinion.teeth.values[1]", {"whole"});
  const std::string count_range = kHead +
                                  "variables:\n"
                                  "  pinion.teeth: [14, 18]\n"
                                  "objectives: [stiffness_fluctuation]\n";
  expect_error(count_range, t(position_of(count_range, "14")), "variables.pinion.teeth", {"values: [14, 18]"});
}

TEST(StudyLoader, EvaluateTakesStartsOrSingleValues) {
  const StudySpec s = load("study: {kind: evaluate}\n"
                           "problem: ../problems/rack_railway.yaml\n"
                           "variables:\n"
                           "  pinion.module: {values: [25 mm]}\n"
                           "  rack.span: {lower: 1 m, upper: 3 m, start: 2 m}\n"
                           "report: [contact_ratio]\n");
  EXPECT_DOUBLE_EQ(*s.variables[0].start, 0.025);
  EXPECT_DOUBLE_EQ(*s.variables[1].start, 2.0);
  // No variables at all: the problem's own design.
  EXPECT_NO_THROW(load("study: {kind: evaluate}\nproblem: ../problems/rack_railway.yaml\n"));

  const std::string no_start = "study: {kind: evaluate}\n"
                               "problem: ../problems/rack_railway.yaml\n"
                               "variables:\n"
                               "  rack.span: [1 m, 3 m]\n";
  expect_error(no_start, t(position_of(no_start, "rack.span")), "variables.rack.span", {"start"});
}

TEST(StudyLoader, SolverSettings) {
  const StudySpec s = load(kOptimize +
                           "solver: {library: ipopt, max_evaluations: 50, max_time: 2 min, starts: 3, "
                           "xtol_rel: 1e-4, gradient_step: 1e-5, ipopt_tol: 1e-7, ipopt_max_iterations: 100}\n");
  EXPECT_EQ(s.solver.library, "ipopt");
  EXPECT_TRUE(s.solver.central_differences);  // Ipopt's default
  EXPECT_EQ(s.solver.max_evaluations, 50u);
  EXPECT_DOUBLE_EQ(s.solver.max_seconds, 120.0);
  EXPECT_EQ(s.solver.starts, 3);
  EXPECT_DOUBLE_EQ(s.solver.xtol_rel, 1e-4);
  EXPECT_DOUBLE_EQ(s.solver.gradient_step, 1e-5);
  EXPECT_DOUBLE_EQ(s.solver.options.at("ipopt_tol"), 1e-7);
  EXPECT_EQ(s.solver.options.at("ipopt_max_iterations"), 100);

  EXPECT_FALSE(load(kOptimize + "solver: {library: nlopt, algorithm: LD_SLSQP}\n").solver.central_differences);
  EXPECT_FALSE(load(kOptimize + "solver: {library: ipopt, gradients: forward}\n").solver.central_differences);
  EXPECT_TRUE(load(kOptimize + "solver: {algorithm: LD_MMA, gradients: central}\n").solver.central_differences);
  // A bare max_time is seconds (not the time kind's default years).
  EXPECT_DOUBLE_EQ(load(kOptimize + "solver: {max_time: 30}\n").solver.max_seconds, 30.0);
}

TEST(StudyLoader, EachLibraryReadsItsOwnSettings) {
  const StudySpec s = load(kOptimize + "solver: {library: pagmo, algorithm: SADE, population: 30, max_evaluations: 600}\n");
  EXPECT_EQ(s.solver.library, "pagmo");
  EXPECT_EQ(s.solver.options.at("population"), 30);
  EXPECT_EQ(s.solver.options.count("stall_generations"), 0u);  // left out: the library's default
  // Without an algorithm a library takes its own default.
  EXPECT_EQ(load(kOptimize + "solver: {library: pagmo, algorithm: cmaes}\n").solver.algorithm, "cmaes");

  const std::string other = kOptimize + "solver: {library: nlopt, population: 30}\n";
  expect_error(other, t(position_of(other, "population")), "solver.population",
               {"setting of library pagmo, not of nlopt", "no settings of its own"});
  const std::string range = kOptimize + "solver: {library: pagmo, algorithm: sade, population: -4}\n";
  expect_error(range, t(position_of(range, "-4")), "solver.population", {"out of range"});
  // What only the algorithm can judge is reported at the setting it concerns.
  const std::string multiple = kOptimize + "solver: {library: pagmo, algorithm: cmaes, population: 3}\n";
  expect_error(multiple, t(position_of(multiple, "3}")), "solver.population", {"at least 5"});
}

TEST(StudyLoader, ParetoMethodFollowsTheSolversFrontAlgorithm) {
  const std::string pareto = "study: {kind: pareto}\n"
                             "problem: ../problems/rack_railway.yaml\n"
                             "variables:\n"
                             "  pinion.pressure_angle: {lower: 17 deg, upper: 25 deg, start: 20 deg}\n"
                             "objectives: [stiffness_fluctuation, supports_per_metre]\n";
  EXPECT_EQ(load(pareto + "solver: {library: pagmo, algorithm: nsga2, max_evaluations: 2000}\n").pareto.method,
            solvers::Scalarization::kPopulation);
  EXPECT_EQ(load(pareto).pareto.method, solvers::Scalarization::kEpsilonConstraint);
  const std::string mismatch = pareto + "pareto: {method: population}\nsolver: {algorithm: LN_COBYLA}\n";
  expect_error(mismatch, t(position_of(mismatch, "population}")), "pareto.method", {"finds whole fronts", "eps_constraint"});
  const std::string eps = pareto + "pareto: {method: eps_constraint}\nsolver: {library: pagmo, algorithm: moead}\n";
  expect_error(eps, t(position_of(eps, "eps_constraint}")), "pareto.method", {"finds whole Pareto fronts"});
  const std::string optimize = kOptimize + "solver: {library: pagmo, algorithm: nsga2}\n";
  expect_error(optimize, t(position_of(optimize, "nsga2")), "solver.algorithm", {"one-objective algorithm"});
}

TEST(StudyLoader, SeedDrivesEveryRandomChoice) {
  const StudySpec s = load("study: {kind: optimize, seed: 42}\n"
                           "problem: ../problems/rack_railway.yaml\n"
                           "variables: {rack.span: [1 m, 3 m]}\n"
                           "objectives: [stiffness_fluctuation]\n");
  EXPECT_EQ(s.seed, 42u);
  EXPECT_EQ(s.solver.seed, 42u);
  EXPECT_EQ(s.pareto.solver.seed, 42u);
  EXPECT_EQ(s.metric_options.reliability_seed, 42);
  const std::string bad = "study: {kind: optimize, seed: -1}\nproblem: ../problems/rack_railway.yaml\n";
  expect_error(bad, t(position_of(bad, "-1")), "study.seed", {"whole number >= 0"});
}

TEST(StudyLoader, MetricSamplingIsTheMetricsOwn) {
  const std::string head = std::string(kOptimize);
  EXPECT_FALSE(load(head).metric_options.positions_per_period);
  const StudySpec s = load(head + "metric_options: {positions_per_period: 24}\n");
  EXPECT_EQ(s.metric_options.positions_per_period, 24);
  const std::string few = head + "metric_options: {positions_per_period: 3}\n";
  expect_error(few, t(position_of(few, "3}")), "metric_options.positions_per_period", {"4", "10000"});
  const std::string frac = head + "metric_options: {positions_per_period: 24.5}\n";
  expect_error(frac, t(position_of(frac, "24.5")), "metric_options.positions_per_period", {"whole number"});
}

// ------------------------------------------------------------------- errors

TEST(StudyLoaderErrors, RequiredKeys) {
  expect_error("problem: ../problems/rack_railway.yaml\n", t("1:1"), "study", {"required key 'study'"});
  const std::string no_kind = "study: {name: x}\nproblem: ../problems/rack_railway.yaml\n";
  expect_error(no_kind, t(position_of(no_kind, "{name")), "study.kind", {"required key 'kind'", "optimize"});
  expect_error("study: {kind: evaluate}\n", t("1:1"), "problem", {"required key 'problem'"});
  const std::string missing_file = "study: {kind: evaluate}\nproblem: ../problems/nothing_here.yaml\n";
  expect_error(missing_file, t(position_of(missing_file, "../problems/nothing")), "problem",
               {"cannot open the problem file", "nothing_here.yaml"});
  const std::string no_metric = kOptimize + "constraints:\n  - {min: 1.3}\n";
  expect_error(no_metric, t(position_of(no_metric, "{min")), "constraints[0].metric", {"required key 'metric'"});
}

TEST(StudyLoaderErrors, UnknownKeysEverywhere) {
  const std::string top = kOptimize + "solverr: {max_evaluations: 10}\n";
  expect_error(top, t(position_of(top, "solverr")), "solverr", {"unknown key 'solverr'", "did you mean 'solver'"});
  const std::string solver = kOptimize + "solver: {max_evals: 10}\n";
  expect_error(solver, t(position_of(solver, "max_evals")), "solver.max_evals",
               {"did you mean 'max_evaluations'"});
  const std::string variable = kHead +
                               "variables:\n"
                               "  rack.span: {lower: 1 m, uper: 3 m}\n"
                               "objectives: [stiffness_fluctuation]\n";
  expect_error(variable, t(position_of(variable, "uper")), "variables.rack.span.uper", {"did you mean 'upper'"});
  const std::string objective = kHead + "variables: {rack.span: [1 m, 3 m]}\n"
                                        "objectives: [{metric: stiffness_fluctuation, sens: maximize}]\n";
  expect_error(objective, t(position_of(objective, "sens:")), "objectives[0].sens", {"did you mean 'sense'"});
  const std::string kind = "study: {kind: optimise}\nproblem: ../problems/rack_railway.yaml\n";
  expect_error(kind, t(position_of(kind, "optimise")), "study.kind",
               {"evaluate | sweep | optimize | pareto | reliability", "did you mean 'optimize'"});
  const std::string sense = kHead + "variables: {rack.span: [1 m, 3 m]}\n"
                                    "objectives: [{metric: stiffness_fluctuation, sense: max}]\n";
  expect_error(sense, t(position_of(sense, "max}")), "objectives[0].sense", {"minimize | maximize"});
  const std::string sw = kOptimize + "output: {plots: maybe}\n";
  expect_error(sw, t(position_of(sw, "maybe")), "output.plots", {"not a switch"});
}

TEST(StudyLoaderErrors, KindNeeds) {
  const std::string two = kHead + "variables: {rack.span: [1 m, 3 m]}\n"
                                  "objectives: [stiffness_fluctuation, contact_ratio]\n";
  expect_error(two, t(position_of(two, "objectives")), "objectives", {"exactly one objective", "kind: pareto"});
  const std::string none = kHead + "objectives: [stiffness_fluctuation]\n";
  expect_error(none, t(position_of(none, "optimize")), "study.kind", {"at least one design variable"});
  const std::string pareto1 = "study: {kind: pareto}\nproblem: ../problems/rack_railway.yaml\n"
                              "variables: {rack.span: [1 m, 3 m]}\n"
                              "objectives: [stiffness_fluctuation]\n";
  expect_error(pareto1, t(position_of(pareto1, "objectives")), "objectives", {"2 or 3 objectives"});
  const std::string pareto4 = "study: {kind: pareto}\nproblem: ../problems/rack_railway.yaml\n"
                              "variables: {rack.span: [1 m, 3 m]}\n"
                              "objectives: [stiffness_fluctuation, contact_ratio, mean_stiffness, min_stiffness]\n";
  expect_error(pareto4, t(position_of(pareto4, "objectives")), "objectives", {"found 4"});
  const std::string sweep = "study: {kind: sweep}\nproblem: ../problems/rack_railway.yaml\nreport: [contact_ratio]\n";
  expect_error(sweep, t(position_of(sweep, "sweep")), "study.kind", {"at least one design variable"});
  // The railway problem has no wear section: a reliability study cannot run.
  const std::string rel = "study: {kind: reliability}\nproblem: ../problems/rack_railway.yaml\n";
  expect_error(rel, t(position_of(rel, "reliability}")), "study.kind", {"wear section"});
  const StudySpec ok = load("study: {kind: reliability}\nproblem: ../problems/ship_lift.yaml\n");
  EXPECT_EQ(ok.kind, StudyKind::kReliability);
}

TEST(StudyLoaderErrors, Bounds) {
  const std::string reversed = kHead + "variables:\n  rack.span: {lower: 3 m, upper: 1.2 m}\n"
                                       "objectives: [stiffness_fluctuation]\n";
  expect_error(reversed, t(position_of(reversed, "1.2 m")), "variables.rack.span.upper", {"must be below"});
  const std::string equal = kHead + "variables:\n  rack.span: [2 m, 200 cm]\n"
                                    "objectives: [stiffness_fluctuation]\n";
  expect_error(equal, t(position_of(equal, "200 cm")), "variables.rack.span[1]", {"must be below"});
  const std::string outside = kHead + "variables:\n  rack.span: {lower: 1 m, upper: 2 m, start: 2.5 m}\n"
                                      "objectives: [stiffness_fluctuation]\n";
  expect_error(outside, t(position_of(outside, "2.5 m")), "variables.rack.span.start", {"outside the bounds"});
  const std::string member = kHead + "variables:\n  pinion.module: {values: [20 mm, 25 mm], start: 22 mm}\n"
                                     "objectives: [stiffness_fluctuation]\n";
  expect_error(member, t(position_of(member, "22 mm")), "variables.pinion.module.start", {"not one of the values"});
  const std::string both = kHead + "variables:\n  pinion.module: {values: [20 mm], lower: 10 mm}\n"
                                   "objectives: [stiffness_fluctuation]\n";
  expect_error(both, t(position_of(both, "lower")), "variables.pinion.module.lower", {"not both"});
  const std::string unit = kHead + "variables:\n  pinion.pressure_angle: [14 mm, 25 deg]\n"
                                   "objectives: [stiffness_fluctuation]\n";
  expect_error(unit, t(position_of(unit, "14 mm")), "variables.pinion.pressure_angle[0]", {"deg"});
  // The problem's own range (5 .. 45 deg) applies to every bound.
  const std::string range = kHead + "variables:\n  pinion.pressure_angle: [14 deg, 60 deg]\n"
                                    "objectives: [stiffness_fluctuation]\n";
  expect_error(range, t(position_of(range, "60 deg")), "variables.pinion.pressure_angle[1]",
               {"refused by the problem", "45 deg"});
}

TEST(StudyLoaderErrors, VariableKeyMustBeNumeric) {
  const std::string text = kHead + "variables:\n  rack.material: [1, 2]\nobjectives: [stiffness_fluctuation]\n";
  expect_error(text, t(position_of(text, "rack.material")), "variables.rack.material",
               {"not a numeric problem key", "pinion.module", "rack.span"});
  const std::string typo = kHead + "variables:\n  pinion.modul: [20 mm, 30 mm]\nobjectives: [stiffness_fluctuation]\n";
  expect_error(typo, t(position_of(typo, "pinion.modul")), "variables.pinion.modul",
               {"did you mean 'pinion.module'"});
  const std::string dup = kHead + "variables:\n  rack.span: [1 m, 2 m]\n  rack.span: [1 m, 3 m]\n"
                                  "objectives: [stiffness_fluctuation]\n";
  expect_error(dup, t(position_of(dup, "rack.span", 1)), "variables.rack.span", {"duplicate"});
}

// A design variable or a problem override that moves the design value of a
// random input given as an absolute distribution: the life at R would ignore
// it, so the study is refused naming both keys. Around the design (the
// shipped form) the same variable is fine.
TEST(StudyLoaderErrors, AbsoluteRandomInputMovedByTheStudy) {
  const std::string head = "study: {kind: sweep}\nproblem: ../problems/ship_lift.yaml\n"
                           "report: [wear_life_at_R(0.9)]\n";
  const std::string absolute = "problem_set:\n  reliability.random[0]: {input: contact_ratio, distribution: normal, "
                               "absolute: true, mean: 1.44, sd: 0.038}\n";
  const std::string variable = head + absolute + "variables:\n  mounting.clearance: [0 mm, 6 mm]\n";
  expect_error(variable, t(position_of(variable, "mounting.clearance")), "variables.mounting.clearance",
               {"contact_ratio", "reliability.random[0]", "absolute"});
  const std::string set = head + absolute + "  mounting.clearance: 4 mm\nvariables:\n  rack.span: [1 m, 2 m]\n";
  expect_error(set, t(position_of(set, "mounting.clearance")), "problem_set.mounting.clearance",
               {"contact_ratio", "reliability.random[0]"});
  const std::string cli = head + absolute + "variables:\n  rack.span: [1 m, 2 m]\n";
  try {
    (void)load(cli, {"problem.pinion.profile_shift=0.4"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "problem.pinion.profile_shift") << e.what();
    EXPECT_NE(std::string(e.what()).find("reliability.random[0]"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW((void)load(cli));
  EXPECT_NO_THROW((void)load(head + "variables:\n  mounting.clearance: [0 mm, 6 mm]\n"));
}

TEST(StudyLoaderErrors, Metrics) {
  const std::string unknown = kHead + "variables: {rack.span: [1 m, 3 m]}\n"
                                      "objectives: [stiffnes_fluctuation]\n";
  expect_error(unknown, t(position_of(unknown, "stiffnes_")), "objectives[0]",
               {"did you mean 'stiffness_fluctuation'"});
  const std::string param = kOptimize + "report: [wear_life_at_R(1.5)]\n";
  expect_error(param, t(position_of(param, "wear_life_at_R")), "report[0]", {"R"});
  // A wear metric on a problem without a wear section: named at the metric.
  const std::string wear = kOptimize + "constraints:\n  - {metric: wear_life, min: 20 yr}\n";
  expect_error(wear, t(position_of(wear, "wear_life,")), "constraints[0].metric",
               {"wear_life cannot be computed", "wear.coefficient"});
  const std::string twice = kHead + "variables: {rack.span: [1 m, 3 m]}\n"
                                    "objectives: [contact_ratio, {metric: contact_ratio, sense: maximize}]\n";
  expect_error(twice, t(position_of(twice, "contact_ratio", 1)), "objectives[1].metric", {"listed twice"});
}

TEST(StudyLoaderErrors, ConstraintBounds) {
  const std::string none = kOptimize + "constraints:\n  - {metric: contact_ratio}\n";
  expect_error(none, t(position_of(none, "{metric: contact")), "constraints[0]", {"at least one bound"});
  const std::string eq = kOptimize + "constraints:\n  - {metric: contact_ratio, equals: 1.5, max: 2}\n";
  expect_error(eq, t(position_of(eq, "max:")), "constraints[0].max", {"equals excludes min and max"});
  const std::string order = kOptimize + "constraints:\n  - {metric: contact_ratio, min: 2, max: 1.5}\n";
  expect_error(order, t(position_of(order, "1.5}")), "constraints[0].max", {"must be below max"});
  const std::string unit = kOptimize + "constraints:\n  - {metric: min_stiffness, min: 400 mm}\n";
  expect_error(unit, t(position_of(unit, "400 mm")), "constraints[0].min", {"MN/m"});
  const std::string per_metre = kOptimize + "constraints:\n  - {metric: supports_per_metre, max: 0.5 m}\n";
  expect_error(per_metre, t(position_of(per_metre, "0.5 m")), "constraints[0].max", {"1/m"});
  const std::string scale = kOptimize + "constraints:\n  - {metric: contact_ratio, min: 1.3, scale: 0}\n";
  expect_error(scale, t(position_of(scale, "0}")), "constraints[0].scale", {"scale > 0"});
}

TEST(StudyLoaderErrors, SolverCombinationsAreRefusedWithAHint) {
  const std::string bobyqa = kOptimize + "constraints:\n  - {metric: contact_ratio, min: 1.3}\n"
                                         "solver: {algorithm: LN_BOBYQA}\n";
  expect_error(bobyqa, t(position_of(bobyqa, "LN_BOBYQA")), "solver.algorithm",
               {"LN_BOBYQA cannot handle", "LN_COBYLA"});
  // Without constraints BOBYQA is fine.
  EXPECT_NO_THROW(load(kOptimize + "solver: {algorithm: LN_BOBYQA}\n"));
  // Equality constraints count as equalities.
  const std::string mma = kOptimize + "constraints:\n  - {metric: contact_ratio, equals: 1.5}\n"
                                      "solver: {algorithm: LD_MMA}\n";
  expect_error(mma, t(position_of(mma, "LD_MMA")), "solver.algorithm", {"equality"});
  const std::string unknown = kOptimize + "solver: {algorithm: LN_COBYLAA}\n";
  expect_error(unknown, t(position_of(unknown, "LN_COBYLAA")), "solver.algorithm", {"unknown NLopt algorithm"});
  const std::string local = kOptimize + "solver: {algorithm: LN_COBYLA, local_algorithm: LN_BOBYQA}\n";
  expect_error(local, t(position_of(local, "LN_BOBYQA")), "solver.local_algorithm", {"only used by AUGLAG"});
  const std::string budget = kOptimize + "solver: {max_evaluations: 0}\n";
  expect_error(budget, t(position_of(budget, "0}")), "solver.max_evaluations", {"1 <= max_evaluations"});
  const std::string lib = kOptimize + "solver: {library: scipy}\n";
  expect_error(lib, t(position_of(lib, "scipy")), "solver.library", {"nlopt | ipopt"});
}

TEST(StudyLoaderErrors, Pareto) {
  const std::string base = "study: {kind: pareto}\nproblem: ../problems/rack_railway.yaml\n"
                           "variables: {rack.span: [1 m, 3 m]}\n"
                           "objectives: [stiffness_fluctuation, supports_per_metre]\n";
  const StudySpec s = load(base + "pareto: {primary: supports_per_metre, points: 9, choose_weights: [1, 0]}\n");
  EXPECT_EQ(s.pareto.primary, 1u);
  EXPECT_EQ(s.pareto.points, 9u);
  EXPECT_EQ(s.choose_weights, (std::vector<double>{1, 0}));
  EXPECT_EQ(load(base + "pareto: {primary: 1}\n").pareto.primary, 1u);

  const std::string primary = base + "pareto: {primary: 2}\n";
  expect_error(primary, t(position_of(primary, "2}")), "pareto.primary",
               {"not one of the objectives", "0 = stiffness_fluctuation", "1 = supports_per_metre"});
  const std::string label = base + "pareto: {primary: contact_ratio}\n";
  expect_error(label, t(position_of(label, "contact_ratio}")), "pareto.primary", {"not one of the objectives"});
  const std::string length = base + "pareto: {choose_weights: [1, 1, 1]}\n";
  expect_error(length, t(position_of(length, "[1, 1, 1]")), "pareto.choose_weights", {"3 weights for 2 objectives"});
  const std::string negative = base + "pareto: {choose_weights: [1, -1]}\n";
  expect_error(negative, t(position_of(negative, "-1")), "pareto.choose_weights[1]", {"weight >= 0"});
  const std::string zero = base + "pareto: {choose_weights: [0, 0]}\n";
  expect_error(zero, t(position_of(zero, "[0, 0]")), "pareto.choose_weights", {"every weight is 0"});
  // eps-constraint bounds the other objectives: BOBYQA cannot take that...
  const std::string eps = base + "solver: {algorithm: LN_BOBYQA}\npareto: {method: eps_constraint}\n";
  expect_error(eps, t(position_of(eps, "eps_constraint")), "pareto.method",
               {"eps_constraint", "weighted_sum", "LN_COBYLA"});
  const std::string eps_default = base + "solver: {algorithm: LN_BOBYQA}\n";
  expect_error(eps_default, t(position_of(eps_default, "LN_BOBYQA")), "solver.algorithm", {"weighted_sum"});
  // ...but a weighted sum is unconstrained.
  EXPECT_NO_THROW(load(base + "solver: {algorithm: LN_BOBYQA}\npareto: {method: weighted_sum}\n"));
}

TEST(StudyLoaderErrors, SizeLimits) {
  const std::string sweep = "study: {kind: sweep}\nproblem: ../problems/rack_railway.yaml\n"
                            "variables:\n"
                            "  rack.span: [1 m, 3 m]\n"
                            "  mounting.clearance: {lower: 0 mm, upper: 4 mm, levels: 1000}\n"
                            "  pinion.module: {values: [20 mm, 25 mm, 32 mm]}\n"
                            "report: [contact_ratio]\n";
  // 5 x 1000 x 3 = 15000 points: fine under the default 100000...
  EXPECT_NO_THROW(load(sweep));
  // ...refused over max_points, naming the factors.
  const std::string big = sweep + "sweep: {levels: 40, max_points: 100000}\n";
  expect_error(big, t(position_of(big, "40")), "sweep.levels",
               {"120000 points", "rack.span 40 x mounting.clearance 1000 x pinion.module 3", "max_points = 100000"});
  const std::string lhs = sweep + "sweep: {method: lhs, points: 500, max_points: 100}\n";
  expect_error(lhs, t(position_of(lhs, "500")), "sweep.points", {"more than sweep.max_points = 100"});

  const std::string combos = kHead +
                             "variables:\n"
                             "  pinion.module: {values: [20 mm, 25 mm, 32 mm]}\n"
                             "  pinion.teeth: {values: [18, 20, 22]}\n"
                             "  rack.span: [1 m, 3 m]\n"
                             "objectives: [stiffness_fluctuation]\n"
                             "limits: {max_discrete_combinations: 8}\n";
  expect_error(combos, t(position_of(combos, "variables")), "variables",
               {"pinion.module (3 values) x pinion.teeth (3 values)", "9 combinations", "max_discrete_combinations = 8"});
}

// ----------------------------------------------------------------- overrides

TEST(StudyLoader, Overrides) {
  const StudySpec s = load(kOptimize + "problem_set: {load.force: 60 kN}\n",
                           {"problem.rack.span=1.5 m", "solver.max_evaluations=50", "study.seed=7",
                            "variables.pinion.pressure_angle.upper=22 deg"});
  ASSERT_EQ(s.problem_overrides.size(), 2u);
  EXPECT_EQ(s.problem_overrides[0], "load.force=\"60 kN\"");
  EXPECT_EQ(s.problem_overrides[1], "rack.span=1.5 m");
  EXPECT_EQ(s.solver.max_evaluations, 50u);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_EQ(s.solver.seed, 7u);
  EXPECT_NEAR(s.variables[0].upper, 22 * kPi / 180, 1e-15);

  // Variable keys are dotted problem paths: --set addresses a whole entry or
  // one field of it, and can add a variable.
  const StudySpec added = load(kOptimize, {"variables.rack.span=[1 m, 2 m]", "variables.rack.span.upper=2.5 m"});
  ASSERT_EQ(added.variables.size(), 2u);
  EXPECT_EQ(added.variables[1].key, "rack.span");
  EXPECT_DOUBLE_EQ(added.variables[1].lower, 1.0);
  EXPECT_DOUBLE_EQ(added.variables[1].upper, 2.5);
  // Removing the only variable leaves an optimize study without one.
  try {
    (void)load(kOptimize, {"variables.pinion.pressure_angle="});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at least one design variable"), std::string::npos) << e.what();
  }

  // Errors of study overrides name the command line.
  try {
    (void)load(kOptimize, {"solver.max_evals=5"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().file, "<command line>");
    EXPECT_NE(std::string(e.what()).find("did you mean 'max_evaluations'"), std::string::npos) << e.what();
  }
  // Problem overrides are checked against the problem now, not at the first design.
  try {
    (void)load(kOptimize, {"problem.rack.spna=1 m"});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().file, "<command line>");
    EXPECT_EQ(e.key_path(), "problem.rack.spna");
    EXPECT_NE(std::string(e.what()).find("did you mean 'span'"), std::string::npos) << e.what();
  }
}

TEST(StudyLoaderErrors, ProblemSetErrorsPointAtTheStudyFile) {
  const std::string text = kOptimize + "problem_set:\n  load.forse: 60 kN\n";
  expect_error(text, t(position_of(text, "load.forse")), "problem_set.load.forse", {"did you mean 'force'"});
  const std::string value = kOptimize + "problem_set:\n  rack.span: 3 kg\n";
  expect_error(value, t(position_of(value, "rack.span: 3")), "problem_set.rack.span", {"kg"});
  // A list value travels as a flow value.
  const std::string fault =
      kOptimize +
      "problem_set:\n  faults[0]: {type: spall, tooth: 1, start: 4 mm, length: 5 mm, width: 5 mm, depth: 1 mm}\n";
  const StudySpec s = load(fault);
  ASSERT_EQ(s.problem_overrides.size(), 1u);
  EXPECT_EQ(s.problem_overrides[0].rfind("faults[0]={", 0), 0u) << s.problem_overrides[0];
}

TEST(StudyLoaderErrors, FileErrors) {
  try {
    (void)studyfile::load_study_file(kStudies + "/does_not_exist.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open the study file"), std::string::npos) << e.what();
  }
  expect_error("[1, 2]\n", t("1:1"), "", {"a study file is a map"});
  expect_error("study: {kind: evaluate}\nstudy: {kind: sweep}\n", t("2:1"), "study", {"duplicate"});
}

}  // namespace
}  // namespace rackopt::study
