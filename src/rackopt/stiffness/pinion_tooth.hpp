// Pinion tooth bending, shear and axial-compression compliance by the
// potential-energy method (Yang & Lin 1987; Tian 2004): physics.md 2.2 for the
// involute part, 2.4 (Chen & Shao 2011) for the straight part below the base
// circle, 9.1-9.2 for a spalled band (centroid-corrected section).
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
  // numerics.quadrature_order Gauss-Legendre points, or GSL adaptive
  // quadrature (rel. 1e-12) when numerics.adaptive_quadrature is set.
  PinionToothCompliance(const MeshGeometry& geometry, const PinionSpec& pinion,
                        const Effects& effects, const Numerics& numerics);

  // Compliance for a unit normal load at LOA coordinate s (s > 0, contact on
  // the involute: sqrt(r_b^2+s^2) between the form and tip radii). A contact
  // below the base circle (s <= 0, only possible with interference ignored) is
  // evaluated at the base circle. With a spall, the section inside the band
  // and between the contact and the root is reduced; a band above the
  // contact has no effect.
  ToothCompliance at(double s, const SpallBand* spall = nullptr) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace rackopt
