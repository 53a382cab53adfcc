#include "rackopt/stiffness/rack_tooth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

std::string mm(double metres) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g mm", metres * 1e3);
  return buf;
}

// Below this flank angle the closed-form bending bracket loses digits to
// cancellation (docs/models/tooth.md): use quadrature instead.
constexpr double kSmallAngle = 5.0 * std::numbers::pi / 180.0;

}  // namespace

RackToothCompliance::RackToothCompliance(const MeshGeometry& geometry, const RackSpec& rack,
                                         double face_width, const Numerics& numerics, bool enabled)
    : alpha0_(geometry.pressure_angle),
      tan_a0_(std::tan(geometry.pressure_angle)),
      sin_a0_(std::sin(geometry.pressure_angle)),
      cos_a0_(std::cos(geometry.pressure_angle)),
      w_f_(geometry.rack.half_thickness_at_root),
      dedendum_(geometry.rack.dedendum),
      height_(geometry.rack.dedendum + geometry.rack.addendum),
      E_(rack.material.youngs_modulus),
      nu_(rack.material.poisson_ratio),
      G_(rack.material.shear_modulus()),
      b_(face_width),
      pitch_radius_(geometry.pinion.pitch_radius),
      shift_(geometry.profile_shift_length),
      clearance_(geometry.clearance),
      enabled_(enabled),
      rule_(std::max(numerics.quadrature_order, 16)) {
  if (!(alpha0_ >= 0.0 && alpha0_ < 0.5 * std::numbers::pi)) {
    throw InputError({}, "pinion.pressure_angle", "rack flank angle outside [0, 90) deg");
  }
  if (!(w_f_ > 0.0) || !(height_ > 0.0) || !(dedendum_ >= 0.0)) {
    throw InputError({}, "rack", "rack tooth needs a positive root half-thickness and height");
  }
  if (!(b_ > 0.0)) throw InputError({}, "rack.face_width", "rack face width must be positive");
  if (!(E_ > 0.0)) throw InputError({}, "rack.material.youngs_modulus", "must be positive");
  if (!(nu_ > -1.0 && nu_ < 0.5)) {
    throw InputError({}, "rack.material.poisson_ratio", "Poisson ratio must be in (-1, 0.5)");
  }
  if (w_f_ - height_ * tan_a0_ <= 0.0) {
    throw DesignError("pointed_tooth", "rack tooth closes below its tip: half-thickness at the tip " +
                                           mm(w_f_ - height_ * tan_a0_));
  }
}

double RackToothCompliance::contact_height(double s) const {
  return dedendum_ + pitch_radius_ * sin_a0_ * sin_a0_ - s * sin_a0_ + shift_ + clearance_;
}

ToothCompliance RackToothCompliance::at(double s, const SpallBand* spall) const {
  if (!std::isfinite(s)) throw InputError({}, "s", "contact position is not finite");
  // The rack flank is straight: a contact behind the pinion base circle
  // (interference ignored) still has a well-defined height on it.
  return at_height(contact_height(s), spall);
}

void RackToothCompliance::validate(const SpallBand& spall) const {
  if (!spall_band_removes_material(spall)) return;
  const double tol = 1e-12 * height_;
  if (spall.low < -tol || spall.high > height_ + tol) {
    throw DesignError("spall_off_profile", "rack spall band [" + mm(spall.low) + ", " +
                                               mm(spall.high) + "] leaves the flank [0, " +
                                               mm(height_) + "] above the root line");
  }
  if (spall.width > b_) {
    throw DesignError("spall_too_wide", "rack spall width " + mm(spall.width) +
                                            " exceeds the face width " + mm(b_));
  }
  const double thinnest = w_f_ - std::min(spall.high, height_) * tan_a0_;
  if (spall.depth >= 2.0 * thinnest) {
    throw DesignError("spall_too_deep", "rack spall depth " + mm(spall.depth) +
                                            " reaches the full tooth thickness " +
                                            mm(2.0 * thinnest) + " inside the band");
  }
}

ToothCompliance RackToothCompliance::at_height(double y_c_in, const SpallBand* spall) const {
  if (!enabled_) return {};
  if (!std::isfinite(y_c_in)) throw InputError({}, "y_c", "contact height is not finite");
  if (spall) validate(*spall);
  const double y_c = std::clamp(y_c_in, 0.0, height_);
  if (y_c == 0.0) return {};
  const double w_c = w_f_ - y_c * tan_a0_;

  const bool pitted = spall && spall->width > 0.0 && spall->depth > 0.0 && spall->low < y_c;
  const CantileverMaterial material{E_, G_, 1.2};
  CantileverLoad load;
  load.position = y_c;
  load.offset = w_c;
  load.transverse = cos_a0_;
  load.axial = sin_a0_;

  if (pitted) {
    const double lo = std::clamp(spall->low, 0.0, y_c), hi = std::clamp(spall->high, 0.0, y_c);
    const std::array<double, 4> stations{0.0, lo, hi, y_c};
    const double ws = spall->width, hs = spall->depth;
    return cantilever_compliance(
        [&](double y) {
          const double w = w_f_ - y * tan_a0_;
          return (y > lo && y < hi) ? tooth_slice_section(w, b_, ws, hs) : tooth_slice_section(w, b_);
        },
        load, material, stations, rule_);
  }

  // ln(w_f/w_c) / tan a0 without cancellation: -log1p(-y_c t/w_f)/t -> y_c/w_f.
  const double eps = y_c * tan_a0_ / w_f_;
  const double log_ratio = -std::log1p(-eps);
  const double log_over_tan = tan_a0_ > 1e-12 ? log_ratio / tan_a0_ : y_c / w_f_;
  const double inv_Eb = 1.0 / (E_ * b_);
  ToothCompliance c;
  c.shear = 1.2 * (1.0 + nu_) * cos_a0_ * cos_a0_ * log_over_tan * inv_Eb;
  c.axial = 0.5 * sin_a0_ * cos_a0_ * log_ratio * inv_Eb;
  if (alpha0_ >= kSmallAngle) {
    const double rho = w_c / w_f_, c2 = cos_a0_ * cos_a0_;
    const double bracket = c2 * c2 * log_ratio - 2.0 * c2 * (1.0 - rho) + 0.5 * (1.0 - rho * rho);
    c.bending = 1.5 * bracket / (sin_a0_ * sin_a0_ * tan_a0_) * inv_Eb;
  } else {
    const std::array<double, 2> stations{0.0, y_c};
    c.bending = cantilever_compliance(
                    [&](double y) { return tooth_slice_section(w_f_ - y * tan_a0_, b_); }, load,
                    material, stations, rule_)
                    .bending;
  }
  return c;
}

}  // namespace rackopt
