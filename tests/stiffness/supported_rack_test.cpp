// The supported rack's two corrections (stiffness/supported_rack.hpp): the
// tooth layer against the closed form of a two-rectangle section, and the
// foundation depth rule.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "rackopt/stiffness/rack_foundation.hpp"
#include "rackopt/stiffness/supported_rack.hpp"

namespace rackopt {
namespace {

RackSpec rectangular_body(double w, double h) {
  RackSpec r;
  r.body_height = h;
  r.body_width = w;
  r.section.area = w * h;
  r.section.second_moment = w * h * h * h / 12;
  r.section.shear_area = w * h / 1.2;
  r.section.neutral_axis_depth = h / 2;
  return r;
}

TEST(SupportedRack, ToothLayerOfTheBodysWidthIsADeeperRectangle) {
  // A layer as wide as the body is the same body t deeper: I = w (h+t)^3/12.
  const double w = 0.04, h = 0.024, ht = 0.009, beta = 0.14, t = beta * ht;
  const RackSpec out = rack_with_tooth_layer(rectangular_body(w, h), ht, w, beta);
  EXPECT_NEAR(out.section.area, w * (h + t), 1e-15);
  EXPECT_NEAR(out.section.second_moment, w * (h + t) * (h + t) * (h + t) / 12, 1e-12 * out.section.second_moment);
  EXPECT_NEAR(out.section.shear_area, w * (h + t) / 1.2, 1e-15);
  // The lever arms stay measured from the body's axis.
  EXPECT_EQ(out.section.neutral_axis_depth, h / 2);
}

TEST(SupportedRack, NarrowLayerByTheParallelAxisTheorem) {
  const double w = 0.06, h = 0.0755, ht = 0.0716, bt = 0.03, beta = 0.2, t = beta * ht;
  const RackSpec out = rack_with_tooth_layer(rectangular_body(w, h), ht, bt, beta);
  // Centroid measured up from the body's bottom.
  const double A1 = w * h, A2 = bt * t, yc = (A1 * h / 2 + A2 * (h + t / 2)) / (A1 + A2);
  const double I = w * h * h * h / 12 + A1 * (yc - h / 2) * (yc - h / 2) + bt * t * t * t / 12 +
                   A2 * (h + t / 2 - yc) * (h + t / 2 - yc);
  EXPECT_NEAR(out.section.second_moment, I, 1e-12 * I);
  EXPECT_GT(out.section.second_moment, rectangular_body(w, h).section.second_moment);
}

TEST(SupportedRack, NoLayerLeavesTheSectionAndBadInputIsRefused) {
  const RackSpec body = rectangular_body(0.04, 0.024);
  const RackSpec out = rack_with_tooth_layer(body, 0.009, 0.04, 0.0);
  EXPECT_EQ(out.section.second_moment, body.section.second_moment);
  EXPECT_EQ(out.section.area, body.section.area);
  EXPECT_THROW(rack_with_tooth_layer(body, 0.009, 0.04, -0.1), std::invalid_argument);
  EXPECT_THROW(rack_with_tooth_layer(body, 0.0, 0.04, 0.1), std::invalid_argument);
  EXPECT_THROW(rack_with_tooth_layer(body, 0.009, 0.0, 0.1), std::invalid_argument);
}

TEST(SupportedRack, FoundationDepthIsLocalButNeverBelowTheCalibration) {
  const double S = 0.01;
  EXPECT_DOUBLE_EQ(supported_foundation_depth(0.05, S, 0.8), 0.8 * S);
  EXPECT_DOUBLE_EQ(supported_foundation_depth(0.004, S, 0.8), 0.004);  // a body thinner than the zone
  EXPECT_THROW(supported_foundation_depth(0.05, S, 0.5 * RackFoundationRange{}.depth_lo), std::invalid_argument);
  const SupportedRackLaw law = supported_rack_law();
  EXPECT_GE(law.foundation_depth, RackFoundationRange{}.depth_lo);
  EXPECT_GT(law.tooth_layer, 0.0);
  for (double deg : {12.0, 14.0, 20.0, 25.0, 30.0}) EXPECT_GE(law.tooth_layer_at(deg * M_PI / 180), 0.0);
  EXPECT_DOUBLE_EQ(law.tooth_layer_at(20 * M_PI / 180), law.tooth_layer);
}

TEST(SupportedRack, ShortDeepSpansAreFlaggedOutsideTheFittedRange) {
  Drive d;
  d.rack = rectangular_body(0.12, 0.25);
  d.rack.span = 1.0;  // 4 body depths, as the ship lift
  d.effects.rack_span = RackSpanModel::kCoupled;
  d.effects.supported_rack = true;
  const std::string w = supported_rack_range_warning(d);
  EXPECT_NE(w.find("4 body depths"), std::string::npos) << w;
  // At 8 body depths the law is inside the range it was fitted on.
  d.rack.span = kSupportedRackSlenderSpan * 0.25;
  EXPECT_EQ(supported_rack_range_warning(d), "");
  // Without the law (or with a rigid rack body) there is nothing to flag.
  d.rack.span = 1.0;
  d.effects.supported_rack = false;
  EXPECT_EQ(supported_rack_range_warning(d), "");
  d.effects.supported_rack = true;
  d.effects.rack_span = RackSpanModel::kRigid;
  EXPECT_EQ(supported_rack_range_warning(d), "");
}

}  // namespace
}  // namespace rackopt
