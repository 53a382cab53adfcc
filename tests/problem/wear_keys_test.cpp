// Problem loader: the wear, duty and reliability keys.
//
// Expected SI values are hand arithmetic written next to each assertion from
// the unit definitions (1 HB = 9.80665e6 Pa, docs/models/wear.md; 1 yr = 365.25 d
// = 31 557 600 s; 1 mm = 1e-3 m) and from docs/models/wear.md, docs/models/reliability.md for the
// bundled ship lift, never from running the loader. Error positions
// (line:column) are counted by hand in the YAML text of each test.
#include "problem_test_support.hpp"
#include "rackopt/problem/problem_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rackopt {
namespace {

using test::kHB;  // Pa per Brinell number
constexpr double kYear = 365.25 * 86400;  // s, Julian year

using test::expect_error;
using test::Expected;
using test::problem_path;

// Lines 1..9: a valid drive without wear (module 10 mm); tests append from line 10.
const std::string kDrive =
    "pinion:\n"              // 1
    "  teeth: 20\n"          // 2
    "  module: 10 mm\n"      // 3
    "  face_width: 50 mm\n"  // 4
    "rack:\n"                // 5
    "  body_height: 80 mm\n" // 6
    "  span: 2 m\n"          // 7
    "load:\n"                // 8
    "  force: 10 kN\n";      // 9

// The smallest configured wear: lines 10..12.
const std::string kWear = kDrive +
                          "wear:\n"                 // 10
                          "  coefficient: 1e-6\n"   // 11
                          "  hardness: 600 HB\n";   // 12

double polynomial(const std::vector<double>& c, double h) {
  double v = 0;
  double power = 1;
  for (double ci : c) {
    v += ci * power;
    power *= h;
  }
  return v;
}

// ------------------------------------------------------------------ ship lift

TEST(WearKeys, ShipLiftWearPaperData) {
  const Drive d = load_problem(problem_path("ship_lift.yaml"));
  const WearSpec& w = d.wear;
  EXPECT_DOUBLE_EQ(w.coefficient, 0.3e-5);      // the wear paper's 0.3 x 10^?, exponent calibrated
  EXPECT_DOUBLE_EQ(w.max_depth, 1.5e-3);        // the wear paper's h_max = 1.5 mm
  EXPECT_DOUBLE_EQ(w.min_contact_ratio, 1.2);
  EXPECT_FALSE(w.update_profile);
  EXPECT_EQ(w.profile_points, 240);
  EXPECT_FALSE(w.stop_at_case_depth);
  // The wear paper's polynomial H = 596 + 2 h - 1.6786 h^2 - 0.25 h^3 (HB, h in mm):
  // c_i [Pa/m^i] = c_i * 9.80665e6 / (1e-3)^i.
  for (const HardnessProfile* h : {&w.pinion_hardness, &w.rack_hardness}) {
    ASSERT_EQ(h->kind, HardnessProfile::Kind::kPolynomial);
    ASSERT_EQ(h->coefficients.size(), 4u);
    EXPECT_DOUBLE_EQ(h->coefficients[0], 596 * 9.80665e6);
    EXPECT_DOUBLE_EQ(h->coefficients[1], 2 * 9.80665e6 / 1e-3);
    EXPECT_DOUBLE_EQ(h->coefficients[2], -1.6786 * 9.80665e6 / 1e-6);
    EXPECT_DOUBLE_EQ(h->coefficients[3], -0.25 * 9.80665e6 / 1e-9);
    EXPECT_DOUBLE_EQ(h->surface, 596 * kHB);  // H0 = 596 HB
    EXPECT_DOUBLE_EQ(h->valid_depth, 6.5e-3);
    EXPECT_DOUBLE_EQ(h->core, 300 * kHB);
    // docs/models/wear.md, independent of the conversion above: the SI polynomial
    // gives 0.8 H0 = 476.8 HB at h = 6.35 mm and its maximum 596.55 HB near 0.53 mm.
    EXPECT_NEAR(polynomial(h->coefficients, 6.35e-3) / kHB, 476.8, 0.5);
    EXPECT_NEAR(polynomial(h->coefficients, 0.53e-3) / kHB, 596.55, 0.01);
  }
  EXPECT_NEAR(d.duty.rack_meshes_per_year, 1.0e4, 1e-9);  // the wear paper's n_L = 1.0 x 10^4 a year (exponent calibrated)
  EXPECT_DOUBLE_EQ(d.duty.pinion_meshes_per_year, d.duty.rack_meshes_per_year);  // default = the rack's
  const ReliabilitySpec& r = d.reliability;
  EXPECT_EQ(r.samples, 1000);  // the wear paper's N = 1000
  EXPECT_EQ(r.seed, 1u);
  EXPECT_FALSE(r.sobol);
  EXPECT_EQ(r.reliabilities, (std::vector<double>{0.9, 0.95, 0.99}));
  // The wear paper's table times (docs/models/reliability.md), in seconds.
  const double years[] = {40, 55, 60, 65, 75};
  ASSERT_EQ(r.times.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(r.times[i], years[i] * 31557600.0);
  EXPECT_DOUBLE_EQ(r.ks_level, 0.05);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].key, "contact_ratio");
  EXPECT_EQ(r.inputs[0].distribution, RandomInput::Distribution::kNormal);
  // Around the design's own contact ratio (the paper's zero clearance: 1.536,
  // the largest this pair can have, docs/models/reliability.md), calibrated against the
  // seed's R(t) table: shifted below it, with about 0.6 % of the samples
  // above it (z = 2.5).
  EXPECT_FALSE(r.inputs[0].absolute);
  EXPECT_GT(r.inputs[0].b, 0.0);
  EXPECT_EQ(r.inputs[0].cv, 0.0);
  EXPECT_NEAR(-r.inputs[0].a / r.inputs[0].b, 2.5, 0.1);
}

// ------------------------------------------------------------------ defaults

TEST(WearKeys, AbsentSectionsLeaveWearUnconfigured) {
  const Drive d = load_problem_text(kDrive, "t.yaml");
  EXPECT_EQ(d.wear.coefficient, 0.0);  // 0 = wear not configured (drive.hpp)
  EXPECT_EQ(d.duty.rack_meshes_per_year, 0.0);
  EXPECT_EQ(d.duty.pinion_meshes_per_year, 0.0);
  EXPECT_EQ(d.reliability.samples, 1000);
  EXPECT_EQ(d.reliability.seed, 1u);
  EXPECT_FALSE(d.reliability.sobol);
  EXPECT_TRUE(d.reliability.inputs.empty());
  EXPECT_TRUE(d.reliability.reliabilities.empty());
  EXPECT_TRUE(d.reliability.times.empty());
  EXPECT_DOUBLE_EQ(d.reliability.ks_level, 0.05);
}

TEST(WearKeys, DefaultsOfAConfiguredWear) {
  const Drive d = load_problem_text(kWear, "t.yaml");
  const WearSpec& w = d.wear;
  EXPECT_DOUBLE_EQ(w.coefficient, 1e-6);
  EXPECT_DOUBLE_EQ(w.max_depth, 1.5e-3);  // documented default 1.5 mm
  EXPECT_DOUBLE_EQ(w.min_contact_ratio, 1.0);
  EXPECT_FALSE(w.stop_at_case_depth);
  EXPECT_TRUE(w.update_profile);
  EXPECT_EQ(w.profile_points, 240);  // converged to 0.5 % (docs/accuracy.md, "Profile points")
  EXPECT_DOUBLE_EQ(w.block_fraction, 0.05);
  // A single hardness is a constant profile for both members; core = surface.
  for (const HardnessProfile* h : {&w.pinion_hardness, &w.rack_hardness}) {
    EXPECT_EQ(h->kind, HardnessProfile::Kind::kConstant);
    EXPECT_DOUBLE_EQ(h->surface, 600 * 9.80665e6);
    EXPECT_DOUBLE_EQ(h->core, 600 * 9.80665e6);
  }
}

// ------------------------------------------------------------------ every key

TEST(WearKeys, EveryKeyToSI) {
  const std::string text = kDrive +
      "wear:\n"
      "  coefficient: 2.5e-7\n"
      "  max_depth: 0.002 m\n"
      "  min_contact_ratio: 1.2\n"
      "  stop_at_case_depth: on\n"
      "  update_profile: off\n"
      "  profile_points: 100\n"
      "  block_fraction: 0.01\n"
      "  hardness: {kind: constant, surface: 5 GPa}\n"   // overridden for both members below
      "  pinion_hardness: {kind: case_hardened, surface: 650 HV, core: 300 HB, case_depth: 4 mm, exponent: 2.5}\n"
      "  rack_hardness:\n"
      "    kind: table\n"
      "    depths: \"[0, 1, 2.5] mm\"\n"
      "    values: [600 HB, 5 GPa, 400]\n"
      "    core: 280 HB\n"
      "duty:\n"
      "  rack_meshes_per_year: 10 per day\n"
      "  pinion_meshes_per_year: 2e5\n"
      "reliability:\n"
      "  samples: 100\n"
      "  seed: 42\n"
      "  sampling: sobol\n"
      "  R: [0.5, 0.99]\n"
      "  times: [\"1 d\", 2 d, 3]\n"
      "  ks_level: 0.1\n"
      "  random:\n"
      "    - {input: contact_ratio, distribution: normal, absolute: true, mean: 1.5, sd: 0.03}\n"
      "    - {input: wear_coefficient, distribution: lognormal, absolute: true, median: 3e-6, sigma: 0.5}\n"
      "    - {input: load, distribution: uniform, absolute: true, lower: 900 kN, upper: 1 MN}\n"
      "    - {input: surface_hardness, distribution: weibull, absolute: true, scale: 600 HB, shape: 20}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  const WearSpec& w = d.wear;
  EXPECT_DOUBLE_EQ(w.coefficient, 2.5e-7);
  EXPECT_DOUBLE_EQ(w.max_depth, 0.002);
  EXPECT_DOUBLE_EQ(w.min_contact_ratio, 1.2);
  EXPECT_TRUE(w.stop_at_case_depth);
  EXPECT_FALSE(w.update_profile);
  EXPECT_EQ(w.profile_points, 100);
  EXPECT_DOUBLE_EQ(w.block_fraction, 0.01);

  const HardnessProfile& p = w.pinion_hardness;
  EXPECT_EQ(p.kind, HardnessProfile::Kind::kCaseHardened);
  EXPECT_DOUBLE_EQ(p.surface, 650 * 9.80665e6);  // HV taken as HB
  EXPECT_DOUBLE_EQ(p.core, 300 * 9.80665e6);
  EXPECT_DOUBLE_EQ(p.case_depth, 4e-3);
  EXPECT_DOUBLE_EQ(p.exponent, 2.5);
  EXPECT_DOUBLE_EQ(p.limit, 0.8 * 650 * 9.80665e6);  // default: ISO 18203 SHD, 0.8 x surface

  const HardnessProfile& r = w.rack_hardness;
  EXPECT_EQ(r.kind, HardnessProfile::Kind::kTable);
  ASSERT_EQ(r.depths.size(), 3u);
  EXPECT_DOUBLE_EQ(r.depths[0], 0.0);
  EXPECT_DOUBLE_EQ(r.depths[1], 1e-3);
  EXPECT_DOUBLE_EQ(r.depths[2], 2.5e-3);
  ASSERT_EQ(r.values.size(), 3u);
  EXPECT_DOUBLE_EQ(r.values[0], 600 * 9.80665e6);
  EXPECT_DOUBLE_EQ(r.values[1], 5e9);
  EXPECT_DOUBLE_EQ(r.values[2], 400 * 9.80665e6);  // bare: HB
  EXPECT_DOUBLE_EQ(r.surface, 600 * 9.80665e6);    // the first measured value
  EXPECT_DOUBLE_EQ(r.core, 280 * 9.80665e6);

  EXPECT_NEAR(d.duty.rack_meshes_per_year, 10 * 365.25, 1e-9);  // 10 a day
  EXPECT_NEAR(d.duty.pinion_meshes_per_year, 2e5, 1e-7);         // bare rate: per year

  const ReliabilitySpec& rel = d.reliability;
  EXPECT_EQ(rel.samples, 100);
  EXPECT_EQ(rel.seed, 42u);
  EXPECT_TRUE(rel.sobol);
  EXPECT_EQ(rel.reliabilities, (std::vector<double>{0.5, 0.99}));
  ASSERT_EQ(rel.times.size(), 3u);
  EXPECT_DOUBLE_EQ(rel.times[0], 86400.0);
  EXPECT_DOUBLE_EQ(rel.times[1], 2 * 86400.0);
  EXPECT_DOUBLE_EQ(rel.times[2], 3 * kYear);  // bare time: years
  EXPECT_DOUBLE_EQ(rel.ks_level, 0.1);
  ASSERT_EQ(rel.inputs.size(), 4u);
  using D = RandomInput::Distribution;
  EXPECT_EQ(rel.inputs[0].key, "contact_ratio");
  EXPECT_EQ(rel.inputs[0].distribution, D::kNormal);
  EXPECT_DOUBLE_EQ(rel.inputs[0].a, 1.5);
  EXPECT_DOUBLE_EQ(rel.inputs[0].b, 0.03);
  EXPECT_EQ(rel.inputs[1].key, "wear.coefficient");
  EXPECT_EQ(rel.inputs[1].distribution, D::kLognormal);
  EXPECT_DOUBLE_EQ(rel.inputs[1].a, 3e-6);
  EXPECT_DOUBLE_EQ(rel.inputs[1].b, 0.5);
  EXPECT_EQ(rel.inputs[2].key, "load");
  EXPECT_EQ(rel.inputs[2].distribution, D::kUniform);
  EXPECT_DOUBLE_EQ(rel.inputs[2].a, 900e3);
  EXPECT_DOUBLE_EQ(rel.inputs[2].b, 1e6);
  EXPECT_EQ(rel.inputs[3].key, "surface_hardness");
  EXPECT_EQ(rel.inputs[3].distribution, D::kWeibull);
  EXPECT_DOUBLE_EQ(rel.inputs[3].a, 600 * 9.80665e6);
  EXPECT_DOUBLE_EQ(rel.inputs[3].b, 20.0);
  for (const RandomInput& in : rel.inputs) EXPECT_TRUE(in.absolute) << in.key;
}

TEST(WearKeys, PolynomialAndTableUnitsApplyToBareNumbers) {
  // Coefficients in GPa with h in um: c1 = 0.001 GPa/um = 1e6 Pa / 1e-6 m = 1e12 Pa/m.
  const std::string text = kDrive +
      "wear:\n"
      "  coefficient: 1e-6\n"
      "  pinion_hardness: {kind: polynomial, coefficients: [6, -0.001], depth_unit: um, hardness_unit: GPa,"
      " valid_depth: 2 mm}\n"
      "  rack_hardness: {kind: table, depths: [0, 500, 1000], depth_unit: um, values: [6, 5.5, 4], hardness_unit: GPa}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  const HardnessProfile& p = d.wear.pinion_hardness;
  ASSERT_EQ(p.coefficients.size(), 2u);
  EXPECT_DOUBLE_EQ(p.coefficients[0], 6e9);
  EXPECT_DOUBLE_EQ(p.coefficients[1], -0.001 * 1e9 / 1e-6);
  EXPECT_DOUBLE_EQ(p.surface, 6e9);
  // Core defaults to the value at the deepest measured point: 6 GPa - 1e12 Pa/m * 2e-3 m = 4 GPa.
  EXPECT_NEAR(p.core, 4e9, 1e-6 * 4e9);
  const HardnessProfile& r = d.wear.rack_hardness;
  EXPECT_EQ(r.depths, (std::vector<double>{0, 500e-6, 1000e-6}));
  ASSERT_EQ(r.values.size(), 3u);
  EXPECT_DOUBLE_EQ(r.values[1], 5.5e9);
  EXPECT_DOUBLE_EQ(r.core, 4e9);  // last measured value
}

TEST(WearKeys, MemberHardnessOverridesTheCommonOne) {
  const std::string text = kWear + "  rack_hardness: {kind: constant, surface: 500 HB}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_DOUBLE_EQ(d.wear.pinion_hardness.surface, 600 * kHB);
  EXPECT_DOUBLE_EQ(d.wear.rack_hardness.surface, 500 * kHB);
}

// ------------------------------------------------------------------ --set

TEST(WearKeys, OverridesReachNestedKeys) {
  const std::string text = kDrive +
      "wear:\n"
      "  coefficient: 1e-6\n"
      "  hardness: {kind: case_hardened, surface: 600 HB, core: 300 HB, case_depth: 4 mm}\n";
  const Drive d = load_problem_text(text, "t.yaml",
                                    {"wear.coefficient=3e-6", "wear.hardness.case_depth=6 mm",
                                     "wear.rack_hardness={kind: constant, surface: 500 HB}",
                                     "wear.profile_points=200", "duty.rack_meshes_per_year=1000",
                                     "reliability.samples=100", "reliability.times=[10 yr, 20 yr]",
                                     "reliability.random[0]={input: load, distribution: normal, absolute: true, mean: 10 kN, sd: 1 kN}"});
  EXPECT_DOUBLE_EQ(d.wear.coefficient, 3e-6);
  EXPECT_DOUBLE_EQ(d.wear.pinion_hardness.case_depth, 6e-3);
  EXPECT_EQ(d.wear.rack_hardness.kind, HardnessProfile::Kind::kConstant);
  EXPECT_DOUBLE_EQ(d.wear.rack_hardness.surface, 500 * kHB);
  EXPECT_EQ(d.wear.profile_points, 200);
  EXPECT_NEAR(d.duty.rack_meshes_per_year, 1000, 1e-9);
  EXPECT_EQ(d.reliability.samples, 100);
  EXPECT_EQ(d.reliability.times, (std::vector<double>{10 * kYear, 20 * kYear}));
  ASSERT_EQ(d.reliability.inputs.size(), 1u);
  EXPECT_DOUBLE_EQ(d.reliability.inputs[0].a, 10e3);

  // On the bundled ship lift: a different wear coefficient and no wear at all.
  EXPECT_DOUBLE_EQ(load_problem(problem_path("ship_lift.yaml"), {"wear.coefficient=3e-9"}).wear.coefficient, 3e-9);
  EXPECT_EQ(load_problem(problem_path("ship_lift.yaml"), {"wear="}).wear.coefficient, 0.0);
}

TEST(WearKeys, OverrideErrorsNameTheCommandLine) {
  expect_error(kWear, {0, 0, "wear.coefficient", "allowed: 1e-20 <= coefficient <= 1", "<command line>"},
               {"wear.coefficient=2"});
  expect_error(kWear, {0, 0, "reliability.samples", "allowed: 1 <= samples <= 1000000", "<command line>"},
               {"reliability.samples=0"});
  expect_error(kWear, {0, 0, "wear.hardness.surface", "unknown unit 'HRC' for a hardness", "<command line>"},
               {"wear.hardness={kind: constant, surface: 55 HRC}"});
}

// ------------------------------------------------------------------ errors

TEST(WearErrors, UnknownDistribution) {
  expect_error(kWear +
                   "reliability:\n"                                                   // 13
                   "  random:\n"                                                      // 14
                   "    - {input: load, distribution: gumbel, mean: 1 kN, sd: 1 kN}\n",  // 15
               {15, 35, "reliability.random[0].distribution",
                "'gumbel' is not allowed; allowed: normal | lognormal | uniform | weibull"});
}

TEST(WearErrors, MissingAndForeignDistributionParameters) {
  // Missing: reported at the item's map ('{' in column 7).
  expect_error(kWear +
                   "reliability:\n"
                   "  random:\n"
                   "    - {input: load, distribution: normal, absolute: true, mean: 1 kN}\n",  // 15
               {15, 7, "reliability.random[0].sd", "required key 'sd' is missing; expected a force"});
  // A parameter of another distribution: at its key.
  expect_error(kWear +
                   "reliability:\n"
                   "  random:\n"
                   "    - {input: wear_coefficient, distribution: lognormal, absolute: true, median: 3e-6, sd: 0.5}\n",  // 15
               {15, 88, "reliability.random[0].sd",
                "'sd' is not a parameter of an absolute lognormal distribution; its parameters: median, sigma"});
}

TEST(WearErrors, DistributionParameterRanges) {
  expect_error(kWear +
                   "reliability:\n"
                   "  random:\n"
                   "    - {input: load, distribution: normal, absolute: true, mean: 1 kN, sd: 0 kN}\n",  // 15, "0 kN" at 75
               {15, 75, "reliability.random[0].sd", "0 N is out of range; allowed: 0 N < sd"});
  expect_error(kWear +
                   "reliability:\n"
                   "  random:\n"
                   "    - {input: contact_ratio, distribution: uniform, absolute: true, lower: 1.5, upper: 1.4}\n",  // 15, "1.4" at 88
               {15, 88, "reliability.random[0].upper", "allowed: 1.5 < upper (upper must exceed lower)"});
  expect_error(kWear, {0, 0, "reliability.random[0].shape", "allowed: 0 < shape", "<command line>"},
               {"reliability.random[0]={input: load, distribution: weibull, absolute: true, scale: 1 kN, shape: -2}"});
  expect_error(kWear, {0, 0, "reliability.random[0].mean", "'HB' is a unit of a hardness but a force is expected",
                       "<command line>"},
               {"reliability.random[0]={input: load, distribution: normal, absolute: true, mean: 600 HB, sd: 1 kN}"});
}

TEST(WearErrors, DuplicateRandomInput) {
  expect_error(kWear +
                   "reliability:\n"                                                         // 13
                   "  random:\n"                                                            // 14
                   "    - {input: load, distribution: normal, absolute: true, mean: 1 kN, sd: 0.1 kN}\n"    // 15
                   "    - {input: load, distribution: uniform, absolute: true, lower: 1 kN, upper: 2 kN}\n",  // 16
               {16, 15, "reliability.random[1].input",
                "'load' is already random in reliability.random[0]; each input may appear once"});
}

TEST(WearErrors, ReliabilityOutsideZeroOne) {
  expect_error(kWear +
                   "reliability:\n"       // 13
                   "  R: [0.9, 1.0]\n",   // 14
               {14, 12, "reliability.R[1]", "1 is out of range; allowed: 0 < R < 1"});
  expect_error(kWear, {0, 0, "reliability.R[0]", "allowed: 0 < R < 1", "<command line>"}, {"reliability.R=[0]"});
}

TEST(WearErrors, TimesListsAndUnits) {
  expect_error(kWear +
                   "reliability:\n"                       // 13
                   "  times: \"[40, 55] weeks\"\n",       // 14, value at column 10
               {14, 10, "reliability.times", "unknown unit 'weeks' for a time"});
  expect_error(kWear +
                   "reliability:\n"                       // 13
                   "  times: [40 yr, -5 yr]\n",           // 14, "-5 yr" at column 18
               {14, 18, "reliability.times[1]", "allowed: 1e-06 yr <= times"});
}

TEST(WearKeys, LifeAtRFidelityKnobs) {
  // Defaults are the documented ones (docs/yaml.md, reliability).
  const Drive d = load_problem_text(kWear, "t.yaml");
  EXPECT_EQ(d.reliability.bootstrap_replicates, 100);
  EXPECT_TRUE(d.reliability.life_table);
  EXPECT_DOUBLE_EQ(d.reliability.life_table_tolerance, 5e-4);
  const Drive e = load_problem_text(kWear +
                                        "reliability:\n"
                                        "  bootstrap_replicates: 250\n"
                                        "  life_table: off\n"
                                        "  life_table_tolerance: 1e-3\n",
                                    "t.yaml");
  EXPECT_EQ(e.reliability.bootstrap_replicates, 250);
  EXPECT_FALSE(e.reliability.life_table);
  EXPECT_DOUBLE_EQ(e.reliability.life_table_tolerance, 1e-3);
  expect_error(kWear +
                   "reliability:\n"                    // 13
                   "  bootstrap_replicates: 5\n",      // 14, value at column 25
               {14, 25, "reliability.bootstrap_replicates", "allowed: 20"});
  expect_error(kWear, {0, 0, "reliability.life_table_tolerance", "allowed", "<command line>"},
               {"reliability.life_table_tolerance=0.5"});
}

TEST(WearErrors, TableDepthsNotAscending) {
  expect_error(kDrive +
                   "wear:\n"                            // 10
                   "  coefficient: 1e-6\n"              // 11
                   "  hardness:\n"                      // 12
                   "    kind: table\n"                  // 13
                   "    depths: [0, 1, 1]\n"            // 14, third item at column 20
                   "    values: [600, 500, 400]\n",     // 15
               {14, 20, "wear.hardness.depths[2]", "depths must be strictly ascending; 1 mm follows 1 mm"});
  expect_error(kDrive +
                   "wear:\n"
                   "  coefficient: 1e-6\n"
                   "  hardness:\n"
                   "    kind: table\n"
                   "    depths: [0, 1, 2]\n"
                   "    values: [600, 500]\n",          // 15, '[' at column 13
               {15, 13, "wear.hardness.values", "values has 2 items but depths has 3"});
}

TEST(WearErrors, UnknownHardnessUnit) {
  expect_error(kDrive +
                   "wear:\n"                                        // 10
                   "  coefficient: 1e-6\n"                          // 11
                   "  hardness:\n"                                  // 12
                   "    kind: polynomial\n"                         // 13
                   "    coefficients: [596, 2, -1.6786, -0.25]\n"   // 14
                   "    hardness_unit: HRC\n"                       // 15, HRC at column 20
                   "    valid_depth: 6.5 mm\n",                     // 16
               {15, 20, "wear.hardness.hardness_unit",
                "unknown unit 'HRC' for a hardness; allowed units: HB, HV, MPa, GPa, Pa, N/mm^2 (a bare number means HB)"});
}

TEST(WearErrors, HardnessProfileShape) {
  // A key of another profile kind.
  expect_error(kDrive +
                   "wear:\n"                                                     // 10
                   "  coefficient: 1e-6\n"                                       // 11
                   "  hardness: {kind: constant, surface: 600, valid_depth: 2}\n",  // 12, valid_depth at 44
               {12, 44, "wear.hardness.valid_depth",
                "key 'valid_depth' does not belong to a 'constant' hardness profile; its keys: kind, surface"});
  // No kind: reported at the map.
  expect_error(kDrive + "wear:\n  coefficient: 1e-6\n  hardness: {surface: 600}\n", {12, 13, "wear.hardness.kind",
                                                                                    "required key 'kind' is missing"});
  // Unknown kind.
  expect_error(kDrive + "wear:\n  coefficient: 1e-6\n  hardness: {kind: nitrided}\n",
               {12, 20, "wear.hardness.kind", "allowed: constant | polynomial | table | case_hardened"});
  // A measured fit that goes to zero inside its range: 100 - 100 h (HB, mm)
  // is 0 at h = 1 mm < valid_depth = 2 mm.
  expect_error(kDrive +
                   "wear:\n"                                                                       // 10
                   "  coefficient: 1e-6\n"                                                         // 11
                   "  hardness: {kind: polynomial, coefficients: [100, -100], valid_depth: 2 mm}\n",  // 12, 2 mm at 72
               {12, 72, "wear.hardness.valid_depth", "a measured fit must stay positive over its range"});
  // Case-hardening: limit outside (core, surface).
  expect_error(kDrive +
                   "wear:\n"
                   "  coefficient: 1e-6\n"
                   "  hardness: {kind: case_hardened, surface: 600, core: 300, case_depth: 4, limit: 650}\n",  // 12
               {12, 82, "wear.hardness.limit", "allowed: 300 HB < limit < 600 HB"});
  // Default limit 0.8 x 600 = 480 HB is below a 500 HB core.
  expect_error(kDrive +
                   "wear:\n"
                   "  coefficient: 1e-6\n"
                   "  hardness: {kind: case_hardened, surface: 600, core: 500, case_depth: 4}\n",  // 12, core 500 at 55
               {12, 55, "wear.hardness.core", "the default limit is 0.8 x surface"});
}

TEST(WearErrors, WearSectionNeedsCoefficientAndHardness) {
  expect_error(kDrive + "wear:\n  hardness: 600 HB\n",  // wear map starts at 11:3
               {11, 3, "wear.coefficient", "required key 'coefficient' is missing"});
  expect_error(kDrive + "wear:\n  coefficient: 1e-6\n",
               {11, 3, "wear.hardness", "a hardness profile for both members"});
  expect_error(kDrive + "wear:\n  coefficient: 1e-6\n  pinion_hardness: 600\n",
               {11, 3, "wear.rack_hardness", "a hardness profile for both members"});
  // A file without wear: --set of one wear key configures wear and needs the rest.
  expect_error(kDrive, {0, 0, "wear.hardness", "a hardness profile for both members", "<command line>"},
               {"wear.coefficient=3e-6"});
}

TEST(WearErrors, WearRangesAndCrossChecks) {
  expect_error(kWear + "  coeficient: 1e-6\n",
               {13, 3, "wear.coeficient", "did you mean 'coefficient'?"});
  // pi m / 4 = pi * 10 mm / 4 = 7.854 mm.
  expect_error(kWear + "  max_depth: 8 mm\n",
               {13, 14, "wear.max_depth", "allowed: 0 mm < max_depth <= 7.85398 mm (half the tooth thickness"});
  expect_error(kWear + "  min_contact_ratio: 0.9\n", {13, 22, "wear.min_contact_ratio", "1 <= min_contact_ratio <= 5"});
  expect_error(kWear + "  profile_points: 3\n", {13, 19, "wear.profile_points", "5 <= profile_points <= 2000"});
  expect_error(kWear + "  block_fraction: 0.6\n", {13, 19, "wear.block_fraction", "block_fraction <= 0.5"});
  expect_error(kWear + "  stop_at_case_depth: on\n",
               {13, 23, "wear.stop_at_case_depth", "needs a case_hardened hardness profile"});
  expect_error(kWear + "duty:\n  pinion_meshes_per_year: 100\n",
               {14, 3, "duty.rack_meshes_per_year", "required key 'rack_meshes_per_year' is missing"});
  expect_error(kWear + "duty:\n  rack_meshes_per_year: 0\n",
               {14, 25, "duty.rack_meshes_per_year", "0 1/yr is out of range; allowed: 0.001 1/yr <= rack_meshes_per_year"});
  expect_error(kWear + "reliability:\n  sampling: halton\n",
               {14, 13, "reliability.sampling", "allowed: pseudo | sobol"});
  expect_error(kWear + "reliability:\n  ks_level: 0.9\n", {14, 13, "reliability.ks_level", "ks_level <= 0.5"});
  expect_error(kWear + "reliability:\n  seed: -1\n", {14, 9, "reliability.seed", "0 <= seed"});
}

TEST(WearKeyKinds, ForStudies) {
  EXPECT_EQ(problem_key_kind("wear.coefficient"), QuantityKind::kDimensionless);
  EXPECT_EQ(problem_key_kind("wear.max_depth"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("wear.hardness"), QuantityKind::kHardness);
  EXPECT_EQ(problem_key_kind("wear.rack_hardness"), QuantityKind::kHardness);
  EXPECT_EQ(problem_key_kind("wear.pinion_hardness.case_depth"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("wear.rack_hardness.surface"), QuantityKind::kHardness);
  EXPECT_EQ(problem_key_kind("wear.hardness.depths[1]"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("duty.rack_meshes_per_year"), QuantityKind::kRate);
  EXPECT_EQ(problem_key_kind("reliability.times[3]"), QuantityKind::kTime);
  EXPECT_EQ(problem_key_kind("reliability.samples"), QuantityKind::kCount);
  EXPECT_EQ(problem_key_kind("reliability.random[0].mean"), std::nullopt);  // kind follows `input`
  EXPECT_EQ(problem_key_kind("wear.rack_hardnessx.surface"), std::nullopt);
  EXPECT_EQ(problem_key_kind("faults[2].depth"), QuantityKind::kLength);
}

}  // namespace
}  // namespace rackopt
