// Numerics shared by the quantities read off a stiffness curve: the integral
// of a smooth piece through its samples and the refinement of an extreme
// between samples (docs/models/mesh.md "Sampling, extremes and mean").
#pragma once

#include <cmath>
#include <utility>

namespace rackopt {

// Integral over [x1, x2] of the Lagrange polynomial through the given points
// (2, 3 or 4 of them, x1 and x2 among them), by 3-point Gauss-Legendre: exact
// for cubics. The general path of interval_integral below.
double lagrange_interval_integral(const double* xs, const double* ys, int n, double x1, double x2);

// The same; inline for the common case of every curve (once per sample):
// the middle of four equally spaced samples, where the cubic's integral is
// h (-y0 + 13 y1 + 13 y2 - y3) / 24, the same polynomial without the
// Lagrange basis (the general path differs from it by rounding only).
inline double interval_integral(const double* xs, const double* ys, int n, double x1, double x2) {
  if (n == 4 && x1 == xs[1] && x2 == xs[2]) {
    const double h = x2 - x1, tol = 1e-9 * h;
    if (std::abs((xs[1] - xs[0]) - h) <= tol && std::abs((xs[3] - xs[2]) - h) <= tol) {
      return h * (13 * (ys[1] + ys[2]) - ys[0] - ys[3]) / 24;
    }
  }
  return lagrange_interval_integral(xs, ys, n, x1, x2);
}

// Minimizes f on [lo, hi] by golden-section search (f unimodal there), to
// x_tol in x. Returns (x, f(x)).
template <class F>
std::pair<double, double> golden_min(F&& f, double lo, double hi, double x_tol) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int it = 0; it < 200 && (b - a) > x_tol; ++it) {
    if (fc < fd) {
      b = d; d = c; fd = fc; c = b - g * (b - a); fc = f(c);
    } else {
      a = c; c = d; fc = fd; d = a + g * (b - a); fd = f(d);
    }
  }
  return fc < fd ? std::make_pair(c, fc) : std::make_pair(d, fd);
}

}  // namespace rackopt
