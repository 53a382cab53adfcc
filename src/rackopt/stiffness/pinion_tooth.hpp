// Pinion tooth bending, shear and axial-compression compliance by the
// potential-energy method (Yang & Lin 1987; Tian 2004): docs/models/tooth.md for the
// involute part, 2.4 (Chen & Shao 2011) for the straight part below the base
// circle, 9.1-9.2 for a spalled band (centroid-corrected section).
//
// Reads from MeshGeometry only: pinion.base_radius, pinion.half_base_angle
// (alpha_2), pinion.root_radius, pinion.tip_radius. Material and face width
// come from PinionSpec.
#pragma once

#include <memory>

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

class PinionToothCompliance {
 public:
  // Precomputes everything that does not depend on the contact position
  // (quadrature nodes, alpha_2, alpha_u, root segment). Uses
  // numerics.quadrature_order Gauss-Legendre points per integral piece, or
  // GSL adaptive quadrature (QAGS, rel. 1e-12) when
  // numerics.adaptive_quadrature is set. effects.pinion_tooth = false makes
  // every call return zeros; effects.root_segment = false drops the 2.4
  // straight segment when r_f < r_b.
  // Throws InputError for a non-positive face width, modulus or radius, or a
  // quadrature order outside 1..4096.
  PinionToothCompliance(const MeshGeometry& geometry, const PinionSpec& pinion,
                        const Effects& effects, const Numerics& numerics);

  // Compliance [m/N] for a unit normal load at LOA coordinate s.
  //  * s is expected in [s_start, s_end]. A contact below the base circle
  //    (s <= 0, only possible with interference ignored) is evaluated at the
  //    base circle; when r_f > r_b a contact below the root circle is
  //    evaluated at the root (zero involute length). A contact above the tip
  //    radius (beyond rounding) throws InputError.
  //  * With a spall, the section inside the band and between the contact and
  //    the root is reduced (9.1, exact centroid-corrected I); a band above the
  //    contact has no effect. The band is validated on every call (see
  //    validate()); an invalid band throws DesignError.
  ToothCompliance at(double s, const SpallBand* spall = nullptr) const;

  // Checks that a spall band can exist on this tooth; throws DesignError
  //   "spall_off_profile"  band not inside [r_f, r_a] (radii),
  //   "spall_too_wide"     width > face width,
  //   "spall_too_deep"     depth >= the local full tooth thickness 2 h_x
  //                        somewhere in the band (thinnest point: a band edge),
  // and InputError for low > high or a negative width/depth. A band with zero
  // width or depth is valid and has no effect. at() calls this; callers may
  // call it once up front to fail early.
  void validate(const SpallBand& spall) const;

  // Half tooth thickness h_x [m] at radius r on this tooth (involute above
  // r_b, the 2.4 straight segment r_b sin(alpha_2) below it).
  double half_thickness_at_radius(double r) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace rackopt
