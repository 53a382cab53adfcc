// The toothed rack on its hinged supports, as FE sees it: two corrections
// to the pair compliance and the hinged beam of rack_span.hpp, fitted on FE
// mesh positions of racks on their supports (tests/data/fe/supports.csv,
// docs/models/rack_span.md "Against FE"). Effect `effects.supported_rack`,
// applied with rack_span: coupled (supported_rack_applies).
//
//  * A tooth layer. The beam of rack_span.hpp is the body below the root
//    line; the teeth stand on it as separate beams, yet their roots bend
//    with the body. A layer of beta times the tooth height, as wide as the
//    teeth, added on top of the section's area, second moment and shear
//    area stands for that (the contacts' lever arms stay measured from the
//    body's own axis).
//  * A local rack foundation. The rack tooth's foundation
//    (rack_foundation.hpp) was calibrated on a rack segment whose base is
//    held at the body's whole depth H: it counts the body's deformation
//    down to that base. On supports the beam counts the body's bending and
//    shear, so the foundation is taken at a depth of k root thicknesses
//    (at most H): the zone under the tooth that the beam does not see.
//
// Example:
//   if (supported_rack_applies(drive.effects)) {
//     RackSpec beam = rack_beam(drive);  // the section with its tooth layer
//     double depth = supported_foundation_depth(H, root_thickness, supported_rack_law().foundation_depth);
//   }
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"

namespace rackopt {

struct SupportedRackLaw {
  double tooth_layer = 0;            // beta at 20 deg: layer thickness / tooth height
  double tooth_layer_per_deg = 0;    // d beta / d alpha0 [1/deg]
  double foundation_depth = 3;       // k: foundation depth / root thickness (>= 0.55, the calibration's least)
  // beta at the pressure angle alpha0 [rad] (not below 0).
  double tooth_layer_at(double pressure_angle) const;
};

// The fitted law (`fe_calibration --fit supports`).
SupportedRackLaw supported_rack_law();

// Spans of at least this many body depths are the slender beams the law was
// fitted on (within 5.4 % of FE there); the two shorter spans checked came
// out 0.8 % and 10 % too soft (docs/models/rack_span.md, "Against FE").
inline constexpr double kSupportedRackSlenderSpan = 8;

// A warning when the law applies to a span shorter than
// kSupportedRackSlenderSpan body depths (rack_body_depth); empty otherwise.
std::string supported_rack_range_warning(const Drive& drive);

// Whether the law applies: effects.supported_rack with rack_span: coupled.
inline bool supported_rack_applies(const Effects& effects) {
  return effects.supported_rack && effects.rack_span == RackSpanModel::kCoupled;
}

// `rack` with a layer of beta * tooth_height, `teeth_width` wide, added on
// top of its section (directly above the root line): the area, the second
// moment about the composite's centroid and the shear area (kappa kept) of
// body + layer. The neutral_axis_depth, from which the contacts' lever arms
// are measured, stays the body's. beta = 0 returns the section unchanged.
// Throws std::invalid_argument for a negative beta or a non-positive height
// or width.
RackSpec rack_with_tooth_layer(const RackSpec& rack, double tooth_height, double teeth_width, double beta);

// The rack as the beam of rack_span.hpp sees it in the mesh model: where
// supported_rack_applies, drive.rack with its tooth
// layer (the law's beta at the drive's pressure angle, the tooth height
// (h_a2* + h_f2*) m, the rack face width or else the pinion's); otherwise
// drive.rack.
RackSpec rack_beam(const Drive& drive);

// The depth [m] the rack foundation is taken at on supports: k *
// root_thickness, at most body_depth. Throws std::invalid_argument for k
// below the calibration's smallest depth (RackFoundationRange::depth_lo).
double supported_foundation_depth(double body_depth, double root_thickness, double k);

}  // namespace rackopt
