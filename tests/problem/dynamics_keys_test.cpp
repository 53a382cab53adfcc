// The problem's `dynamics` section and effects.dynamics: each key with its
// units and default, each refusal at its file:line:column, --set and design
// values on the keys, and that the shipped problems' sections load.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "problem_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt {
namespace {

using test::expect_error;
using test::kMinimal;

// kMinimal is 9 lines: `dynamics:` is line 10, its first key line 11.
std::string with_dynamics(const std::string& body) { return std::string(kMinimal) + "dynamics:\n" + body; }

Drive load(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return load_problem_text(text, "t.yaml", overrides);
}

TEST(DynamicsSection, AbsentIsNotGivenAndTheDefaultsHold) {
  const Drive d = load(kMinimal);
  EXPECT_FALSE(d.dynamics.given());
  EXPECT_EQ(d.dynamics.moving_mass, 0.0);
  EXPECT_EQ(d.dynamics.drive_inertia, 0.0);
  EXPECT_EQ(d.dynamics.drive_stiffness, 0.0);  // rigid drive train
  EXPECT_EQ(d.dynamics.damping_ratio, 0.05);
  EXPECT_EQ(d.dynamics.speed_points, 0);  // no range: the dynamic model's default
  EXPECT_FALSE(d.effects.dynamics);
  // An empty section is the same as none.
  const Drive e = load(std::string(kMinimal) + "dynamics:\n");
  EXPECT_FALSE(e.dynamics.given());
  EXPECT_EQ(e.dynamics.damping_ratio, 0.05);
}

TEST(DynamicsSection, EveryKeyWithItsUnits) {
  const Drive d = load(with_dynamics("  moving_mass: 12 t\n"
                                     "  drive_inertia: 2.4 kg m^2\n"
                                     "  drive_stiffness: 5 MN*m/rad\n"
                                     "  damping_ratio: 0.08\n"
                                     "  speed_range: {from: 6 m/min, to: 1.5 m/s, points: 40}\n"));
  EXPECT_TRUE(d.dynamics.given());
  EXPECT_DOUBLE_EQ(d.dynamics.moving_mass, 12e3);
  EXPECT_DOUBLE_EQ(d.dynamics.drive_inertia, 2.4);
  EXPECT_DOUBLE_EQ(d.dynamics.drive_stiffness, 5e6);
  EXPECT_DOUBLE_EQ(d.dynamics.damping_ratio, 0.08);
  EXPECT_DOUBLE_EQ(d.dynamics.speed_from, 0.1);  // 6 m/min
  EXPECT_DOUBLE_EQ(d.dynamics.speed_to, 1.5);
  EXPECT_EQ(d.dynamics.speed_points, 40);
}

TEST(DynamicsSection, OtherSpellingsAndBareNumbers) {
  // Bare numbers are kg, kg*m^2, N*m/rad and m/s.
  const Drive bare = load(with_dynamics("  moving_mass: 1500\n  drive_inertia: 0.35\n  drive_stiffness: 2e5\n"
                                        "  speed_range: {from: 0.2, to: 0.8, points: 7}\n"));
  EXPECT_DOUBLE_EQ(bare.dynamics.moving_mass, 1500.0);
  EXPECT_DOUBLE_EQ(bare.dynamics.drive_inertia, 0.35);
  EXPECT_DOUBLE_EQ(bare.dynamics.drive_stiffness, 2e5);
  EXPECT_DOUBLE_EQ(bare.dynamics.speed_from, 0.2);
  EXPECT_DOUBLE_EQ(bare.dynamics.speed_to, 0.8);
  const Drive s = load(with_dynamics("  moving_mass: 1500 kg\n  drive_inertia: 35 kg*cm^2\n"
                                     "  drive_stiffness: 200 kN m/rad\n"));
  EXPECT_DOUBLE_EQ(s.dynamics.moving_mass, 1500.0);
  EXPECT_DOUBLE_EQ(s.dynamics.drive_inertia, 35e-4);
  EXPECT_DOUBLE_EQ(s.dynamics.drive_stiffness, 2e5);
  const Drive n = load(with_dynamics("  moving_mass: 1.5 t\n  drive_inertia: 1 kg*m^2\n"
                                     "  drive_stiffness: 2e5 N*m/rad\n"));
  EXPECT_DOUBLE_EQ(n.dynamics.drive_stiffness, 2e5);
  // Explicit zeros: no drive inertia beyond the pinion, a rigid drive train.
  const Drive z = load(with_dynamics("  moving_mass: 1.5 t\n  drive_inertia: 0\n  drive_stiffness: 0\n"));
  EXPECT_EQ(z.dynamics.drive_inertia, 0.0);
  EXPECT_EQ(z.dynamics.drive_stiffness, 0.0);
}

TEST(DynamicsSection, OneSpeedIsOnePoint) {
  const Drive d = load(with_dynamics("  moving_mass: 2 t\n  speed_range: {from: 0.5 m/s, to: 30 m/min, points: 1}\n"));
  EXPECT_DOUBLE_EQ(d.dynamics.speed_from, 0.5);
  EXPECT_DOUBLE_EQ(d.dynamics.speed_to, 0.5);
  EXPECT_EQ(d.dynamics.speed_points, 1);
}

TEST(DynamicsSection, OutOfRangeValuesAreRefusedWhereWritten) {
  // Line 11, the value after "  damping_ratio: " (column 18).
  expect_error(with_dynamics("  damping_ratio: 1\n"),
               {11, 18, "dynamics.damping_ratio", "allowed: 0 <= damping_ratio < 1"});
  expect_error(with_dynamics("  damping_ratio: 1.5\n"), {11, 18, "dynamics.damping_ratio", "never overdamped"});
  expect_error(with_dynamics("  damping_ratio: -0.01\n"), {11, 18, "dynamics.damping_ratio", "out of range"});
  expect_error(with_dynamics("  moving_mass: -3 t\n"), {11, 16, "dynamics.moving_mass", "out of range"});
  expect_error(with_dynamics("  moving_mass: 0\n"), {11, 16, "dynamics.moving_mass", "0.001 kg <= moving_mass"});
  expect_error(with_dynamics("  moving_mass: 12 kg m^2\n"),
               {11, 16, "dynamics.moving_mass", "'kg m^2' is a unit of a moment of inertia but a mass is expected"});
  expect_error(with_dynamics("  moving_mass: 1 t\n  drive_inertia: 3 kg\n"),
               {12, 18, "dynamics.drive_inertia", "'kg' is a unit of a mass but a moment of inertia is expected"});
  expect_error(with_dynamics("  moving_mass: 1 t\n  drive_inertia: -1\n"),
               {12, 18, "dynamics.drive_inertia", "out of range"});
  expect_error(with_dynamics("  moving_mass: 1 t\n  drive_inertia: 1\n  drive_stiffness: 5 N/m\n"),
               {13, 20, "dynamics.drive_stiffness", "'N/m' is a unit of a stiffness but a torsional stiffness"});
  expect_error(with_dynamics("  moving_mass: 1 t\n  drive_inertia: 1\n  drive_stiffness: -5\n"),
               {13, 20, "dynamics.drive_stiffness", "out of range"});
}

TEST(DynamicsSection, UnknownKeysAreNamed) {
  expect_error(with_dynamics("  moving_mas: 1 t\n"), {11, 3, "dynamics.moving_mas", "did you mean 'moving_mass'"});
  expect_error(with_dynamics("  speed_range: {from: 0.1, to: 0.2, point: 3}\n"),
               {11, 37, "dynamics.speed_range.point", "did you mean 'points'"});
}

TEST(DynamicsSection, ADriveSpringNeedsTheDriveInertia) {
  expect_error(with_dynamics("  moving_mass: 1 t\n  drive_stiffness: 5 MN*m/rad\n"),
               {12, 3, "dynamics.drive_stiffness", "give dynamics.drive_inertia"});
}

// Lines of the speed range tests: `  speed_range:` is line 11, its keys 12..14
// and their values at column 11 ("    from: "), 9 ("    to: "), 13 ("    points: ").
std::string with_range(const std::string& from, const std::string& to, const std::string& points) {
  return with_dynamics("  speed_range:\n    from: " + from + "\n    to: " + to + "\n    points: " + points + "\n");
}

TEST(DynamicsSpeedRange, ARangeThatReachesOrCrossesZeroIsRefused) {
  expect_error(with_range("0 m/s", "1 m/s", "5"),
               {12, 11, "dynamics.speed_range.from", "allowed: 0 m/s < from <= 50 m/s"});
  expect_error(with_range("-0.5 m/s", "1 m/s", "5"), {12, 11, "dynamics.speed_range.from", "0 m/s < from"});
  expect_error(with_range("-1 m/s", "-0.5 m/s", "5"), {12, 11, "dynamics.speed_range.from", "0 m/s < from"});
  expect_error(with_range("0.5 m/s", "0", "5"), {13, 9, "dynamics.speed_range.to", "0 m/s < to"});
  expect_error(with_range("0.5 m/s", "60 m/s", "5"), {13, 9, "dynamics.speed_range.to", "to <= 50 m/s"});
  expect_error(with_range("0.5 m/s", "1 kg", "5"), {13, 9, "dynamics.speed_range.to", "'kg' is a unit of a mass"});
}

TEST(DynamicsSpeedRange, ToBelowFromIsRefused) {
  expect_error(with_range("1 m/s", "30 m/min", "5"),
               {13, 9, "dynamics.speed_range.to", "allowed: 1 m/s <= to (the sweep runs up from speed_range.from"});
}

TEST(DynamicsSpeedRange, PointsFitTheRange) {
  expect_error(with_range("0.1", "1", "0"), {14, 13, "dynamics.speed_range.points", "allowed: 1 <= points <= 1000"});
  expect_error(with_range("0.1", "1", "1001"), {14, 13, "dynamics.speed_range.points", "points <= 1000"});
  expect_error(with_range("0.1", "1", "2.5"), {14, 13, "dynamics.speed_range.points", "not a whole number"});
  expect_error(with_range("0.1", "1", "1"),
               {14, 13, "dynamics.speed_range.points", "one point is one speed: give from == to"});
  expect_error(with_range("0.5", "0.5", "3"),
               {14, 13, "dynamics.speed_range.points", "from == to is a single speed"});
  // Every part is required.
  expect_error(with_dynamics("  speed_range: {from: 0.1, to: 1}\n"),
               {11, 16, "dynamics.speed_range.points", "required key 'points' is missing"});
  expect_error(with_dynamics("  speed_range: {to: 1, points: 4}\n"),
               {11, 16, "dynamics.speed_range.from", "required key 'from' is missing"});
  expect_error(with_dynamics("  speed_range: 0.5 m/s\n"), {11, 16, "dynamics.speed_range", "expected a map"});
}

// kMinimal has no speed; effects.dynamics needs one and a moving mass.
TEST(EffectsDynamics, OnNeedsAMovingMassAndASpeed) {
  const std::string fx = "effects:\n  dynamics: on\n";  // effects.dynamics on line 11, column 3
  expect_error(std::string(kMinimal) + "effects:\n  dynamics: on\n",
               {11, 3, "effects.dynamics", "give dynamics.moving_mass"});
  expect_error(std::string(kMinimal) + fx + "dynamics: {moving_mass: 2 t}\n",
               {11, 3, "effects.dynamics", "give load.speed"});
  const Drive d = load(std::string(kMinimal) + "  speed: 0.5 m/s\n" + fx + "dynamics: {moving_mass: 2 t}\n");
  EXPECT_TRUE(d.effects.dynamics);
  const Drive off = load(std::string(kMinimal) + "effects:\n  dynamics: off\n");
  EXPECT_FALSE(off.effects.dynamics);
  expect_error(std::string(kMinimal) + "effects:\n  dynamics: maybe\n", {11, 13, "effects.dynamics", "not a switch"});
}

TEST(DynamicsSection, SetOnTheCommandLine) {
  const Drive d = load(kMinimal, {"dynamics.moving_mass=12 t", "dynamics.damping_ratio=0.1",
                                  "dynamics.drive_inertia=3 kg*m^2", "dynamics.drive_stiffness=4 MN*m/rad",
                                  "dynamics.speed_range={from: 0.1 m/s, to: 1 m/s, points: 10}"});
  EXPECT_DOUBLE_EQ(d.dynamics.moving_mass, 12e3);
  EXPECT_DOUBLE_EQ(d.dynamics.damping_ratio, 0.1);
  EXPECT_DOUBLE_EQ(d.dynamics.drive_inertia, 3.0);
  EXPECT_DOUBLE_EQ(d.dynamics.drive_stiffness, 4e6);
  EXPECT_EQ(d.dynamics.speed_points, 10);
  const Drive s = load(with_dynamics("  moving_mass: 2 t\n  speed_range: {from: 0.1, to: 1, points: 10}\n"),
                       {"dynamics.speed_range.points=20", "load.speed=0.4 m/s", "effects.dynamics=on"});
  EXPECT_EQ(s.dynamics.speed_points, 20);
  EXPECT_TRUE(s.effects.dynamics);
  expect_error(kMinimal, {0, 0, "dynamics.damping_ratio", "damping_ratio < 1", "<command line>"},
               {"dynamics.damping_ratio=1"});
  expect_error(kMinimal, {0, 0, "dynamics.moving_mass", "is a unit of a length", "<command line>"},
               {"dynamics.moving_mass=12 mm"});
}

TEST(DynamicsSection, KeysHaveKindsAndTakeDesignValues) {
  EXPECT_EQ(problem_key_kind("dynamics.moving_mass"), QuantityKind::kMass);
  EXPECT_EQ(problem_key_kind("dynamics.drive_inertia"), QuantityKind::kInertia);
  EXPECT_EQ(problem_key_kind("dynamics.drive_stiffness"), QuantityKind::kTorsionalStiffness);
  EXPECT_EQ(problem_key_kind("dynamics.damping_ratio"), QuantityKind::kDimensionless);
  EXPECT_EQ(problem_key_kind("dynamics.speed_range.from"), QuantityKind::kSpeed);
  EXPECT_EQ(problem_key_kind("dynamics.speed_range.points"), QuantityKind::kCount);
  EXPECT_EQ(problem_key_kind("dynamics.speed_range"), std::nullopt);  // a map, not a number
  EXPECT_EQ(problem_key_kind("variants.heavy.dynamics.moving_mass"), QuantityKind::kMass);

  const ProblemTree tree = load_problem_tree(kMinimal, "t.yaml", {});
  const std::array<std::pair<std::string, double>, 4> values = {
      {{"dynamics.moving_mass", 7500.0},
       {"dynamics.damping_ratio", 0.07},
       {"dynamics.drive_inertia", 1.25},
       {"dynamics.drive_stiffness", 3.5e6}}};
  const Drive d = drive_with_values(tree, values);
  EXPECT_EQ(d.dynamics.moving_mass, 7500.0);  // written in SI with 17 digits: bit-exact
  EXPECT_EQ(d.dynamics.damping_ratio, 0.07);
  EXPECT_EQ(d.dynamics.drive_inertia, 1.25);
  EXPECT_EQ(d.dynamics.drive_stiffness, 3.5e6);
  // A design value out of range is refused as the file's would be.
  const std::array<std::pair<std::string, double>, 1> overdamped = {{{"dynamics.damping_ratio", 1.0}}};
  EXPECT_THROW(drive_with_values(tree, overdamped), InputError);
}

// The section changes no static input: the same file with and without it
// gives the same pinion, rack, load and effects.
TEST(DynamicsSection, ChangesNothingStatic) {
  const Drive a = load(kMinimal);
  const Drive b = load(with_dynamics("  moving_mass: 12 t\n  drive_inertia: 2 kg*m^2\n"
                                     "  drive_stiffness: 5 MN*m/rad\n"));
  EXPECT_EQ(a.load.force, b.load.force);
  EXPECT_EQ(a.load.dynamic_factor, b.load.dynamic_factor);
  EXPECT_EQ(a.pinion.module, b.pinion.module);
  EXPECT_EQ(a.rack.section.second_moment, b.rack.section.second_moment);
  EXPECT_EQ(a.effects.dynamics, b.effects.dynamics);
}

TEST(DynamicsSection, ShippedProblemsGiveTheirDrives) {
  for (const char* name : {"gantry_axis.yaml", "rack_railway.yaml", "ship_lift.yaml", "large_module.yaml"}) {
    SCOPED_TRACE(name);
    const Drive d = load_problem(test::problem_path(name));
    EXPECT_TRUE(d.dynamics.given());
    EXPECT_GT(d.dynamics.drive_inertia, 0.0);
    EXPECT_EQ(d.dynamics.damping_ratio, 0.05);
    EXPECT_FALSE(d.effects.dynamics);  // the static results stay as they were
  }
}

}  // namespace
}  // namespace rackopt
