// Stress metrics read their inputs from the problem (material allowables,
// load factors, rack root round); MetricOptions values > 0 still win; a
// missing allowable names the problem key to add.
//
// Independent numbers: the Hertz pitch-point pressure of the ship lift in
// closed form (docs/models/wear.md), ISO 6336-3's K_Fbeta = K_Hbeta^N_F by hand,
// and the linearity of the stresses in the load factors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "metrics_test_support.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/input_error_expectations.hpp"

namespace rackopt::metrics {
namespace {

using test::eval;
using test::kPi;
using test::path;

// ISO 6336-3 N_F for b/h below 3 (both bundled drives): b/h = 3.
constexpr double kNfShort = 9.0 / 13.0;

// Ship lift, the wear paper's data: sigma_H = Z_eps * p0, p0 the Hertz pressure of a
// cylinder of radius r sin a0 on a flat under F_n / b, all by hand.
TEST(StressInputs, ShipLiftSafetyFromTheProblemsAllowablesMatchesAHandComputation) {
  const Drive d = load_problem(path("ship_lift"));
  const MetricValues v = eval(d, {"contact_ratio", "contact_stress", "contact_safety", "root_bending_stress",
                                  "rack_root_bending_stress", "root_bending_safety"});
  ASSERT_TRUE(v.all_ok()) << v.first_failure()->message;

  const double a0 = 20 * kPi / 180, r = 0.063 * 16 / 2, b = 0.120;
  const double force = 453e3 / (r * std::cos(a0));
  const double inv_estar = (1 - 0.271 * 0.271) / 209e9 + (1 - 0.3 * 0.3) / 202e9;
  const double p0 = std::sqrt(force / b / (kPi * inv_estar * r * std::sin(a0)));
  EXPECT_NEAR(p0, 1283e6, 1e6);  // docs/models/wear.md
  const double eps = v.at("contact_ratio").value;
  EXPECT_NEAR(eps, 1.536, 0.001);  // docs/models/reliability.md
  const double sigma_h = p0 * std::sqrt((4 - eps) / 3);
  EXPECT_NEAR(v.at("contact_stress").value, sigma_h, 1e-9 * sigma_h);
  // materials.*.allowable_contact: 1057 MPa for both members.
  EXPECT_NEAR(v.at("contact_safety").value, 1057e6 / sigma_h, 1e-9);
  // About 0.91: the ship lift at the seed's torque exceeds the MQ endurance
  // limit (the file's comment explains why that is plausible).
  EXPECT_NEAR(v.at("contact_safety").value, 0.91, 0.01);
  // materials.*.allowable_bending: 737 MPa for both members.
  const double sp = 737e6 / v.at("root_bending_stress").value;
  const double sr = 737e6 / v.at("rack_root_bending_stress").value;
  EXPECT_DOUBLE_EQ(v.at("root_bending_safety").value, std::min(sp, sr));
  EXPECT_EQ(v.at("root_bending_safety").message, sp <= sr ? "pinion governs" : "rack governs");
}

// Each member's allowable comes from its own material.
TEST(StressInputs, EachMemberUsesItsMaterial) {
  const ProblemTree tree = load_problem_tree_file(path("ship_lift"), {"materials.rack_steel.allowable_bending=300 MPa",
                                                                     "materials.pinion_steel.allowable_contact=900 MPa"});
  const Drive d = drive_from_tree(tree);
  const MetricValues v =
      eval(d, {"root_bending_stress", "rack_root_bending_stress", "root_bending_safety", "contact_stress", "contact_safety"});
  ASSERT_TRUE(v.all_ok());
  const double sp = 737e6 / v.values[0].value, sr = 300e6 / v.values[1].value;
  EXPECT_DOUBLE_EQ(v.values[2].value, std::min(sp, sr));
  EXPECT_DOUBLE_EQ(v.values[4].value, 900e6 / v.values[3].value);
  EXPECT_EQ(v.values[4].message, "pinion governs");
}

TEST(StressInputs, LoadFactorsFromTheProblem) {
  const Drive base = load_problem(path("ship_lift"));
  const MetricValues v0 = eval(base, {"root_bending_stress", "rack_root_bending_stress", "contact_stress"});
  ASSERT_TRUE(v0.all_ok());
  const std::vector<std::string> factors{"load.application_factor=1.5", "load.dynamic_factor=1.05",
                                         "load.face_load_factor=1.2", "load.transverse_load_factor=1.1"};
  {
    // K_Fbeta absent: 1.2^N_F with b/h = 120 / (2.25 x 63) = 0.85 < 3, so N_F = 9/13.
    const Drive d = load_problem(path("ship_lift"), factors);
    const MetricValues v = eval(d, {"root_bending_stress", "rack_root_bending_stress", "contact_stress"});
    const double kf = 1.5 * 1.05 * std::pow(1.2, kNfShort) * 1.1;
    EXPECT_NEAR(v.values[0].value / v0.values[0].value, kf, 1e-12);
    EXPECT_NEAR(v.values[1].value / v0.values[1].value, kf, 1e-12);
    EXPECT_NEAR(v.values[2].value / v0.values[2].value, std::sqrt(1.5 * 1.05 * 1.2 * 1.1), 1e-12);
  }
  {
    std::vector<std::string> with_kfb = factors;
    with_kfb.push_back("load.face_load_factor_bending=1.3");
    const Drive d = load_problem(path("ship_lift"), with_kfb);
    const MetricValues v = eval(d, {"root_bending_stress"});
    EXPECT_NEAR(v.values[0].value / v0.values[0].value, 1.5 * 1.05 * 1.3 * 1.1, 1e-12);
  }
}

TEST(StressInputs, MetricOptionsStillWin) {
  const Drive d = load_problem(path("ship_lift"), {"load.application_factor=1.5", "rack.root_radius=10 mm"});
  const MetricValues v0 = eval(d, {"root_bending_stress", "rack_root_bending_stress", "contact_stress"});
  ASSERT_TRUE(v0.all_ok());
  MetricOptions o;
  o.allowable_bending_pinion = 500e6;   // drive: 737 MPa
  o.allowable_contact_rack = 900e6;     // drive: 1057 MPa
  o.load_factors.application = 2.0;     // drive: 1.5
  o.load_factors.face_contact = 1.44;   // drive: 1; K_Fbeta (not given) follows it
  const MetricValues v = eval(d, {"root_bending_stress", "rack_root_bending_stress", "root_bending_safety",
                                  "contact_stress", "contact_safety"}, o);
  ASSERT_TRUE(v.all_ok());
  const double kf = 2.0 / 1.5 * std::pow(1.44, kNfShort);
  EXPECT_NEAR(v.values[0].value / v0.values[0].value, kf, 1e-12);
  EXPECT_NEAR(v.values[1].value / v0.values[1].value, kf, 1e-12);
  EXPECT_NEAR(v.values[3].value / v0.values[2].value, std::sqrt(2.0 / 1.5 * 1.44), 1e-12);
  EXPECT_DOUBLE_EQ(v.values[2].value, std::min(500e6 / v.values[0].value, 737e6 / v.values[1].value));
  EXPECT_DOUBLE_EQ(v.values[4].value, 900e6 / v.values[3].value);
  EXPECT_EQ(v.values[4].message, "rack governs");

  // Rack root round: rack.root_radius (10 mm) is used, an option (15 mm) wins.
  const MeshGeometry g = build_mesh_geometry(d);
  const LoadFactors k = drive_load_factors(d);
  EXPECT_DOUBLE_EQ(v0.values[1].value, tooth_stress(d, g, k, 10e-3).rack_root_stress);
  EXPECT_DOUBLE_EQ(v0.values[1].value, tooth_stress(d, g, k).rack_root_stress);  // 0: the drive's
  // A sharper round than the default 0.38 m = 23.9 mm raises the rack stress.
  Drive default_round = d;
  default_round.rack.root_radius = 0;
  EXPECT_GT(v0.values[1].value, tooth_stress(default_round, g, k).rack_root_stress);
  MetricOptions r;
  r.rack_root_radius = 15e-3;
  EXPECT_DOUBLE_EQ(eval(d, {"rack_root_bending_stress"}, r).values[0].value,
                   tooth_stress(d, g, k, 15e-3).rack_root_stress);
}

// Only the options give allowables: the rack falls back to the pinion's
// option, as before the problem keys existed.
TEST(StressInputs, PinionOptionCoversARackWithoutAllowable) {
  Drive d = load_problem(path("rack_railway"));
  d.pinion.material.allowable_bending = d.rack.material.allowable_bending = 0;
  MetricOptions o;
  o.allowable_bending_pinion = 450e6;
  const MetricValues v = eval(d, {"root_bending_stress", "rack_root_bending_stress", "root_bending_safety"}, o);
  ASSERT_TRUE(v.all_ok());
  EXPECT_DOUBLE_EQ(v.values[2].value, std::min(450e6 / v.values[0].value, 450e6 / v.values[1].value));
}

void expect_missing(const Drive& d, const char* metric, const std::string& key, const std::string& fragment) {
  SCOPED_TRACE(metric);
  test_support::expect_input_error([&] { eval(d, {metric}); },
                                   {.file = d.source_file, .key = key, .in_message = {fragment}});
}

TEST(StressInputs, MissingAllowableNamesTheProblemKey) {
  const Drive railway = load_problem(path("rack_railway"), {"materials.steel.allowable_bending="});
  expect_missing(railway, "root_bending_safety", "materials.steel.allowable_bending",
                 "root_bending_safety needs materials.steel.allowable_bending (the permissible stress of the "
                 "pinion's material 'steel'");
  EXPECT_TRUE(eval(railway, {"contact_safety"}).all_ok());  // contact allowable still there
  const Drive ship = load_problem(path("ship_lift"), {"materials.rack_steel.allowable_contact="});
  expect_missing(ship, "contact_safety", "materials.rack_steel.allowable_contact",
                 "contact_safety needs materials.rack_steel.allowable_contact (the permissible stress of the rack's "
                 "material 'rack_steel'");
  // check_metric_requests says the same before any model runs.
  const std::vector<MetricRequest> r{parse_metric_request("contact_safety")};
  EXPECT_THROW(check_metric_requests(ship, r, {}), InputError);
  // A drive built in code may carry a negative allowable: refused, naming the key.
  Drive bad = load_problem(path("ship_lift"));
  bad.pinion.material.allowable_contact = -1;
  expect_missing(bad, "contact_stress", "materials.pinion_steel.allowable_contact", "must be > 0");
}

TEST(StressInputs, DerivedFaceLoadFactorBendingIsIso6336) {
  Drive d = load_problem(path("ship_lift"));
  EXPECT_EQ(derived_face_load_factor_bending(d, 1.0), 1.0);
  EXPECT_NEAR(derived_face_load_factor_bending(d, 1.5), std::pow(1.5, kNfShort), 1e-15);
  // A wide face: b/h = 1.2 m / (2.25 x 63 mm) = 8.466 for both members.
  d.pinion.face_width = d.rack.face_width = 1.2;
  const double bh = 1.2 / (2.25 * 0.063);
  EXPECT_NEAR(derived_face_load_factor_bending(d, 1.5), std::pow(1.5, bh * bh / (1 + bh + bh * bh)), 1e-14);
  // The smaller b/h of the two members counts: a rack 0.5 m wide.
  d.rack.face_width = 0.5;
  const double bh2 = 0.5 / (2.25 * 0.063);
  EXPECT_NEAR(derived_face_load_factor_bending(d, 1.5), std::pow(1.5, bh2 * bh2 / (1 + bh2 + bh2 * bh2)), 1e-14);
  // Given explicitly, K_Fbeta is taken as it is.
  d.load.face_load_factor = 1.5;
  d.load.face_load_factor_bending = 1.1;
  EXPECT_EQ(drive_load_factors(d).face_bending, 1.1);
  d.load.face_load_factor_bending = 0;
  EXPECT_NEAR(drive_load_factors(d).face_bending, std::pow(1.5, bh2 * bh2 / (1 + bh2 + bh2 * bh2)), 1e-14);
  d.load.transverse_load_factor = 1.2;
  EXPECT_EQ(drive_load_factors(d).transverse_bending, 1.2);  // K_Falpha = K_Halpha
  EXPECT_EQ(drive_load_factors(d).transverse_contact, 1.2);
}

}  // namespace
}  // namespace rackopt::metrics
