#include "rackopt/stiffness/cantilever_energy.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt {

GaussLegendreRule::GaussLegendreRule(int points) {
  if (points < 1 || points > 4096) {
    throw InputError({}, "numerics.quadrature_order",
                     "quadrature order " + std::to_string(points) + " outside 1..4096");
  }
  // GSL computes the table once here; per-call integration then allocates nothing.
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)>
      table(gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(points)),
            &gsl_integration_glfixed_table_free);
  if (!table) throw std::runtime_error("GSL could not build a Gauss-Legendre table");
  nodes_.resize(static_cast<std::size_t>(points));
  weights_.resize(static_cast<std::size_t>(points));
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (gsl_integration_glfixed_point(-1.0, 1.0, i, &nodes_[i], &weights_[i], table.get()) !=
        GSL_SUCCESS) {
      throw std::runtime_error("GSL could not return a Gauss-Legendre node");
    }
  }
}

CantileverSection tooth_slice_section(double half_thickness, double face_width,
                                      double spall_width, double spall_depth) {
  const double hx = half_thickness, b = face_width;
  CantileverSection s;
  s.area = 2.0 * hx * b;
  s.second_moment = 2.0 / 3.0 * hx * hx * hx * b;
  if (spall_width > 0.0 && spall_depth > 0.0) {
    const double ws = spall_width, hs = spall_depth, inner = hx - hs;
    s.area -= hs * ws;
    // Removed strip spans [hx - hs, hx] across ws: its moment about the centre
    // line is ws (hx^3 - inner^3)/3, its first moment ws hs (hx - hs/2).
    const double i_centre_line = s.second_moment - ws * (hx * hx * hx - inner * inner * inner) / 3.0;
    s.centroid_offset = -ws * hs * (hx - 0.5 * hs) / s.area;
    s.second_moment = i_centre_line - s.area * s.centroid_offset * s.centroid_offset;
  }
  return s;
}

}  // namespace rackopt
