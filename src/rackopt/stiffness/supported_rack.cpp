#include "rackopt/stiffness/supported_rack.hpp"

#include <algorithm>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "rackopt/stiffness/pair_compliance.hpp"
#include "rackopt/stiffness/rack_foundation.hpp"

namespace rackopt {

// `fe_calibration --fit supports tests/data/fe/supports.csv`
// (docs/models/rack_span.md, "Against FE").
// SUPPORTED_RACK_FIT
SupportedRackLaw supported_rack_law() { return {0.135, 0.0070, 0.55}; }

double SupportedRackLaw::tooth_layer_at(double pressure_angle) const {
  return std::max(0.0, tooth_layer + tooth_layer_per_deg * (pressure_angle * 180 / std::numbers::pi - 20));
}

RackSpec rack_with_tooth_layer(const RackSpec& rack, double tooth_height, double teeth_width, double beta) {
  if (!(beta >= 0)) throw std::invalid_argument("rack_with_tooth_layer: beta must be >= 0");
  if (!(tooth_height > 0) || !(teeth_width > 0)) {
    throw std::invalid_argument("rack_with_tooth_layer: tooth height and width must be positive");
  }
  RackSpec out = rack;
  if (beta == 0) return out;
  const RackSection& s = rack.section;
  const double t = beta * tooth_height;
  const double A1 = teeth_width * t, A = s.area + A1;
  // Depths below the root line: the body's centroid at y0, the layer's at -t/2.
  const double y0 = s.neutral_axis_depth;
  const double y = (s.area * y0 - A1 * t / 2) / A;
  out.section.area = A;
  out.section.second_moment = s.second_moment + s.area * (y0 - y) * (y0 - y) + teeth_width * t * t * t / 12 +
                              A1 * (t / 2 + y) * (t / 2 + y);
  // The shear area keeps the body's ratio kappa A.
  out.section.shear_area = s.area > 0 ? s.shear_area * A / s.area : s.shear_area;
  // The contacts' lever arm stays measured from the body's own axis: the
  // teeth are not a continuous flange, and against FE the body's axis fits
  // (docs/models/rack_span.md, "Against FE").
  return out;
}

RackSpec rack_beam(const Drive& drive) {
  if (!supported_rack_applies(drive.effects)) return drive.rack;
  const double width = drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
  const double height = (drive.rack.addendum_coef + drive.rack.dedendum_coef) * drive.pinion.module;
  return rack_with_tooth_layer(drive.rack, height, width,
                               supported_rack_law().tooth_layer_at(drive.pinion.pressure_angle));
}

std::string supported_rack_range_warning(const Drive& drive) {
  if (!supported_rack_applies(drive.effects)) return {};
  const double depth = rack_body_depth(drive.rack);
  if (!(depth > 0) || drive.rack.span >= kSupportedRackSlenderSpan * depth) return {};
  std::ostringstream w;
  w << "supported rack: the span is " << drive.rack.span / depth << " body depths; the beam law was fitted on spans of "
    << "at least " << kSupportedRackSlenderSpan
    << " (within 5.4 % of FE), on shorter ones FE found it from 0.8 % to 10 % too soft "
       "(docs/models/rack_span.md, \"Against FE\")";
  return w.str();
}

double supported_foundation_depth(double body_depth, double root_thickness, double k) {
  if (!(k >= RackFoundationRange{}.depth_lo)) {
    throw std::invalid_argument("supported_foundation_depth: k below the rack foundation's calibrated range");
  }
  return std::min(body_depth, k * root_thickness);
}

}  // namespace rackopt
