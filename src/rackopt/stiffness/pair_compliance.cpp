#include "rackopt/stiffness/pair_compliance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/fillet_calibration.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/stiffness/pinion_tooth.hpp"
#include "rackopt/stiffness/rack_foundation.hpp"
#include "rackopt/stiffness/rack_tooth.hpp"
#include "rackopt/stiffness/supported_rack.hpp"

namespace rackopt {

double rack_body_depth(const RackSpec& rack) {
  if (rack.body_height > 0) return rack.body_height;
  return std::max(2 * rack.section.neutral_axis_depth, 0.0);
}

struct PairCompliance::Impl {
  Effects fx;
  Material pinion_material, rack_material;
  double a0 = 0, cos_a0 = 0, tan_a0 = 0;
  double rb = 0, alpha2 = 0;
  double rack_half_thickness_at_root = 0, rack_dedendum = 0;
  double rack_datum_height_at_pitch = 0, sin_a0 = 0;  // y_c(s) = this - s sin a0
  double width = 0, e_star = 0;
  std::optional<PinionToothCompliance> pinion;
  std::optional<FilletFoundationCompliance> fillet;
  std::optional<FilletCalibration> fillet_calibration;
  std::optional<RackToothCompliance> rack;
  std::optional<RackFoundationCompliance> rack_foundation;
  std::vector<std::string> warnings;

  double rack_height(double s) const { return rack_datum_height_at_pitch - s * sin_a0; }
};

namespace {

// Sainsot's foundation plus its FE calibration (a stiffening). The sum stays
// positive wherever the calibration was fitted; far outside, it is refused
// rather than let a tooth pull its load.
double fillet_at(const PairCompliance::Impl& im, double s, double b) {
  double c = im.fillet->at(s, b);
  if (im.fillet_calibration) {
    c += im.fillet_calibration->at(s, b);
    if (!(c > 0)) {
      throw DesignError("fillet_calibration_out_of_range",
                        "the FE calibration of the fillet foundation leaves a non-positive compliance at theta_f = " +
                            std::to_string(im.fillet_calibration->theta_f()) +
                            " rad (calibrated 0.06..0.26 rad, 14..25 deg); switch effects.fillet_calibration off");
    }
  }
  return c;
}

}  // namespace

PairCompliance::PairCompliance(const Drive& drive, const MeshGeometry& geo) : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.fx = drive.effects;
  im.pinion_material = drive.pinion.material;
  im.rack_material = drive.rack.material;
  im.a0 = drive.pinion.pressure_angle;
  im.cos_a0 = std::cos(im.a0);
  im.sin_a0 = std::sin(im.a0);
  im.tan_a0 = std::tan(im.a0);
  im.rb = geo.pinion.base_radius;
  im.alpha2 = geo.pinion.half_base_angle;
  im.rack_half_thickness_at_root = geo.rack.half_thickness_at_root;
  im.rack_dedendum = geo.rack.dedendum;
  // y_c = dedendum + r sin^2 a0 - s sin a0 + x m + Delta (docs/models/mesh.md).
  im.rack_datum_height_at_pitch = geo.rack.dedendum + geo.pinion.pitch_radius * im.sin_a0 * im.sin_a0 +
                                  geo.profile_shift_length + geo.clearance;
  const double b_rack = drive.rack.face_width > 0 ? drive.rack.face_width : drive.pinion.face_width;
  im.width = std::min(drive.pinion.face_width, b_rack);
  if (im.fx.hertz == HertzModel::kLinear) im.e_star = effective_modulus(drive.pinion.material, drive.rack.material);

  const Effects& fx = im.fx;
  if (fx.pinion_tooth) im.pinion.emplace(geo, drive.pinion, fx, drive.numerics);
  if (fx.fillet_foundation) {
    im.fillet.emplace(geo, drive.pinion);
    if (fx.fillet_calibration) im.fillet_calibration.emplace(geo, drive.pinion);
    // Sainsot's table extrapolated in theta_f is what the FE calibration was
    // fitted on top of: inside the calibration's range only h_f counts.
    const bool calibrated = im.fillet_calibration && !im.fillet_calibration->outside_fitted_range();
    const double h_f = im.fillet->h_f();
    if (calibrated ? (h_f < 1.4 || h_f > 7.0) : im.fillet->outside_fitted_range()) {
      std::ostringstream w;
      w << "fillet foundation: (h_f, theta_f) = (" << h_f << ", " << im.fillet->theta_f()
        << " rad) is outside the fitted range of Sainsot's table (1.4..7, 0.01..0.12 rad"
        << (calibrated ? ", theta_f covered by the FE calibration" : "") << "); extrapolated";
      im.warnings.push_back(w.str());
    }
    if (im.fillet_calibration && im.fillet_calibration->outside_fitted_range()) {
      std::ostringstream w;
      w << "fillet calibration: theta_f = " << im.fillet_calibration->theta_f()
        << " rad or the pressure angle lies outside the FE-calibrated range (theta_f 0.06..0.26 rad, "
           "14..25 deg); extrapolated";
      im.warnings.push_back(w.str());
    }
  }
  if (fx.rack_tooth) im.rack.emplace(geo, drive.rack, b_rack, drive.numerics);
  if (fx.rack_foundation && fx.rack_tooth) {
    double depth = rack_body_depth(drive.rack);
    if (!(depth > 0)) {
      throw InputError({}, "rack.body_height",
                       "effects.rack_foundation needs the rack body's depth below the root line (rack.body_height, "
                       "or rack.section with its neutral_axis_depth)");
    }
    // On its supports the beam counts the body's bending and shear: the
    // foundation keeps the zone under the tooth (supported_rack.hpp).
    if (supported_rack_applies(fx)) {
      depth = supported_foundation_depth(depth, 2 * geo.rack.half_thickness_at_root,
                                         supported_rack_law().foundation_depth);
    }
    im.rack_foundation.emplace(geo, drive.rack, depth, b_rack);
    if (im.rack_foundation->outside_fitted_range()) {
      const RackFoundationRange range;
      std::ostringstream w;
      w << "rack foundation: body depth / root thickness " << im.rack_foundation->depth_over_root()
        << " and root round / root thickness " << im.rack_foundation->round_over_root()
        << " lie outside the FE-calibrated range (" << range.depth_lo << ".." << range.depth_hi << ", "
        << range.round_lo << ".." << range.round_hi << "); extrapolated";
      im.warnings.push_back(w.str());
    }
  }
}

PairCompliance::~PairCompliance() = default;
PairCompliance::PairCompliance(PairCompliance&&) noexcept = default;
PairCompliance& PairCompliance::operator=(PairCompliance&&) noexcept = default;

PairTeeth PairCompliance::teeth(double s, const SpallBand* pinion_spall, const SpallBand* rack_spall,
                                double face_width) const {
  const Impl& im = *impl_;
  PairTeeth t;
  const double b = face_width > 0 ? face_width : im.width;
  if (im.pinion) t.pinion = im.pinion->at(s, pinion_spall);
  if (im.fillet) t.fillet = fillet_at(im, s, b);
  if (im.rack) t.rack = im.rack->at(s, rack_spall);
  if (im.rack_foundation) t.rack_foundation = im.rack_foundation->at(s);
  return t;
}

PairTeeth PairCompliance::teeth_at(double s, double rack_height, double face_width) const {
  const Impl& im = *impl_;
  PairTeeth t;
  const double b = face_width > 0 ? face_width : im.width;
  if (im.pinion) t.pinion = im.pinion->at(s);
  if (im.fillet) t.fillet = fillet_at(im, s, b);
  if (im.rack) t.rack = im.rack->at_height(rack_height);
  if (im.rack_foundation) t.rack_foundation = im.rack_foundation->at_height(rack_height);
  return t;
}

double PairCompliance::contact(double s, double force, double face_width, double rack_height) const {
  const Impl& im = *impl_;
  const double b = face_width > 0 ? face_width : im.width;
  switch (im.fx.hertz) {
    case HertzModel::kOff:
      return 0.0;
    case HertzModel::kLinear:
      return hertz_linear_compliance(im.e_star, b);
    case HertzModel::kWeberBanaschek: {
      // Distances from the contact to the two tooth centre lines along the
      // load line, where the tooth beams' deflections are taken: the pinion
      // half thickness h = r_b [(a1 + a2) cos a1 - sin a1] over cos a1 (a1
      // the load angle), the rack half thickness over cos a0.
      const double s_eff = std::max(s, 1e-6 * im.rb);
      const double a1 = s_eff / im.rb - im.alpha2;
      const double h1 = im.rb * ((a1 + im.alpha2) * std::cos(a1) - std::sin(a1)) / std::cos(a1);
      const double y = rack_height >= 0 ? rack_height : im.rack_height(s);
      const double h2 = (im.rack_half_thickness_at_root - y * im.tan_a0) / im.cos_a0;
      return hertz_weber_banaschek_compliance(im.pinion_material, im.rack_material, b, force, s_eff,
                                              std::max(h1, 1e-9), std::max(h2, 1e-9), ElasticPlane::kStress);
    }
  }
  return 0.0;
}

void ContactLaw::strip_too_wide(double force) {
  // As hertz_weber_banaschek_compliance: the strip has outgrown the teeth.
  throw DesignError("hertz_out_of_range", "Weber-Banaschek contact strip at " + std::to_string(force) +
                                              " N is wider than the teeth: outside the contact model");
}

ContactLaw PairCompliance::contact_law(double s, double face_width, double rack_height) const {
  const Impl& im = *impl_;
  const double b = face_width > 0 ? face_width : im.width;
  ContactLaw law;
  law.floor = 1.0 * b;  // hertz_weber_banaschek_compliance's floor: 1 N per metre of width
  law.f_ref = std::max(law.floor, 1.0);
  law.c_ref = contact(s, law.f_ref, b, rack_height);
  if (im.fx.hertz == HertzModel::kWeberBanaschek) {
    law.slope = (1.0 / im.pinion_material.youngs_modulus + 1.0 / im.rack_material.youngs_modulus) /
                (std::numbers::pi * b);
  }
  return law;
}

bool PairCompliance::contact_depends_on_force() const { return impl_->fx.hertz == HertzModel::kWeberBanaschek; }
double PairCompliance::rack_contact_height(double s) const { return impl_->rack_height(s); }
double PairCompliance::contact_width() const { return impl_->width; }
const PinionToothCompliance* PairCompliance::pinion_tooth() const {
  return impl_->pinion ? &*impl_->pinion : nullptr;
}
const RackToothCompliance* PairCompliance::rack_tooth() const { return impl_->rack ? &*impl_->rack : nullptr; }
const std::vector<std::string>& PairCompliance::warnings() const { return impl_->warnings; }

}  // namespace rackopt
