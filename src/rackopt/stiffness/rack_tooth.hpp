// Straight-sided trapezoid rack tooth as a cantilever on the root line:
// closed-form bending, shear and axial compliances (physics.md 5.2);
// numerical quadrature with reduced sections for a spalled band (9.1).
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

class RackToothCompliance {
 public:
  RackToothCompliance(const MeshGeometry& geometry, const RackSpec& rack, double face_width,
                      const Numerics& numerics);
  // Unit normal load at LOA coordinate s; the contact is at height
  // dedendum + contact_height_above_datum(s) above the root line.
  ToothCompliance at(double s, const SpallBand* spall = nullptr) const;
  // Same, by contact height y_c above the root line [m].
  ToothCompliance at_height(double y_c, const SpallBand* spall = nullptr) const;

 private:
  const MeshGeometry* geometry_ = nullptr;
  double alpha0_, w_f_, dedendum_, E_, nu_, b_;
  int order_;
};

}  // namespace rackopt
