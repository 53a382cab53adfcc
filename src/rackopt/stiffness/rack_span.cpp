// Rack body on two hinges: influence coefficients along the line of action
// (derivation in docs/models/rack_span.md).
#include "rackopt/stiffness/rack_span.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "rackopt/stiffness/beam_influence.hpp"

namespace rackopt {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("RackSpanCompliance: " + what);
}

double require_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0) {
    std::ostringstream os;
    os << name << " must be finite and > 0, got " << value;
    fail(os.str());
  }
  return value;
}

// The failures of the checks below, out of line: the checks run several
// times per curve sample, their messages never in a valid model.
[[noreturn, gnu::noinline, gnu::cold]] void abscissa_outside(double a, double l) {
  std::ostringstream os;
  os << "contact abscissa a = " << a << " m is outside the span [0, " << l << "] m";
  fail(os.str());
}

[[noreturn, gnu::noinline, gnu::cold]] void heights_not_finite(double e_j, double e_k) {
  std::ostringstream os;
  os << "contact heights must be finite, got e_j = " << e_j << ", e_k = " << e_k;
  fail(os.str());
}

}  // namespace

RackSpanCompliance::RackSpanCompliance(const RackSpec& rack, double pressure_angle,
                                       const Effects& effects)
    : l_(require_positive(rack.span, "rack.span [m]")),
      s_(std::sin(pressure_angle)),
      c_(std::cos(pressure_angle)),
      inv_EI_(0.0),
      inv_EA_(0.0),
      inv_kGA_(0.0),
      couple_(effects.couple_term),
      pin_pin_(rack.supports == Supports::kPinPin) {
  if (!std::isfinite(pressure_angle) || pressure_angle <= 0.0 ||
      pressure_angle >= std::numbers::pi / 2) {
    std::ostringstream os;
    os << "pressure angle must be in (0, pi/2) rad, got " << pressure_angle;
    fail(os.str());
  }
  const double E = require_positive(rack.material.youngs_modulus, "rack.material E [Pa]");
  const double I = require_positive(rack.section.second_moment, "rack.section.second_moment [m^4]");
  inv_EI_ = 1.0 / (E * I);
  if (effects.body_axial) {
    inv_EA_ = 1.0 / (E * require_positive(rack.section.area, "rack.section.area [m^2]"));
  }
  if (effects.body_shear) {
    const double nu = rack.material.poisson_ratio;
    if (!std::isfinite(nu) || nu <= -1.0 || nu > 0.5) {
      std::ostringstream os;
      os << "rack.material Poisson ratio must be in (-1, 0.5], got " << nu;
      fail(os.str());
    }
    const double kA = require_positive(rack.section.shear_area, "rack.section.shear_area [m^2]");
    inv_kGA_ = 1.0 / (rack.material.shear_modulus() * kA);
  }
}

inline double RackSpanCompliance::checked_abscissa(double a) const {
  // a = x - k*span can miss the hinge by a rounding error; accept that much.
  const double tolerance = 1e-9 * l_;
  if (!std::isfinite(a) || a < -tolerance || a > l_ + tolerance) abscissa_outside(a, l_);
  return std::clamp(a, 0.0, l_);
}

RackSpanInfluence RackSpanCompliance::parts(double a_j, double e_j, double a_k,
                                            double e_k) const {
  double x = checked_abscissa(a_j);
  double xi = checked_abscissa(a_k);
  if (!std::isfinite(e_j) || !std::isfinite(e_k)) heights_not_finite(e_j, e_k);
  // Without the couple term the tooth height plays no role in load or response.
  double ex = couple_ ? e_j : 0.0;
  double exi = couple_ ? e_k : 0.0;
  // Evaluate always with the lower (a, e) first: every expression below then
  // depends only on the unordered pair, so swapping j and k is bitwise exact.
  if (xi < x || (xi == x && exi < ex)) {
    std::swap(x, xi);
    std::swap(ex, exi);
  }
  namespace hb = hinged_beam;
  const double s = s_, c = c_, l = l_;
  // Load of a unit LOA force: vertical -s, axial +c, couple -e c. Response
  // weights are the same (work conjugate): v -> -s, u -> +c, psi -> -e c.
  RackSpanInfluence r;
  r.vertical = s * s * inv_EI_ * hb::bending_deflection_per_force(x, xi, l);
  r.couple = c * c * ex * exi * inv_EI_ * hb::bending_rotation_per_couple(x, xi, l);
  // (-s)(-e_hi c) v(lo | couple at hi) + (-e_lo c)(-s) psi(lo | force at hi)
  r.coupling = s * c * inv_EI_ *
               (exi * hb::bending_deflection_per_couple(x, xi, l) +
                ex * hb::bending_rotation_per_force(x, xi, l));
  r.axial = c * c * inv_EA_ *
            (pin_pin_ ? hb::axial_displacement_pin_pin(x, xi, l)
                      : hb::axial_displacement_pin_roller(x, xi));
  r.shear = s * s * inv_kGA_ * hb::shear_deflection_per_force(x, xi, l);
  r.shear_couple = c * c * ex * exi * inv_kGA_ * hb::shear_rotation_per_couple(l);
  return r;
}

double RackSpanCompliance::influence(double a_j, double e_j, double a_k, double e_k) const {
  return parts(a_j, e_j, a_k, e_k).total();
}

double RackSpanCompliance::self(double a, double e) const {
  // parts(a, e, a, e) term by term, written the same way so that the sum
  // keeps its last bits (tests/stiffness/rack_span_test.cpp checks it).
  const double x = checked_abscissa(a);
  if (!std::isfinite(e)) heights_not_finite(e, e);
  const double ex = couple_ ? e : 0.0;
  namespace hb = hinged_beam;
  const double s = s_, c = c_, l = l_;
  const double vertical = s * s * inv_EI_ * hb::bending_deflection_per_force(x, x, l);
  const double couple = c * c * ex * ex * inv_EI_ * hb::bending_rotation_per_couple(x, x, l);
  const double coupling = s * c * inv_EI_ *
                          (ex * hb::bending_deflection_per_couple(x, x, l) +
                           ex * hb::bending_rotation_per_force(x, x, l));
  const double axial = c * c * inv_EA_ *
                       (pin_pin_ ? hb::axial_displacement_pin_pin(x, x, l) : hb::axial_displacement_pin_roller(x, x));
  const double shear = s * s * inv_kGA_ * hb::shear_deflection_per_force(x, x, l);
  const double shear_couple = c * c * ex * ex * inv_kGA_ * hb::shear_rotation_per_couple(l);
  return vertical + couple + coupling + axial + shear + shear_couple;
}

}  // namespace rackopt
