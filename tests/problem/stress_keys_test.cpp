// Stress inputs as problem keys: material allowables, ISO 6336 load factors
// and the rack root round. Units, defaults, errors with file:line:column,
// overrides, design values and key kinds.
//
// Expected numbers are hand arithmetic written next to the assertion, or the
// ISO 6336-5 formulas the bundled files cite, never loader output.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "problem_test_support.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

using test::expect_error;
using test::Expected;
using test::kMinimal;
using test::problem_path;

TEST(StressKeys, DefaultsMeanNotGivenOrOne) {
  const Drive d = load_problem_text(kMinimal, "t.yaml");
  EXPECT_EQ(d.pinion.material.allowable_bending, 0.0);
  EXPECT_EQ(d.pinion.material.allowable_contact, 0.0);
  EXPECT_EQ(d.rack.material.allowable_bending, 0.0);
  EXPECT_EQ(d.rack.material.allowable_contact, 0.0);
  EXPECT_EQ(d.load.application_factor, 1.0);
  EXPECT_EQ(d.load.dynamic_factor, 1.0);
  EXPECT_EQ(d.load.face_load_factor, 1.0);
  EXPECT_EQ(d.load.face_load_factor_bending, 0.0);  // derived from K_Hbeta by the metrics
  EXPECT_EQ(d.load.transverse_load_factor, 1.0);
  EXPECT_EQ(d.rack.root_radius, 0.0);  // = the cutter tip radius
}

// Each member takes the allowables of its own material.
TEST(StressKeys, EveryKeyToSIAndMembersTakeTheirMaterials) {
  const std::string text =
      "materials:\n"
      "  soft: {E: 202 GPa, nu: 0.3, allowable_bending: \"400 N/mm^2\", allowable_contact: 1100 MPa}\n"
      "  hard: {E: 209 GPa, nu: 0.29, allowable_bending: 0.43 GPa, allowable_contact: 1.2e9 Pa}\n"
      "pinion: {teeth: 20, module: 10 mm, face_width: 50 mm, material: hard}\n"
      "rack: {body_height: 80 mm, span: 2 m, material: soft, root_radius: 0.4 cm}\n"
      "load:\n"
      "  torque: 1 kN*m\n"
      "  application_factor: 1.25\n"
      "  dynamic_factor: 1.1\n"
      "  face_load_factor: 1.3\n"
      "  face_load_factor_bending: 1.2\n"
      "  transverse_load_factor: 1.05\n";
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_DOUBLE_EQ(d.pinion.material.allowable_bending, 430e6);
  EXPECT_DOUBLE_EQ(d.pinion.material.allowable_contact, 1200e6);
  EXPECT_DOUBLE_EQ(d.rack.material.allowable_bending, 400e6);
  EXPECT_DOUBLE_EQ(d.rack.material.allowable_contact, 1100e6);
  EXPECT_DOUBLE_EQ(d.rack.root_radius, 4e-3);
  EXPECT_DOUBLE_EQ(d.load.application_factor, 1.25);
  EXPECT_DOUBLE_EQ(d.load.dynamic_factor, 1.1);
  EXPECT_DOUBLE_EQ(d.load.face_load_factor, 1.3);
  EXPECT_DOUBLE_EQ(d.load.face_load_factor_bending, 1.2);
  EXPECT_DOUBLE_EQ(d.load.transverse_load_factor, 1.05);
  // The load factors do not touch the model load: F = T / r_b, r_b = m z cos(20 deg) / 2.
  EXPECT_NEAR(d.load.force, 1000.0 / (0.5 * 0.010 * 20 * std::cos(20 * M_PI / 180)), 1e-9);
  // Factors exactly 1 and 10 are the ends of the closed range.
  const Drive edge = load_problem_text(std::string(kMinimal) + "  application_factor: 1\n  dynamic_factor: 10\n", "t.yaml");
  EXPECT_EQ(edge.load.application_factor, 1.0);
  EXPECT_EQ(edge.load.dynamic_factor, 10.0);
}

TEST(StressKeys, BareNumbersTakeTheKindsDefaultUnit) {
  // Modulus kind: a bare number is GPa; dimensionless factors are plain; length is mm.
  const std::string text =
      "materials: {steel: {E: 210, nu: 0.3, allowable_bending: 0.5, allowable_contact: 1.5}}\n"
      "pinion: {teeth: 20, module: 10, face_width: 50}\n"
      "rack: {body_height: 80, span: 2000, root_radius: 3.8}\n"
      "load: {force: 10000, application_factor: 2}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_DOUBLE_EQ(d.pinion.material.allowable_bending, 0.5e9);
  EXPECT_DOUBLE_EQ(d.rack.material.allowable_contact, 1.5e9);
  EXPECT_DOUBLE_EQ(d.rack.root_radius, 3.8e-3);
  EXPECT_DOUBLE_EQ(d.load.application_factor, 2.0);
}

TEST(StressKeys, ErrorsPointAtTheValue) {
  // "430" is 430 GPa: out of range, and the message says why.
  expect_error("materials:\n  steel: {E: 210 GPa, nu: 0.3, allowable_bending: 430}\n" + std::string(kMinimal),
               {2, 51, "materials.steel.allowable_bending", "a bare number means GPa: write e.g. 430 MPa"});
  expect_error("materials:\n  steel: {E: 210 GPa, nu: 0.3, allowable_contact: 0 MPa}\n" + std::string(kMinimal),
               {2, 51, "materials.steel.allowable_contact", "0.001 GPa <= allowable_contact <= 5 GPa"});
  expect_error("materials:\n  steel: {E: 210 GPa, nu: 0.3, allowable_contact: 1200 mm}\n" + std::string(kMinimal),
               {2, 51, "materials.steel.allowable_contact", "a length but a modulus is expected"});
  // Load factors below 1 are refused, not warned about.
  expect_error(std::string(kMinimal) + "  application_factor: 0.9\n",
               {10, 23, "load.application_factor", "1 <= application_factor <= 10 (ISO 6336 load factors are >= 1"});
  expect_error(std::string(kMinimal) + "  face_load_factor_bending: 0\n",
               {10, 29, "load.face_load_factor_bending", "out of range"});
  expect_error(std::string(kMinimal) + "  transverse_load_factor: 11\n",
               {10, 27, "load.transverse_load_factor", "<= 10"});
  expect_error(std::string(kMinimal) + "  dynamic_factor: 1.1 mm\n", {10, 19, "load.dynamic_factor", "mm"});
  expect_error(
      "pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\n"
      "rack: {body_height: 80 mm, span: 2 m, root_radius: -1 mm}\n"
      "load: {force: 10 kN}\n",
      {2, 52, "rack.root_radius", "0.001 mm <= root_radius <= 1000 mm (0 = the pinion cutter tip radius)"});
}

TEST(StressKeys, UnknownKeysSuggestTheNewOnes) {
  expect_error("materials:\n  steel: {E: 210 GPa, nu: 0.3, allowable_bend: 400 MPa}\n" + std::string(kMinimal),
               {2, 32, "materials.steel.allowable_bend", "did you mean 'allowable_bending'?"});
  expect_error(std::string(kMinimal) + "  aplication_factor: 1.2\n",
               {10, 3, "load.aplication_factor", "did you mean 'application_factor'?"});
  expect_error(std::string(kMinimal) + "  face_load_factor_bend: 1.2\n",
               {10, 3, "load.face_load_factor_bend", "did you mean 'face_load_factor_bending'?"});
  expect_error("pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\n"
               "rack: {body_height: 80 mm, span: 2 m, root_raduis: 4 mm}\n"
               "load: {force: 10 kN}\n",
               {2, 39, "rack.root_raduis", "did you mean 'root_radius'?"});
  // The allowed-keys list names the new load keys.
  expect_error(std::string(kMinimal) + "  k_a: 1.2\n", {10, 3, "load.k_a", "application_factor, dynamic_factor"});
}

TEST(StressKeys, OverridesAndDesignValues) {
  const std::string text = "materials:\n  steel: {E: 210 GPa, nu: 0.3}\n" + std::string(kMinimal);
  const Drive d = load_problem_text(text, "t.yaml",
                                    {"materials.steel.allowable_bending=500 MPa", "load.face_load_factor=1.4",
                                     "rack.root_radius=5 mm"});
  EXPECT_DOUBLE_EQ(d.pinion.material.allowable_bending, 500e6);
  EXPECT_DOUBLE_EQ(d.rack.material.allowable_bending, 500e6);  // the same material
  EXPECT_DOUBLE_EQ(d.load.face_load_factor, 1.4);
  EXPECT_DOUBLE_EQ(d.rack.root_radius, 5e-3);
  expect_error(text, {0, 0, "load.dynamic_factor", "out of range", "<command line>"}, {"load.dynamic_factor=0.5"});

  // Studies vary them as design values in SI.
  const ProblemTree tree = load_problem_tree(text, "t.yaml");
  const std::vector<std::pair<std::string, double>> x{{"materials.steel.allowable_contact", 1.2e9},
                                                      {"load.application_factor", 1.75},
                                                      {"load.face_load_factor_bending", 1.15},
                                                      {"rack.root_radius", 3.5e-3}};
  const Drive v = drive_with_values(tree, x);
  EXPECT_EQ(v.rack.material.allowable_contact, 1.2e9);
  EXPECT_EQ(v.load.application_factor, 1.75);
  EXPECT_EQ(v.load.face_load_factor_bending, 1.15);
  EXPECT_EQ(v.rack.root_radius, 3.5e-3);
  const std::vector<std::pair<std::string, double>> bad{{"load.application_factor", 0.8}};
  EXPECT_THROW(drive_with_values(tree, bad), InputError);
}

TEST(StressKeys, KeyKindsForStudies) {
  EXPECT_EQ(problem_key_kind("materials.steel.allowable_bending"), QuantityKind::kModulus);
  EXPECT_EQ(problem_key_kind("materials.rack_steel.allowable_contact"), QuantityKind::kModulus);
  EXPECT_EQ(problem_key_kind("variants.hard.materials.steel.allowable_contact"), QuantityKind::kModulus);
  for (const char* k : {"load.application_factor", "load.dynamic_factor", "load.face_load_factor",
                        "load.face_load_factor_bending", "load.transverse_load_factor"}) {
    EXPECT_EQ(problem_key_kind(k), QuantityKind::kDimensionless) << k;
  }
  EXPECT_EQ(problem_key_kind("rack.root_radius"), QuantityKind::kLength);
  EXPECT_EQ(problem_key_kind("load.application"), std::nullopt);
  EXPECT_EQ(problem_key_kind("materials.steel.allowable"), std::nullopt);
}

// The bundled files carry the ISO 6336-5 MQ values their comments derive
// (sigma_FP = 2 sigma_Flim, sigma_HP = sigma_Hlim, every other factor 1),
// rounded to 1 MPa in the files.
TEST(StressKeys, BundledProblemsCarryIso6336Allowables) {
  {
    const Drive d = load_problem(problem_path("rack_railway.yaml"));
    const double hv = 300;  // assumed QT alloy steel
    EXPECT_NEAR(d.pinion.material.allowable_bending, 2 * (0.423 * hv + 104) * 1e6, 0.5e6);
    EXPECT_NEAR(d.pinion.material.allowable_contact, (1.313 * hv + 188) * 1e6, 0.5e6);
    EXPECT_EQ(d.rack.material.allowable_bending, d.pinion.material.allowable_bending);
    EXPECT_EQ(d.rack.material.allowable_contact, d.pinion.material.allowable_contact);
    EXPECT_EQ(d.load.application_factor, 1.0);
    EXPECT_EQ(d.load.face_load_factor_bending, 0.0);
  }
  {
    const Drive d = load_problem(problem_path("ship_lift.yaml"));
    // Induction hardened, MQ, at the tops of the ranges (596 HB ~ 630 HV is above them).
    for (const Material* m : {&d.pinion.material, &d.rack.material}) {
      EXPECT_NEAR(m->allowable_bending, 2 * (0.138 * 570 + 290) * 1e6, 0.5e6) << m->name;
      EXPECT_NEAR(m->allowable_contact, (0.740 * 615 + 602) * 1e6, 0.5e6) << m->name;
    }
    EXPECT_EQ(d.pinion.material.name, "pinion_steel");
    EXPECT_EQ(d.rack.material.name, "rack_steel");
    EXPECT_EQ(d.load.dynamic_factor, 1.0);
  }
}

}  // namespace
}  // namespace rackopt
