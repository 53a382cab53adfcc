// Strain-energy compliance of a straight, non-uniform cantilever loaded by one
// inclined force, and the Gauss-Legendre rule used to integrate it.
//
// This is the common core of the tooth models (docs/models/tooth.md): a
// tooth is a cantilever clamped at its root (axial coordinate u = 0) and
// loaded at u = u_c by a unit force split into a transverse part (bending +
// shear) and a compressive axial part acting at a lateral offset from the
// reference line (the undamaged tooth centre line). The pinion tooth uses its
// own involute-parametrised integrals for speed; this generic form serves the
// spalled rack tooth, the pinion root segment with a spall, and the tests.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "rackopt/stiffness/tooth_compliance.hpp"

namespace rackopt {

// n-point Gauss-Legendre rule on [-1, 1], nodes and weights taken once from
// GSL's glfixed table. Exact for polynomials of degree <= 2n - 1.
// Throws InputError ("numerics.quadrature_order") for points < 1.
class GaussLegendreRule {
 public:
  explicit GaussLegendreRule(int points);
  std::size_t size() const { return nodes_.size(); }
  const std::vector<double>& nodes() const { return nodes_; }
  const std::vector<double>& weights() const { return weights_; }

  // Integral of f over [a, b] (a > b gives the negative, a == b gives 0).
  template <class F>
  double integrate(F&& f, double a, double b) const {
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) sum += weights_[i] * f(mid + half * nodes_[i]);
    return sum * half;
  }

 private:
  std::vector<double> nodes_, weights_;
};

// Cross-section of the cantilever at one station.
struct CantileverSection {
  double area = 0.0;             // A [m^2]
  double second_moment = 0.0;   // I about the section's own centroid [m^4]
  double centroid_offset = 0.0;  // e: centroid position from the reference line, + towards the loaded flank [m]
};

// Rectangular tooth slice of half-thickness h_x and face width b, optionally
// with a pit of width w_s (across the face) and depth h_s (into the loaded
// flank) cut from the loaded side (docs/models/tooth.md, exact form):
//   A_s = 2 h_x b - h_s w_s,
//   I_cl = (2/3) h_x^3 b - (1/3) w_s [h_x^3 - (h_x - h_s)^3]  (about the centre line),
//   e_s = -w_s h_s (h_x - h_s/2) / A_s,  I_s = I_cl - A_s e_s^2.
// No pit (w_s or h_s zero) gives A = 2 h_x b, I = (2/3) h_x^3 b, e = 0.
// Preconditions (checked by the callers that validate spalls): h_x > 0,
// 0 <= h_s <= 2 h_x, 0 <= w_s <= b, and not both h_s = 2 h_x and w_s = b.
CantileverSection tooth_slice_section(double half_thickness, double face_width,
                                      double spall_width = 0.0, double spall_depth = 0.0);

// A unit load on the cantilever.
struct CantileverLoad {
  double position = 0.0;    // u_c: axial coordinate of the load point from the root [m]
  double offset = 0.0;      // lateral position of the load point from the reference line
                            // (+ = loaded flank; the tooth half-thickness at the contact) [m]
  double transverse = 0.0;  // load component normal to the axis per unit load (cos of the load angle)
  double axial = 0.0;       // compressive component along the axis per unit load (sin of the load angle)
};

struct CantileverMaterial {
  double youngs_modulus = 0.0;  // E [Pa]
  double shear_modulus = 0.0;   // G [Pa]
  double shear_factor = 1.2;    // Timoshenko factor of a rectangle
};

// Compliance densities d(1/k)/du at one station (docs/models/tooth.md with the
// section's own centroid): bending M^2/(E I) with
// M = transverse (u_c - u) - axial (offset - e), shear kappa transverse^2/(G A),
// axial axial^2/(E A).
inline ToothCompliance cantilever_density(const CantileverSection& section,
                                          const CantileverLoad& load,
                                          const CantileverMaterial& material, double u) {
  const double moment = load.transverse * (load.position - u) -
                        load.axial * (load.offset - section.centroid_offset);
  ToothCompliance d;
  d.bending = moment * moment / (material.youngs_modulus * section.second_moment);
  d.shear = material.shear_factor * load.transverse * load.transverse /
            (material.shear_modulus * section.area);
  d.axial = load.axial * load.axial / (material.youngs_modulus * section.area);
  return d;
}

// Compliance [m/N] of the cantilever between the first and last entry of
// `stations` (ascending axial coordinates, usually 0 ... u_c with the
// discontinuities of the section in between). Each piece is integrated with
// `rule`; section_at(u) returns the CantileverSection at u.
template <class SectionAt>
ToothCompliance cantilever_compliance(SectionAt&& section_at, const CantileverLoad& load,
                                      const CantileverMaterial& material,
                                      std::span<const double> stations,
                                      const GaussLegendreRule& rule) {
  ToothCompliance total;
  for (std::size_t k = 0; k + 1 < stations.size(); ++k) {
    const double a = stations[k], b = stations[k + 1];
    if (!(b > a)) continue;
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    for (std::size_t i = 0; i < rule.size(); ++i) {
      const double u = mid + half * rule.nodes()[i];
      const ToothCompliance d = cantilever_density(section_at(u), load, material, u);
      const double w = rule.weights()[i] * half;
      total.bending += w * d.bending;
      total.shear += w * d.shear;
      total.axial += w * d.axial;
    }
  }
  return total;
}

}  // namespace rackopt
