// Size, mass, torque, power and cost metrics against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/geometry/pinion_section.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/input_error_expectations.hpp"

namespace rackopt::metrics {
namespace {

constexpr double kDeg = M_PI / 180.0;

// z 20, m 10 mm, 20 deg, b 50 mm, standard 1/1.25 teeth, rack body 80 x 50 mm,
// thrust 12 kN at 1.5 m/s through 90 % efficiency, bore 40 mm.
const char* const kGantry =
    "pinion: {teeth: 20, module: 10 mm, pressure_angle: 20 deg, face_width: 50 mm, bore_radius: 40 mm}\n"
    "rack: {body_height: 80 mm, span: 2 m}\n"
    "load: {thrust: 12 kN, speed: 1.5 m/s, efficiency: 0.9}\n"
    "duty: {travel_per_year: 2000 km/yr, stroke: 8 m}\n";

Drive gantry(const std::vector<std::string>& overrides = {}) { return load_problem_text(kGantry, "g.yaml", overrides); }

double value(const Drive& d, const char* metric, const MetricOptions& o = {}) {
  const std::vector<MetricRequest> q{parse_metric_request(metric)};
  const MetricValues v = evaluate_metrics(d, q, o);
  EXPECT_TRUE(v.values.at(0).ok) << metric << ": " << v.values.at(0).message;
  return v.values.at(0).value;
}

TEST(SizeMetrics, DiametersTorqueSpeedAndPowerByHand) {
  const Drive d = gantry();
  EXPECT_NEAR(value(d, "pinion_pitch_diameter"), 0.200, 1e-12);
  EXPECT_NEAR(value(d, "pinion_tip_diameter"), 0.220, 1e-12);
  EXPECT_NEAR(value(d, "pinion_torque"), 12e3 * 0.100, 1e-6);                 // F_t r = 1.2 kN m
  EXPECT_NEAR(value(d, "pinion_speed"), 1.5 / (M_PI * 0.200), 1e-12);         // 2.387 1/s = 143 1/min
  EXPECT_NEAR(value(d, "drive_power"), 12e3 * 1.5 / 0.9, 1e-6);               // 20 kW
  // A shifted pinion's tip diameter grows by 2 x m.
  EXPECT_NEAR(value(gantry({"pinion.profile_shift=0.4"}), "pinion_tip_diameter"), 0.228, 1e-12);
  // The torque for a fixed thrust grows with the module, the power does not.
  const Drive big = gantry({"pinion.module=12 mm"});
  EXPECT_NEAR(value(big, "pinion_torque"), 12e3 * 0.120, 1e-6);
  EXPECT_NEAR(value(big, "drive_power"), 20e3, 1e-6);
}

TEST(SizeMetrics, RackMassAndHeightByHand) {
  const Drive d = gantry();
  // Trapezoid tooth: width 15.708 + 2 x 12.5 tan 20 = 24.807 mm at the root,
  // 15.708 - 2 x 10 tan 20 = 8.429 mm at the tip, 22.5 mm high: 373.9 mm^2,
  // 50 mm wide every 31.416 mm: 595.1 mm^2 per metre; body 80 x 50 mm.
  const double t = std::tan(20 * kDeg);
  const double tooth = 0.5 * ((5 * M_PI + 25 * t) + (5 * M_PI - 20 * t)) * 22.5 * 1e-6;
  EXPECT_NEAR(tooth, 373.9e-6, 0.1e-6);
  const double per_metre = 7850 * (0.08 * 0.05 + tooth * 0.05 / (M_PI * 0.01));
  EXPECT_NEAR(value(d, "rack_mass_per_metre"), per_metre, 1e-9);
  EXPECT_NEAR(per_metre, 36.07, 0.01);
  EXPECT_NEAR(value(d, "rack_section_height"), 0.080 + 0.0225, 1e-12);
  EXPECT_NEAR(value(d, "face_width_ratio"), 5.0, 1e-12);  // 50 mm / 10 mm
  EXPECT_NEAR(value(gantry({"rack.face_width=30 mm"}), "face_width_ratio"), 3.0, 1e-12);  // the narrower face
}

TEST(SizeMetrics, PinionMassIsDensityFaceWidthAndOutlineLessBore) {
  const Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  const double area = pinion_outline_area(d.pinion, g);
  EXPECT_NEAR(value(d, "pinion_mass"), 7850 * 0.05 * (area - M_PI * 0.04 * 0.04), 1e-9);
  // About the pitch disc less the bore: 7850 x 0.05 x pi (0.1^2 - 0.04^2) = 10.36 kg.
  EXPECT_NEAR(value(d, "pinion_mass"), 10.36, 0.25);
  // Twice the face width, twice the mass; a lighter material, proportionally lighter.
  EXPECT_NEAR(value(gantry({"pinion.face_width=100 mm"}), "pinion_mass"), 2 * value(d, "pinion_mass"), 1e-9);
}

TEST(SizeMetrics, CostPerMetreCombinesTheWeightedParts) {
  const Drive d = gantry();
  MetricOptions o;
  o.cost = CostWeights{2.0, 5.0, 300.0, 0.0};  // rack length 0: the duty's 8 m stroke
  const double expected = 2.0 * value(d, "rack_mass_per_metre") + 300.0 / 2.0 + 5.0 * value(d, "pinion_mass") / 8.0;
  EXPECT_NEAR(value(d, "cost_per_metre", o), expected, 1e-9);
  o.cost.rack_length = 16.0;
  EXPECT_NEAR(value(d, "cost_per_metre", o), expected - 5.0 * value(d, "pinion_mass") / 16.0, 1e-9);
  // Default weights: kg per metre of rack plus the pinion per metre of stroke.
  EXPECT_NEAR(value(d, "cost_per_metre"), value(d, "rack_mass_per_metre") + value(d, "pinion_mass") / 8.0, 1e-9);
}

TEST(SizeMetrics, MissingInputsAreNamed) {
  Drive d = gantry();
  d.load.speed = 0;
  const std::vector<MetricRequest> power{parse_metric_request("drive_power")};
  test_support::expect_input_error([&] { evaluate_metrics(d, power); }, {.key = "load.speed"});
  d = gantry();
  d.duty.stroke = 0;
  const std::vector<MetricRequest> cost{parse_metric_request("cost_per_metre")};
  test_support::expect_input_error([&] { evaluate_metrics(d, cost); }, {.key = "cost.rack_length"});
  MetricOptions o;
  o.cost.pinion_per_kg = 0;  // no pinion share: no length needed
  EXPECT_NO_THROW(evaluate_metrics(d, cost, o));
}

}  // namespace
}  // namespace rackopt::metrics
