// Foundation compliance of a rack tooth: what the rack adds to the clamped
// trapezoid tooth (rack_tooth.hpp) because the tooth stands on an elastic
// body and not on a rigid root line: the root and body under the tooth
// rotate, slide and sink under its load, and the root rounds and the 2-D
// stress field near the root differ from the beam's.
//
// There is no closed form for it, so it is calibrated with the FE tier the
// way Sainsot et al. (2004) calibrated the pinion's fillet foundation: a
// rack segment on a body of depth H, its base held, loaded on one flank
// (fe/tooth_compliance_fe.hpp), minus the clamped tooth, fitted over the
// rack shapes in the form Sainsot's analysis gives (a root rotation, a
// sliding and a sinking of the tooth's foundation):
//
//   c_rf = [cos^2 a0 (L q^2 + M q + P) + sin^2 a0 Q] / (E b),  q = u / S,
//
// u the height above the root line where the load line crosses the tooth
// centre line, S = 2 w_f the tooth thickness at the root line, and each of
// L, M, P, Q linear in ln(H / S) and rho / S (rho the root round). The
// data, the fit and its error are in docs/models/rack_foundation.md; the
// data are tests/data/fe/rack_tooth.csv.
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

// The coefficients at one shape (dimensionless).
struct RackFoundationCoefficients {
  double L = 0, M = 0, P = 0, Q = 0;
};

// L, M, P, Q at body depth over root thickness H/S and root round over
// root thickness rho/S.
RackFoundationCoefficients rack_foundation_coefficients(double depth_over_root, double round_over_root);

// The fitted range: H/S and rho/S of the calibration sample. Outside it the
// law is extrapolated (callers warn).
struct RackFoundationRange {
  double depth_lo = 0.55, depth_hi = 3.0;
  double round_lo = 0.03, round_hi = 0.15;
};

class RackFoundationCompliance {
 public:
  // body_depth: depth of the rack body below the root line [m] (the rack's
  // body_height, or twice its neutral-axis depth for a section given
  // explicitly). face_width: the rack face width in use. The root round is
  // RackSpec.root_radius, or the pinion cutter's tip radius when that is 0
  // (as the rack outline draws it). Throws InputError for a non-positive
  // depth, width or modulus; DesignError "rack_foundation_out_of_range" if
  // the law, far outside its fitted range, gives a non-positive compliance
  // anywhere on the tooth.
  RackFoundationCompliance(const MeshGeometry& geometry, const RackSpec& rack, double body_depth,
                           double face_width);

  // [m/N] for a unit normal load at height y_c above the root line (clamped
  // to the tooth).
  double at_height(double y_c) const;
  // Same at LOA coordinate s (the rack tooth's contact height at s).
  double at(double s) const;

  bool outside_fitted_range() const { return outside_range_; }
  double depth_over_root() const { return depth_over_root_; }
  double round_over_root() const { return round_over_root_; }

 private:
  double tan_a0_, cos2_, sin2_, w_f_, height_, E_b_;
  double pitch_radius_sin2_, sin_a0_, datum_lift_, dedendum_;
  double depth_over_root_, round_over_root_;
  RackFoundationCoefficients c_;
  bool outside_range_ = false;
};

}  // namespace rackopt
