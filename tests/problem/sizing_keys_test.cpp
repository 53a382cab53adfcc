// Problem keys for sizing: the load as rack thrust, drive speed and
// efficiency, material density, duty as travel, and the refusal of a mesh
// with every compliance switched off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "problem_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

using test::kDeg;

// Lines matter to the error tests.
const char* const kWithoutLoad =
    "pinion:\n"                    // 1
    "  teeth: 20\n"                // 2
    "  module: 10 mm\n"            // 3
    "  face_width: 50 mm\n"        // 4
    "  pressure_angle: 20 deg\n"   // 5
    "rack:\n"                      // 6
    "  body_height: 80 mm\n"       // 7
    "  span: 2 m\n";               // 8

InputError error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    load_problem_text(text, "t.yaml", overrides);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for\n" << text;
  return InputError({}, "", "");
}

TEST(LoadAsThrust, NormalForceAndTorqueFollowTheThrustAsPressureAngleAndModuleVary) {
  const std::string text = std::string(kWithoutLoad) + "load: {thrust: 12 kN, speed: 90 m/min, efficiency: 0.9}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_DOUBLE_EQ(d.load.thrust, 12e3);
  EXPECT_DOUBLE_EQ(d.load.torque, 0.0);
  EXPECT_NEAR(d.load.force, 12e3 / std::cos(20 * kDeg), 1e-9);  // F_n = F_t / cos a0 = 12.770 kN
  EXPECT_DOUBLE_EQ(d.load.speed, 1.5);
  EXPECT_DOUBLE_EQ(d.load.efficiency, 0.9);
  // The thrust stays fixed when the pressure angle or module changes.
  const Drive d25 = load_problem_text(text, "t.yaml", {"pinion.pressure_angle=25 deg", "pinion.module=16 mm"});
  EXPECT_DOUBLE_EQ(d25.load.thrust, 12e3);
  EXPECT_NEAR(d25.load.force, 12e3 / std::cos(25 * kDeg), 1e-9);  // 13.241 kN
  // Torque input: F_n = T / r_b, so the thrust it implies is T / r.
  const Drive dt = load_problem_text(std::string(kWithoutLoad) + "load: {torque: 1.2 kN*m}\n", "t.yaml");
  const double r = 0.5 * 10e-3 * 20;
  EXPECT_NEAR(dt.load.force * std::cos(20 * kDeg), 1.2e3 / r, 1e-6);
  // Defaults: no speed, efficiency 1.
  EXPECT_DOUBLE_EQ(dt.load.speed, 0.0);
  EXPECT_DOUBLE_EQ(dt.load.efficiency, 1.0);
}

TEST(LoadAsThrust, OnlyOneOfForceTorqueThrust) {
  const InputError e = error_of(std::string(kWithoutLoad) + "load:\n  force: 1 kN\n  thrust: 2 kN\n");
  EXPECT_EQ(e.key_path(), "load.thrust");
  EXPECT_EQ(e.mark().line, 11);
  EXPECT_NE(e.message().find("not load.force and load.thrust"), std::string::npos) << e.message();
  const InputError s = error_of(std::string(kWithoutLoad) + "load: {thrust: 2 kN, speed: 5 kg}\n");
  EXPECT_EQ(s.key_path(), "load.speed");
  const InputError f = error_of(std::string(kWithoutLoad) + "load: {thrust: 2 kN, efficiency: 1.2}\n");
  EXPECT_EQ(f.key_path(), "load.efficiency");
}

TEST(MaterialDensity, DefaultSteelAndChecked) {
  const Drive d = load_problem_text(std::string(kWithoutLoad) + "load: {force: 1 kN}\n", "t.yaml");
  EXPECT_DOUBLE_EQ(d.pinion.material.density, 7850.0);
  const Drive p = load_problem_text(std::string(kWithoutLoad) +
                                        "  material: pom\nload: {force: 1 kN}\nmaterials:\n"
                                        "  pom: {E: 3 GPa, nu: 0.35, density: 1.41 g/cm^3}\n",
                                    "t.yaml");
  EXPECT_DOUBLE_EQ(p.rack.material.density, 1410.0);
  const InputError e = error_of(std::string(kWithoutLoad) + "load: {force: 1 kN}\nmaterials:\n"
                                                     "  steel: {E: 210 GPa, nu: 0.3, density: 7.85}\n");
  EXPECT_EQ(e.key_path(), "materials.steel.density");  // 7.85 kg/m^3: a unit was forgotten
}

TEST(DutyAsTravel, RackAndPinionMeshCountsFollowFromTravelStrokeAndModule) {
  const std::string text = std::string(kWithoutLoad) + "load: {force: 1 kN}\nduty: {travel_per_year: 2000 km/yr, stroke: 4 m}\n";
  const Drive d = load_problem_text(text, "t.yaml");
  EXPECT_NEAR(d.duty.travel_per_year, 2e6, 1e-6);
  EXPECT_DOUBLE_EQ(d.duty.stroke, 4.0);
  EXPECT_NEAR(d.duty.rack_meshes_per_year, 2e6 / 4, 1e-6);                // each stroke passes a tooth once
  EXPECT_NEAR(d.duty.pinion_meshes_per_year, 2e6 / (M_PI * 0.2), 1e-6);  // once per revolution, pi m z = 0.628 m
  // Strokes x stroke is the same travel; a larger module means fewer pinion revolutions.
  const Drive s = load_problem_text(std::string(kWithoutLoad) + "load: {force: 1 kN}\nduty: {strokes_per_year: 5e5, stroke: 4 m}\n",
                                    "t.yaml", {"pinion.module=20 mm"});
  EXPECT_NEAR(s.duty.rack_meshes_per_year, 5e5, 1e-6);
  EXPECT_NEAR(s.duty.pinion_meshes_per_year, 2e6 / (M_PI * 0.4), 1e-6);
}

TEST(DutyAsTravel, ConflictsAndMissingPartsAreNamed) {
  const std::string base = std::string(kWithoutLoad) + "load: {force: 1 kN}\nduty:\n";
  InputError e = error_of(base + "  rack_meshes_per_year: 1e4\n  stroke: 4 m\n  travel_per_year: 1 km/yr\n");
  EXPECT_EQ(e.key_path(), "duty.stroke");
  EXPECT_NE(e.message().find("duty.rack_meshes_per_year is also given"), std::string::npos) << e.message();
  e = error_of(base + "  stroke: 4 m\n");
  EXPECT_EQ(e.key_path(), "duty.travel_per_year");
  e = error_of(base + "  travel_per_year: 1 km/yr\n");
  EXPECT_EQ(e.key_path(), "duty.stroke");
  e = error_of(base + "  stroke: 4 m\n  travel_per_year: 1 km/yr\n  strokes_per_year: 10\n");
  EXPECT_EQ(e.key_path(), "duty.strokes_per_year");
  e = error_of(base + "  stroke: 4 m\n  travel_per_year: 1 km/yr\n  pinion_meshes_per_year: 10\n");
  EXPECT_EQ(e.key_path(), "duty.pinion_meshes_per_year");
  e = error_of(base + "  stroke: 4 m\n  travel_per_year: 2000\n");  // a bare number is m/s
  EXPECT_EQ(e.key_path(), "duty.travel_per_year");
}

TEST(Effects, EveryComplianceOffIsAnInputError) {
  const std::string text = std::string(kWithoutLoad) + "load: {force: 1 kN}\neffects:\n  pinion_tooth: off\n"
                           "  fillet_foundation: off\n  rack_tooth: off\n  hertz: off\n  rack_span: rigid\n";
  const InputError e = error_of(text);
  EXPECT_EQ(e.key_path(), "effects");
  EXPECT_EQ(e.mark().line, 10);
  EXPECT_NE(e.message().find("rigid"), std::string::npos) << e.message();
  // One compliance left is a valid (if partial) model.
  EXPECT_NO_THROW(load_problem_text(text, "t.yaml", {"effects.hertz=linear"}));
}

}  // namespace
}  // namespace rackopt
