// Problem loader: bundled files, every error class with its exact
// file:line:column and key path, overrides, variants, derived values.
//
// Expected numbers come from the sources the problem files cite (seed tables,
// docs/models/reliability.md, docs/models/geometry.md, docs/models/mesh.md) or from hand arithmetic written next to the
// assertion, never from running the loader.
#include "problem_test_support.hpp"
#include "rackopt/problem/problem_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;

using test::expect_error;
using test::Expected;
using test::kDeg;
using test::kMinimal;
using test::problem_path;

// ---------------------------------------------------------------- bundled files

TEST(BundledProblems, RackRailwayMatchesRailwayPaperTable1) {
  const Drive d = load_problem(problem_path("rack_railway.yaml"));
  // The rack railway paper's Table 1.
  EXPECT_EQ(d.pinion.teeth, 22);
  EXPECT_DOUBLE_EQ(d.pinion.module, 31.831e-3);
  EXPECT_DOUBLE_EQ(d.pinion.pressure_angle, 14 * kDeg);
  EXPECT_DOUBLE_EQ(d.pinion.face_width, 0.060);
  EXPECT_DOUBLE_EQ(d.pinion.addendum_coef, 0.9);
  EXPECT_DOUBLE_EQ(d.pinion.dedendum_coef, 0.9 + 0.166);
  EXPECT_DOUBLE_EQ(d.rack.addendum_coef, 0.9);
  EXPECT_DOUBLE_EQ(d.rack.dedendum_coef, 0.9 + 0.166);
  EXPECT_DOUBLE_EQ(d.pinion.material.youngs_modulus, 210e9);
  EXPECT_DOUBLE_EQ(d.rack.material.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(d.rack.span, 2.4);
  EXPECT_EQ(d.rack.supports, Supports::kPinPin);
  EXPECT_DOUBLE_EQ(d.mounting.clearance, 0.0);
  // docs/models/mesh.md: EI = 4.517e5 N m^2 from the series fit; the 60 x 75.5 mm
  // body reproduces it to 0.5 %.
  EXPECT_NEAR(d.rack.material.youngs_modulus * d.rack.section.second_moment, 4.517e5, 0.005 * 4.517e5);
  // Full physics: every effect on, coupled rack span.
  EXPECT_TRUE(d.effects.interference_limit);
  EXPECT_TRUE(d.effects.couple_term);
  EXPECT_EQ(d.effects.rack_span, RackSpanModel::kCoupled);
  // Rack tooth offset defaults to half a pitch: pi * 31.831 / 2 = 50.0 mm.
  EXPECT_NEAR(d.rack.tooth_offset, 0.050, 1e-5);
  EXPECT_TRUE(d.spalls.empty());
}

TEST(BundledProblems, RackRailwayPaperIsTheReducedModel) {
  const Drive d = load_problem(problem_path("rack_railway_paper.yaml"));
  EXPECT_EQ(d.pinion.teeth, 22);
  EXPECT_EQ(d.effects.rack_span, RackSpanModel::kPerPair);
  EXPECT_FALSE(d.effects.couple_term);
  EXPECT_FALSE(d.effects.interference_limit);
  EXPECT_DOUBLE_EQ(d.rack.face_width, 0.060);  // defaulted to the pinion face width
}

TEST(BundledProblems, ShipLiftForceFromTorqueMatchesPhysicsMd) {
  const Drive d = load_problem(problem_path("ship_lift.yaml"));
  EXPECT_EQ(d.pinion.teeth, 16);
  EXPECT_DOUBLE_EQ(d.pinion.profile_shift, 0.5);
  EXPECT_DOUBLE_EQ(d.pinion.material.youngs_modulus, 209e9);
  EXPECT_DOUBLE_EQ(d.pinion.material.poisson_ratio, 0.271);
  EXPECT_DOUBLE_EQ(d.rack.material.youngs_modulus, 202e9);
  EXPECT_DOUBLE_EQ(d.rack.material.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(d.load.torque, 453e3);
  // docs/models/reliability.md: F_n = 956.5 kN (printed to 4 digits).
  EXPECT_NEAR(d.load.force, 956.5e3, 0.05e3);
  // Default bore: 0.5 r_f = 0.5 * 63 * (8 - 1.25 + 0.5) mm = 228.375 mm.
  EXPECT_NEAR(d.pinion.bore_radius, 0.228375, 1e-9);
}

TEST(BundledProblems, LargeModuleVariantsAreTheSpallingPaperSpallLevels) {
  const std::string path = problem_path("large_module.yaml");
  EXPECT_EQ(problem_variants(path), (std::vector<std::string>{"normal", "mild", "moderate", "severe"}));
  const Drive normal = load_problem(path);  // the file selects "normal"
  EXPECT_TRUE(normal.spalls.empty());
  EXPECT_EQ(normal.pinion.teeth, 17);
  EXPECT_DOUBLE_EQ(normal.pinion.material.youngs_modulus, 211e9);
  EXPECT_DOUBLE_EQ(normal.pinion.material.poisson_ratio, 0.29);
  // The spalling paper's table: depth 2 mm, width 5 mm, length 5 / 10 / 15 mm.
  const std::vector<std::pair<std::string, double>> levels = {{"mild", 5e-3}, {"moderate", 10e-3}, {"severe", 15e-3}};
  for (const auto& [name, length] : levels) {
    const Drive d = load_problem(path, {"variant=" + name});
    ASSERT_EQ(d.spalls.size(), 1u) << name;
    EXPECT_DOUBLE_EQ(d.spalls[0].length, length) << name;
    EXPECT_DOUBLE_EQ(d.spalls[0].depth, 2e-3);
    EXPECT_DOUBLE_EQ(d.spalls[0].width, 5e-3);
    EXPECT_EQ(d.spalls[0].member, Member::kPinion);
    EXPECT_EQ(d.spalls[0].tooth, 0);
    EXPECT_NE(d.name.find(name), std::string::npos);
    // The variant changes the faults and nothing else.
    EXPECT_DOUBLE_EQ(d.pinion.module, normal.pinion.module);
  }
}

// ------------------------------------------------------------ defaults, derived

TEST(Loader, DefaultsAndDerivedRectangularSection) {
  const Drive d = load_problem_text(kMinimal, "t.yaml");
  EXPECT_EQ(d.name, "t");  // file stem
  EXPECT_DOUBLE_EQ(d.pinion.pressure_angle, 20 * kDeg);
  EXPECT_DOUBLE_EQ(d.pinion.addendum_coef, 1.0);
  EXPECT_DOUBLE_EQ(d.pinion.dedendum_coef, 1.25);
  EXPECT_DOUBLE_EQ(d.pinion.tip_radius_coef, 0.38);
  EXPECT_DOUBLE_EQ(d.pinion.profile_shift, 0.0);
  // r_f = 10 * (10 - 1.25) = 87.5 mm; bore = half of it.
  EXPECT_NEAR(d.pinion.bore_radius, 0.04375, 1e-12);
  EXPECT_EQ(d.pinion.material.name, "steel");
  EXPECT_DOUBLE_EQ(d.pinion.material.youngs_modulus, 210e9);
  // Rack: face and body width default to the pinion face width, 50 mm.
  EXPECT_DOUBLE_EQ(d.rack.face_width, 0.050);
  EXPECT_DOUBLE_EQ(d.rack.body_width, 0.050);
  // 50 x 80 mm: A = 4000 mm^2, I = 50 * 80^3 / 12 = 2133333.3 mm^4,
  // kappa A = 4000/1.2 = 3333.3 mm^2, neutral axis 40 mm below the root line.
  EXPECT_NEAR(d.rack.section.area, 4000e-6, 1e-15);
  EXPECT_NEAR(d.rack.section.second_moment, 2133333.333333e-12, 1e-15);
  EXPECT_NEAR(d.rack.section.shear_area, 3333.333333e-6, 1e-12);
  EXPECT_DOUBLE_EQ(d.rack.section.neutral_axis_depth, 0.040);
  EXPECT_NEAR(d.rack.tooth_offset, kPi * 0.010 / 2, 1e-15);
  // Effects and numerics default to the struct defaults.
  const Effects fx;
  EXPECT_EQ(d.effects.hertz, fx.hertz);
  EXPECT_EQ(d.effects.rack_span, fx.rack_span);
  EXPECT_EQ(d.numerics.quadrature_order, 16);
  EXPECT_EQ(d.numerics.positions_per_period, 100);
}

TEST(Loader, ExplicitSection) {
  const std::string text = std::string(kMinimal).replace(std::string(kMinimal).find("  body_height: 80 mm\n"), 21,
                                                         "  section: {area: 3000 mm^2, second_moment: 2.5e6 mm^4,"
                                                         " neutral_axis_depth: 30 mm}\n");
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_DOUBLE_EQ(d.rack.section.area, 3000e-6);
  EXPECT_DOUBLE_EQ(d.rack.section.second_moment, 2.5e-6);
  EXPECT_DOUBLE_EQ(d.rack.section.shear_area, 3000e-6 / 1.2);  // default area / 1.2
  EXPECT_DOUBLE_EQ(d.rack.section.neutral_axis_depth, 0.030);
  EXPECT_DOUBLE_EQ(d.rack.body_height, 0.0);
}

TEST(Loader, TorqueBecomesForceThroughTheBaseRadius) {
  std::string text = kMinimal;
  text.replace(text.find("force: 10 kN"), 12, "torque: 1 kN*m");
  const Drive d = load_problem_text(text, "t.yaml", {"pinion.pressure_angle=25 deg", "pinion.profile_shift=0.4"});
  // r_b = m z cos(a0) / 2 = 10 mm * 20 * cos 25 deg / 2 = 90.6308 mm, whatever the shift.
  EXPECT_NEAR(d.load.force, 1000.0 / (0.1 * std::cos(25 * kDeg)), 1e-9);
  EXPECT_DOUBLE_EQ(d.load.torque, 1000.0);
}

TEST(Loader, MaterialsAndFaults) {
  const std::string text = std::string(kMinimal) +
                           "materials:\n"
                           "  bronze: {E: 110 GPa, nu: 0.34}\n"
                           "faults:\n"
                           "  - {type: spall, member: rack, tooth: 3, start: 1 mm, length: 4 mm, width: 5 mm,"
                           " depth: 0.5 mm}\n";
  const Drive d = load_problem_text(text, "t.yaml", {"rack.material=bronze"});
  EXPECT_EQ(d.rack.material.name, "bronze");
  EXPECT_DOUBLE_EQ(d.rack.material.youngs_modulus, 110e9);
  EXPECT_EQ(d.pinion.material.name, "steel");  // built-in still there
  ASSERT_EQ(d.spalls.size(), 1u);
  EXPECT_EQ(d.spalls[0].member, Member::kRack);
  EXPECT_EQ(d.spalls[0].tooth, 3);
  EXPECT_DOUBLE_EQ(d.spalls[0].depth, 0.5e-3);
  EXPECT_EQ(d.spalls[0].name, "spall 1");
}

// -------------------------------------------------------------------- overrides

TEST(Overrides, ChangeAddAndRemoveKeys) {
  const Drive d = load_problem_text(kMinimal, "t.yaml",
                                    {"rack.span=1.2 m", "effects.rack_span=off", "effects.hertz=weber_banaschek",
                                     "rack.tooth_offset=10 mm",  // absent from the file: added
                                     "numerics.quadrature_order=8", "name=study point"});
  EXPECT_DOUBLE_EQ(d.rack.span, 1.2);
  EXPECT_EQ(d.effects.rack_span, RackSpanModel::kRigid);  // off = rigid
  EXPECT_EQ(d.effects.hertz, HertzModel::kWeberBanaschek);
  EXPECT_DOUBLE_EQ(d.rack.tooth_offset, 0.010);
  EXPECT_EQ(d.numerics.quadrature_order, 8);
  EXPECT_EQ(d.name, "study point");
  // Removing force and giving a torque switches the load kind.
  const Drive t = load_problem_text(kMinimal, "t.yaml", {"load.force=", "load.torque=100 N*m"});
  EXPECT_DOUBLE_EQ(t.load.torque, 100.0);
  // Flow values set whole maps.
  const Drive m = load_problem_text(kMinimal, "t.yaml", {"materials.steel={E: 200 GPa, nu: 0.28}"});
  EXPECT_DOUBLE_EQ(m.pinion.material.youngs_modulus, 200e9);
  // A list index can append to a list the file does not have.
  const Drive f = load_problem_text(kMinimal, "t.yaml",
                                    {"faults[0]={type: spall, tooth: 1, start: 1, length: 2, width: 3, depth: 0.4}"});
  ASSERT_EQ(f.spalls.size(), 1u);
  EXPECT_DOUBLE_EQ(f.spalls[0].depth, 0.4e-3);  // bare number = mm
}

TEST(Overrides, ErrorsNameTheCommandLine) {
  expect_error(kMinimal, {0, 0, "pinion.modul", "unknown key 'modul' in pinion; did you mean 'module'?",
                          "<command line>"},
               {"pinion.modul=12 mm"});
  expect_error(kMinimal, {0, 0, "rack.span", "'kg' is a unit of a mass but a length is expected", "<command line>"},
               {"rack.span=3 kg"});
  expect_error(kMinimal, {0, 0, "rack.span", "'deg' is a unit of an angle but a length is expected", "<command line>"}, {"rack.span=14 deg"});
  expect_error(kMinimal, {0, 0, "rack.span", "is not an assignment", "<command line>"}, {"rack.span"});
  expect_error(kMinimal, {0, 0, "pinion.teeth.x", "not a map", "<command line>"}, {"pinion.teeth.x=1"});
  expect_error(kMinimal, {0, 0, "effects.rack_span", "allowed: off | rigid | coupled | per_pair", "<command line>"},
               {"effects.rack_span=stiff"});
  expect_error(kMinimal, {0, 0, "", "YAML syntax error", "<command line>"}, {"rack.span=[1, 2"});
}

// ------------------------------------------------------------------ variants

const char* const kWithVariants =
    "pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\n"  // 1
    "rack: {body_height: 80 mm, span: 2 m}\n"                  // 2
    "load: {force: 10 kN}\n"                                   // 3
    "variants:\n"                                              // 4
    "  short: {rack: {span: 1 m}}\n"                           // 5
    "  wide:\n"                                                // 6
    "    pinion: {face_width: 80 mm}\n";                       // 7

TEST(Variants, MergeOverTheBaseAndOverridesWin) {
  EXPECT_DOUBLE_EQ(load_problem_text(kWithVariants, "t.yaml").rack.span, 2.0);
  const Drive s = load_problem_text(kWithVariants, "t.yaml", {"variant=short"});
  EXPECT_DOUBLE_EQ(s.rack.span, 1.0);
  EXPECT_DOUBLE_EQ(s.pinion.face_width, 0.050);  // merged, not replaced
  const Drive w = load_problem_text(kWithVariants, "t.yaml", {"variant=wide", "pinion.face_width=90 mm"});
  EXPECT_DOUBLE_EQ(w.pinion.face_width, 0.090);  // the override beats the variant
  EXPECT_DOUBLE_EQ(w.rack.face_width, 0.090);
  const Drive e = load_problem_text(kWithVariants, "t.yaml", {"variant=short", "variants.short.rack.span=0.5 m"});
  EXPECT_DOUBLE_EQ(e.rack.span, 0.5);
}

TEST(Variants, Errors) {
  expect_error(kWithVariants, {0, 0, "variant", "unknown variant 'long'; defined: short, wide", "<command line>"},
               {"variant=long"});
  expect_error(std::string(kWithVariants) + "variant: tall\n", {8, 10, "variant", "unknown variant 'tall'"});
  expect_error(kMinimal, {0, 0, "variant", "defines no variants", "<command line>"}, {"variant=x"});
  // An unselected variant is still checked: its error points into the variant.
  expect_error(std::string(kWithVariants) + "  bad: {rack: {spam: 1 m}}\n",
               {8, 16, "rack.spam", "did you mean 'span'?"});
}

// ------------------------------------------------------------ error classes

TEST(Errors, YamlSyntaxUsesYamlCppMark1Based) {
  // Bad indentation: yaml-cpp's mark is 0-based (2, 1) at the stray key.
  expect_error("pinion:\n  teeth: 20\n module: 3\n", {3, 2, "", "YAML syntax error: end of map not found"});
  // Unclosed flow list: yaml-cpp notices at the end of the input (line 3, column 1).
  expect_error("pinion:\n  teeth: [1, 2\n", {3, 1, "", "YAML syntax error: end of sequence flow not found"});
  // An empty key in a flow map.
  expect_error("pinion: {teeth: 20,, x}\n", {1, 20, "", "a key must be a plain name, found an empty key"});
}

TEST(Errors, UnknownKeySuggestsTheClosestKnownKey) {
  std::string text = kMinimal;
  text.replace(text.find("  face_width"), 12, "  face_widht");
  expect_error(text, {4, 3, "pinion.face_widht", "did you mean 'face_width'?"});
  expect_error(std::string(kMinimal) + "lood: {}\n", {10, 1, "lood", "at the top level; did you mean 'load'?"});
  // No suggestion when nothing is close.
  expect_error(std::string(kMinimal) + "zzzzzzzz: 1\n", {10, 1, "zzzzzzzz", "Allowed keys: name, description"});
}

TEST(Errors, DuplicateKeysAreDetected) {
  // yaml-cpp 0.7 keeps both silently (docs/dependencies.md, "yaml-cpp 0.7").
  expect_error(std::string(kMinimal) + "  force: 20 kN\n", {10, 3, "load.force", "duplicate key 'force' (first given at t.yaml:9:3)"});
}

TEST(Errors, WrongTypes) {
  std::string text = kMinimal;
  text.replace(text.find("10 mm"), 5, "[10, 12]");
  expect_error(text, {3, 11, "pinion.module", "expected a length (e.g. 60 mm), found a list"});
  text = kMinimal;
  text.replace(text.find("teeth: 20"), 9, "teeth: 20.5");
  expect_error(text, {2, 10, "pinion.teeth", "not a whole number"});
  expect_error(std::string(kMinimal) + "effects: {couple_term: maybe}\n",
               {10, 24, "effects.couple_term", "not a switch; allowed: on, off"});
  expect_error(std::string(kMinimal) + "effects: [1]\n", {10, 10, "effects", "expected a map of keys"});
  expect_error("- 1\n- 2\n", {1, 1, "", "a problem file is a map of sections"});
}

TEST(Errors, OutOfRangeStatesTheRangeWithUnits) {
  expect_error(kMinimal, {0, 0, "pinion.pressure_angle", "50 deg is out of range; allowed: 5 deg <= pressure_angle <= 45 deg",
                          "<command line>"},
               {"pinion.pressure_angle=50 deg"});
  std::string text = kMinimal;
  text.replace(text.find("50 mm"), 5, "-5 mm");
  expect_error(text, {4, 15, "pinion.face_width", "-5 mm is out of range; allowed: 0.1 mm <= face_width <= 10000 mm"});
  expect_error(std::string(kMinimal) + "materials: {steel: {E: 210 GPa, nu: 0.5}}\n",
               {10, 37, "materials.steel.nu", "0.5 is out of range; allowed: 0 <= nu < 0.5"});
  // Derived limit: the bore must lie inside the root circle r_f = 87.5 mm.
  expect_error(kMinimal, {0, 0, "pinion.bore_radius", "(the root radius r_f", "<command line>"},
               {"pinion.bore_radius=90 mm"});
  // Clearance: 0 (zero backlash) .. 1 module = 10 mm at m = 10 mm.
  expect_error(kMinimal, {0, 0, "mounting.clearance", "allowed: 0 mm <= clearance <= 10 mm", "<command line>"},
               {"mounting.clearance=11 mm"});
  // Pinion tooth index 0..z-1.
  expect_error(kMinimal, {0, 0, "faults[0].tooth", "allowed: 0 <= tooth <= 19", "<command line>"},
               {"faults[0]={type: spall, tooth: 20, start: 1, length: 2, width: 3, depth: 0.4}"});
  expect_error(kMinimal, {0, 0, "numerics.quadrature_order", "allowed: 2 <= quadrature_order <= 64", "<command line>"},
               {"numerics.quadrature_order=100"});
}

TEST(Errors, MissingRequiredKeysPointAtTheParentMap) {
  std::string text = kMinimal;
  text.erase(text.find("  module: 10 mm\n"), 16);
  // The pinion map starts at line 2, column 3 (its first key).
  expect_error(text, {2, 3, "pinion.module", "required key 'module' is missing; expected a length"});
  // A whole missing section: the top-level map's mark.
  expect_error("rack: {body_height: 80 mm, span: 2 m}\nload: {force: 1 kN}\n", {1, 1, "pinion.teeth", "is missing"});
  // Neither body_height nor section.
  text = kMinimal;
  text.erase(text.find("  body_height: 80 mm\n"), 21);
  expect_error(text, {6, 3, "rack.body_height", "rack.body_height (rectangular body"});
}

TEST(Errors, ExclusiveKeys) {
  expect_error(std::string(kMinimal) + "  torque: 5 kN*m\n", {10, 3, "load.torque", "not load.force and load.torque"});
  expect_error("pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\nrack: {body_height: 80 mm, span: 2 m}\nload: {}\n",
               {3, 7, "load.force", "load.force (normal mesh force"});
  expect_error(kMinimal, {0, 0, "rack.section", "not both", "<command line>"},
               {"rack.section={area: 1, second_moment: 1, neutral_axis_depth: 1}"});
}

TEST(Errors, UnknownMaterialListsTheDefinedOnes) {
  expect_error(std::string(kMinimal) + "materials: {brass: {E: 100 GPa, nu: 0.33}}\n",
               {0, 0, "pinion.material", "unknown material 'bronze'; defined: brass, steel", "<command line>"},
               {"pinion.material=bronze"});
  std::string text = kMinimal;
  text.replace(text.find("  face_width: 50 mm\n"), 20, "  face_width: 50 mm\n  material: bronze\n");
  expect_error(text, {5, 13, "pinion.material", "unknown material 'bronze'"});
}

TEST(Errors, MergeKeysAreRejected) {
  const std::string text =
      "base: &b {teeth: 20}\n"
      "pinion:\n"
      "  <<: *b\n"
      "  module: 10 mm\n";
  expect_error(text, {3, 3, "pinion.<<", "merge keys '<<' are not supported"});
}

TEST(Errors, DeepNestingIsCaught) {
  // 600 nested flow lists: yaml-cpp throws DeepRecursion at depth 500.
  const std::string deep = "pinion: " + std::string(600, '[') + std::string(600, ']') + "\n";
  try {
    load_problem_text(deep, "t.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().line, 1);
    EXPECT_GT(e.mark().column, 1);
    EXPECT_NE(std::string(e.message()).find("nesting deeper than 500"), std::string::npos) << e.what();
  }
  // 40 levels: accepted by yaml-cpp, refused by our own depth limit.
  const std::string forty = "pinion: " + std::string(40, '[') + std::string(40, ']') + "\n";
  expect_error(forty, {1, 40, "", "nesting deeper than 32 levels"});
}

TEST(Errors, AliasFanOutIsCaught) {
  // "Billion laughs": 10^6 logical nodes from 7 lines.
  const std::string bomb =
      "a: &a [x, x, x, x, x, x, x, x, x, x]\n"
      "b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
      "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\n"
      "d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
      "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\n"
      "f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]\n";
  try {
    load_problem_text(bomb, "t.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.message()).find("alias fan-out"), std::string::npos) << e.what();
    EXPECT_GE(e.mark().line, 1);
  }
}

TEST(Errors, UnreadableFile) {
  try {
    load_problem("/nonexistent/problem.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().file, "/nonexistent/problem.yaml");
    EXPECT_NE(std::string(e.message()).find("cannot open"), std::string::npos);
  }
}

TEST(KeyKinds, ForStudies) {
  EXPECT_EQ(problem_key_kind("pinion.module"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("pinion.pressure_angle"), QuantityKind::kAngle);
  EXPECT_EQ(problem_key_kind("materials.steel.E"), QuantityKind::kModulus);
  EXPECT_EQ(problem_key_kind("faults[2].depth"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("variants.mild.rack.span"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("load.torque"), QuantityKind::kTorque);
  EXPECT_EQ(problem_key_kind("pinion.teeth"), QuantityKind::kCount);
  EXPECT_EQ(problem_key_kind("effects.hertz"), std::nullopt);
  EXPECT_EQ(problem_key_kind("pinion.nonsense"), std::nullopt);
}

}  // namespace
}  // namespace rackopt
