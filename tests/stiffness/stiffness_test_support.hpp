// Small helpers several stiffness tests share (one definition, so the test
// files can be compiled together in a unity build).
#pragma once

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace rackopt::test {

constexpr double kPi = std::numbers::pi;
inline double deg(double d) { return d * kPi / 180.0; }
// Involute function inv(a) = tan a - a.
inline double inv(double a) { return std::tan(a) - a; }

// Integral of f over [a, b] by GSL's adaptive QAGS to the relative tolerance
// epsrel: the independent quadrature the closed forms are checked against.
inline double qags(const std::function<double(double)>& f, double a, double b, double epsrel) {
  gsl_set_error_handler_off();
  gsl_function F{[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
                 const_cast<std::function<double(double)>*>(&f)};
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  double r = 0, e = 0;
  gsl_integration_qags(&F, a, b, 0.0, epsrel, 1000, w, &r, &e);
  gsl_integration_workspace_free(w);
  return r;
}

}  // namespace rackopt::test
