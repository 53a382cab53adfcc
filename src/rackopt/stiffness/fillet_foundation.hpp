// Fillet-foundation (gear body) compliance of the pinion: Sainsot, Velex &
// Duverger (2004), physics.md 3. Uses the tool addendum in theta_f and the
// full u_f definition (both are known bugs in public codes).
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

class FilletFoundationCompliance {
 public:
  FilletFoundationCompliance(const MeshGeometry& geometry, const PinionSpec& pinion);
  // [m/N] for a unit normal load at LOA coordinate s, effective face width
  // face_width (reduced while a spall is under the contact).
  double at(double s, double face_width) const;
  // True when (h_f, theta_f) lies outside the fitted range of the coefficient
  // table (about 1.4 <= h_f <= 7, 0.01 <= theta_f <= 0.12 rad); callers warn.
  bool outside_fitted_range() const { return outside_range_; }
  double h_f() const { return h_f_; }
  double theta_f() const { return theta_f_; }

 private:
  double rb_, alpha2_, rf_, E_, L_, M_, P_, Q_, S_f_, h_f_, theta_f_;
  bool outside_range_ = false;
};

}  // namespace rackopt
