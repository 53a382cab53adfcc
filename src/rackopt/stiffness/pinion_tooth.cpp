#include "rackopt/stiffness/pinion_tooth.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/cantilever_energy.hpp"
#include "rackopt/stiffness/cumulative_integrals.hpp"

namespace rackopt {
namespace {

std::string mm(double metres) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g mm", metres * 1e3);
  return buf;
}

// The involute integrals are tabulated (cumulative_integrals.hpp) at the
// default quadrature order and above: the table is more accurate than the
// 16-point rule (docs/accuracy.md). Lower orders integrate each contact with
// their rule, so that the quadrature error can still be studied.
constexpr int kTabulatedFromOrder = 16;
// Panels shrinking towards the tip, where H (the half-thickness) is smallest.
constexpr int kInvolutePanels = 8;
constexpr double kInvolutePanelRatio = 1.5;

void require_positive(double value, const char* key, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError({}, key, std::string(what) + " must be positive and finite");
  }
}

}  // namespace

struct PinionToothCompliance::Impl {
  // Geometry (docs/models/tooth.md symbols).
  double rb = 0, alpha2 = 0, rf = 0, ra = 0;
  double alpha_u = 0;           // upper (root) limit of the involute integrals
  bool segment = false;         // 2.4 straight segment present and switched on
  double h1 = 0;                // segment half-thickness r_b sin(alpha_2)
  double y_base = 0, y_root = 0;  // centre-line coordinates of the segment ends
  double segment_ratio = 0;     // cos(alpha_2) - (r_f/r_b) cos(alpha_3) = h_r / r_b
  double rho_cos_a3 = 0;        // (r_f/r_b) cos(alpha_3)
  double sin3_a2 = 0, sin_a2 = 0, cos_a2 = 0;
  // Material and section.
  double E = 0, nu = 0, G = 0, b = 0, inv_Eb = 0, shear_coef = 0;
  bool enabled = true, adaptive = false;
  GaussLegendreRule rule{16};
  // The involute integrals of a tooth without a spall from any contact to
  // the root (empty when the rule or QAGS integrates each contact anew).
  CumulativeIntegrals involute_integrals;

  Impl(int order) : rule(order) {}

  // Half-thickness in units of r_b at involute parameter alpha: H(alpha).
  double involute_H(double alpha) const {
    return std::sin(alpha) + (alpha2 - alpha) * std::cos(alpha);
  }
  double alpha_at_radius(double r) const {
    const double q = r / rb;
    return alpha2 - std::sqrt(std::max(q * q - 1.0, 0.0));
  }
  double half_thickness(double r) const { return r >= rb ? rb * involute_H(alpha_at_radius(r)) : h1; }

  // The densities below without a spall are sums of four functions of alpha
  // times powers of the load angle's cosine and sine:
  //   bending = 1.5/(E b) (F_0 + 2 c1 F_1 + c1^2 F_2),  F_i = L^i g / H^3,  L = tau sin(alpha) - cos(alpha),
  //   shear = 1.2 (1 + nu)/(E b) c1^2 J,  axial = 0.5/(E b) s1^2 J,  J = g / H.
  // Their integrals from the contact to the root are tabulated per tooth.
  CumulativeIntegrals::Values separable_densities(double alpha) const {
    const double tau = alpha2 - alpha, sa = std::sin(alpha), ca = std::cos(alpha);
    const double g = tau * ca, H = sa + g, L = tau * sa - ca;
    const double F0 = g / (H * H * H);
    return {F0, L * F0, L * L * F0, g / H};
  }

  // The involute part without a spall from alpha = lo to hi: tabulated when
  // there is a table, else by the rule (or QAGS).
  ToothCompliance plain_involute(double lo, double hi, double c1, double s1) const {
    if (involute_integrals.empty()) return involute_piece(lo, hi, c1, s1, 0.0, 0.0);
    if (!(hi > lo)) return {};
    CumulativeIntegrals::Values I = involute_integrals.from(lo);
    if (hi < alpha_u) {
      const CumulativeIntegrals::Values beyond = involute_integrals.from(hi);
      for (std::size_t k = 0; k < I.size(); ++k) I[k] -= beyond[k];
    }
    ToothCompliance total;
    total.bending = 1.5 * (I[0] + c1 * (2.0 * I[1] + c1 * I[2])) * inv_Eb;
    total.shear = shear_coef * c1 * c1 * I[3] * inv_Eb;
    total.axial = 0.5 * s1 * s1 * I[3] * inv_Eb;
    return total;
  }

  // Compliance densities per unit alpha of the involute part (docs/models/tooth.md),
  // with a pit of width ws / depth hs when both are positive (9.1-9.2).
  ToothCompliance density(double alpha, double c1, double s1, double ws, double hs) const {
    const double tau = alpha2 - alpha, sa = std::sin(alpha), ca = std::cos(alpha);
    const double g = tau * ca;           // -dx/dalpha / r_b
    const double H = sa + g;             // h_x / r_b
    const double N = 1.0 + c1 * (tau * sa - ca);  // lever of the unit load / r_b
    ToothCompliance d;
    if (ws > 0.0 && hs > 0.0) {
      const CantileverSection sec = tooth_slice_section(rb * H, b, ws, hs);
      // The axial part acts at h about the original centre line, i.e. at
      // h - e_s about the shifted centroid: (d-x) c1 - (h - e_s) s1 = r_b N + e_s s1.
      const double lever = rb * N + sec.centroid_offset * s1;
      d.bending = lever * lever * rb * g / (E * sec.second_moment);
      d.shear = 1.2 * c1 * c1 * rb * g / (G * sec.area);
      d.axial = s1 * s1 * rb * g / (E * sec.area);
    } else {
      const double gH = g / H;
      d.bending = 1.5 * N * N * gH / (H * H) * inv_Eb;
      d.shear = shear_coef * c1 * c1 * gH * inv_Eb;
      d.axial = 0.5 * s1 * s1 * gH * inv_Eb;
    }
    return d;
  }

  ToothCompliance involute_piece(double lo, double hi, double c1, double s1, double ws,
                                 double hs) const {
    ToothCompliance total;
    if (!(hi > lo)) return total;
    if (!adaptive) {
      const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
      const auto& x = rule.nodes();
      const auto& w = rule.weights();
      for (std::size_t i = 0; i < x.size(); ++i) {
        const ToothCompliance d = density(mid + half * x[i], c1, s1, ws, hs);
        total.bending += w[i] * d.bending;
        total.shear += w[i] * d.shear;
        total.axial += w[i] * d.axial;
      }
      total.bending *= half;
      total.shear *= half;
      total.axial *= half;
      return total;
    }
    // Reference mode: one QAGS per energy; workspace per call keeps at() const
    // and thread-safe.
    struct Params {
      const Impl* self;
      double c1, s1, ws, hs;
      int component;
    };
    auto trampoline = [](double alpha, void* p) -> double {
      const auto* q = static_cast<const Params*>(p);
      const ToothCompliance d = q->self->density(alpha, q->c1, q->s1, q->ws, q->hs);
      return q->component == 0 ? d.bending : (q->component == 1 ? d.shear : d.axial);
    };
    constexpr std::size_t kLimit = 200;
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws_ptr(
        gsl_integration_workspace_alloc(kLimit), &gsl_integration_workspace_free);
    if (!ws_ptr) throw std::runtime_error("GSL could not allocate an integration workspace");
    std::array<double, 3> out{};
    for (int c = 0; c < 3; ++c) {
      Params params{this, c1, s1, ws, hs, c};
      gsl_function f{trampoline, &params};
      double result = 0.0, err = 0.0;
      const int status =
          gsl_integration_qags(&f, lo, hi, 0.0, 1e-12, kLimit, ws_ptr.get(), &result, &err);
      // Round-off limits are acceptable when the estimate is still tight.
      if (status != GSL_SUCCESS && !(err <= 1e-9 * std::fabs(result))) {
        throw std::runtime_error(std::string("adaptive tooth quadrature failed: ") +
                                 gsl_strerror(status));
      }
      out[static_cast<std::size_t>(c)] = result;
    }
    total.bending = out[0];
    total.shear = out[1];
    total.axial = out[2];
    return total;
  }

  // Straight segment below the base circle, closed form (docs/models/tooth.md).
  // The cubic difference is factored so that cos(alpha_1) cancels exactly:
  // A^3 - B^3 = (A - B)(A^2 + AB + B^2), A - B = c1 (cos a2 - (r_f/r_b) cos a3).
  ToothCompliance segment_closed_form(double c1, double s1) const {
    const double A = 1.0 - c1 * rho_cos_a3, B = 1.0 - c1 * cos_a2;
    ToothCompliance d;
    d.bending = segment_ratio * (A * A + A * B + B * B) / (2.0 * sin3_a2) * inv_Eb;
    d.shear = shear_coef * c1 * c1 * segment_ratio / sin_a2 * inv_Eb;
    d.axial = 0.5 * s1 * s1 * segment_ratio / sin_a2 * inv_Eb;
    return d;
  }
};

PinionToothCompliance::PinionToothCompliance(const MeshGeometry& geometry,
                                             const PinionSpec& pinion, const Effects& effects,
                                             const Numerics& numerics) {
  auto impl = std::make_shared<Impl>(numerics.quadrature_order);
  Impl& m = *impl;
  m.enabled = effects.pinion_tooth;
  m.adaptive = numerics.adaptive_quadrature;
  if (m.adaptive) gsl_set_error_handler_off();  // GSL's default handler aborts

  const PinionGeometry& g = geometry.pinion;
  require_positive(g.base_radius, "pinion.base_radius", "base radius");
  require_positive(g.root_radius, "pinion.root_radius", "root radius");
  require_positive(g.tip_radius, "pinion.tip_radius", "tip radius");
  require_positive(g.half_base_angle, "pinion.half_base_angle", "half base angle alpha_2");
  require_positive(pinion.face_width, "pinion.face_width", "face width");
  require_positive(pinion.material.youngs_modulus, "pinion.material.youngs_modulus",
                   "Young's modulus");
  if (!(pinion.material.poisson_ratio > -1.0 && pinion.material.poisson_ratio < 0.5)) {
    throw InputError({}, "pinion.material.poisson_ratio", "Poisson ratio must be in (-1, 0.5)");
  }

  m.rb = g.base_radius;
  m.alpha2 = g.half_base_angle;
  m.rf = g.root_radius;
  m.ra = g.tip_radius;
  m.E = pinion.material.youngs_modulus;
  m.nu = pinion.material.poisson_ratio;
  m.G = pinion.material.shear_modulus();
  m.b = pinion.face_width;
  m.inv_Eb = 1.0 / (m.E * m.b);
  m.shear_coef = 1.2 * (1.0 + m.nu);
  m.sin_a2 = std::sin(m.alpha2);
  m.cos_a2 = std::cos(m.alpha2);
  m.sin3_a2 = m.sin_a2 * m.sin_a2 * m.sin_a2;
  m.h1 = m.rb * m.sin_a2;
  m.y_base = m.rb * m.cos_a2;

  if (m.ra <= m.rf) {
    throw InputError({}, "pinion", "tip radius " + mm(m.ra) + " must exceed root radius " + mm(m.rf));
  }
  if (m.involute_H(m.alpha_at_radius(m.ra)) <= 0.0) {
    throw DesignError("pointed_tooth", "pinion tooth is pointed below the tip radius " + mm(m.ra));
  }

  if (m.rf > m.rb) {
    m.alpha_u = m.alpha_at_radius(m.rf);
  } else {
    m.alpha_u = m.alpha2;
    if (m.h1 >= m.rf) {
      throw DesignError("root_too_small", "root radius " + mm(m.rf) +
                                              " is below the base half-thickness " + mm(m.h1));
    }
    const double alpha3 = std::asin(m.h1 / m.rf);
    m.rho_cos_a3 = m.rf / m.rb * std::cos(alpha3);
    m.y_root = m.rf * std::cos(alpha3);
    m.segment_ratio = m.cos_a2 - m.rho_cos_a3;
    m.segment = effects.root_segment && m.rf < m.rb;
  }
  if (m.enabled && !m.adaptive && numerics.quadrature_order >= kTabulatedFromOrder) {
    // From the highest contact at() accepts (the tip and its tolerance) to the root.
    const double t_max = std::sqrt(std::max(std::pow(m.ra * (1.0 + 1e-9) / m.rb, 2) - 1.0, 0.0));
    const double alpha_tip = std::min(m.alpha2 - t_max, m.alpha_u);
    if (alpha_tip < m.alpha_u) {
      m.involute_integrals = CumulativeIntegrals([&](double alpha) { return m.separable_densities(alpha); },
                                                 alpha_tip, m.alpha_u, kInvolutePanels, kInvolutePanelRatio);
    }
  }
  impl_ = std::move(impl);
}

double PinionToothCompliance::half_thickness_at_radius(double r) const {
  return impl_->half_thickness(r);
}

void PinionToothCompliance::validate(const SpallBand& spall) const {
  const Impl& m = *impl_;
  if (!spall_band_removes_material(spall)) return;
  const double tol = 1e-12 * m.ra;
  if (spall.low < m.rf - tol || spall.high > m.ra + tol) {
    throw DesignError("spall_off_profile", "pinion spall band [" + mm(spall.low) + ", " +
                                               mm(spall.high) + "] (radii) leaves the flank [" +
                                               mm(m.rf) + ", " + mm(m.ra) + "]");
  }
  if (spall.width > m.b) {
    throw DesignError("spall_too_wide", "pinion spall width " + mm(spall.width) +
                                            " exceeds the face width " + mm(m.b));
  }
  // h_x rises from the base circle up to alpha = 0 and falls beyond, so the
  // thinnest point of any band is one of its edges.
  const double thinnest = std::min(m.half_thickness(spall.low), m.half_thickness(spall.high));
  if (spall.depth >= 2.0 * thinnest) {
    throw DesignError("spall_too_deep", "pinion spall depth " + mm(spall.depth) +
                                            " reaches the full tooth thickness " +
                                            mm(2.0 * thinnest) + " inside the band");
  }
}

ToothCompliance PinionToothCompliance::at(double s, const SpallBand* spall) const {
  const Impl& m = *impl_;
  if (!m.enabled) return {};
  if (!std::isfinite(s)) throw InputError({}, "s", "contact position is not finite");
  if (spall) validate(*spall);

  const double t = std::max(s, 0.0) / m.rb;  // roll angle tan(alpha_k)
  if (m.rb * std::sqrt(1.0 + t * t) > m.ra * (1.0 + 1e-9)) {
    throw InputError({}, "s", "contact at s = " + mm(s) + " lies above the pinion tip");
  }
  const double alpha1 = t - m.alpha2;  // load angle
  const double c1 = std::cos(alpha1), s1 = std::sin(alpha1);
  const double lo = std::min(-alpha1, m.alpha_u);  // contact; clamped to the root when below it
  const double hi = m.alpha_u;

  const bool pitted = spall && spall->width > 0.0 && spall->depth > 0.0;
  ToothCompliance total;
  if (!pitted) {
    total = m.plain_involute(lo, hi, c1, s1);
  } else {
    // Band in alpha: the upper edge has the smaller alpha. Split so each piece
    // has a smooth integrand; only the part between contact and root counts.
    const double band_lo = std::max(m.alpha_at_radius(std::max(spall->high, m.rb)), lo);
    const double band_hi = std::min(m.alpha_at_radius(std::max(spall->low, m.rb)), hi);
    if (band_hi > band_lo) {
      const ToothCompliance p1 = m.plain_involute(lo, band_lo, c1, s1);
      const ToothCompliance p2 = m.involute_piece(band_lo, band_hi, c1, s1, spall->width, spall->depth);
      const ToothCompliance p3 = m.plain_involute(band_hi, hi, c1, s1);
      total.bending = p1.bending + p2.bending + p3.bending;
      total.shear = p1.shear + p2.shear + p3.shear;
      total.axial = p1.axial + p2.axial + p3.axial;
    } else {
      total = m.plain_involute(lo, hi, c1, s1);
    }
  }

  if (m.segment) {
    ToothCompliance seg;
    if (pitted && spall->low < m.rb) {
      // Spall reaching below the base circle: integrate the constant-thickness
      // segment numerically along the centre line with the reduced section.
      const double y_lo = std::clamp(std::sqrt(std::max(spall->low * spall->low - m.h1 * m.h1, 0.0)),
                                     m.y_root, m.y_base);
      const double y_hi = std::clamp(std::sqrt(std::max(spall->high * spall->high - m.h1 * m.h1, 0.0)),
                                     m.y_root, m.y_base);
      const double roll = alpha1 + m.alpha2;
      CantileverLoad load;
      load.position = m.rb * (c1 + roll * s1) - m.y_root;  // contact y_c above the root
      load.offset = m.rb * (roll * c1 - s1);                // contact half-thickness h
      load.transverse = c1;
      load.axial = s1;
      const CantileverMaterial mat{m.E, m.G, 1.2};
      const CantileverSection plain = tooth_slice_section(m.h1, m.b);
      const CantileverSection pit = tooth_slice_section(m.h1, m.b, spall->width, spall->depth);
      const double u_lo = y_lo - m.y_root, u_hi = y_hi - m.y_root;
      const std::array<double, 4> stations{0.0, u_lo, u_hi, m.y_base - m.y_root};
      seg = cantilever_compliance(
          [&](double u) { return (u > u_lo && u < u_hi) ? pit : plain; }, load, mat, stations,
          m.rule);
    } else {
      seg = m.segment_closed_form(c1, s1);
    }
    total.bending += seg.bending;
    total.shear += seg.shear;
    total.axial += seg.axial;
  }
  return total;
}

}  // namespace rackopt
