#include "rackopt/stiffness/curve_numerics.hpp"

#include <cmath>

namespace rackopt {

double interval_integral(const double* xs, const double* ys, int n, double x1, double x2) {
  // Most intervals of a curve are the middle of four equally spaced samples:
  // there the cubic's integral is h (-y0 + 13 y1 + 13 y2 - y3) / 24, the same
  // polynomial without the Lagrange basis (the general path below differs
  // from it by rounding only).
  if (n == 4 && x1 == xs[1] && x2 == xs[2]) {
    const double h = x2 - x1, tol = 1e-9 * h;
    if (std::abs((xs[1] - xs[0]) - h) <= tol && std::abs((xs[3] - xs[2]) - h) <= tol) {
      return h * (13 * (ys[1] + ys[2]) - ys[0] - ys[3]) / 24;
    }
  }
  static const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double mid = 0.5 * (x1 + x2), half = 0.5 * (x2 - x1);
  // Lagrange basis with its denominators once per interval (one division
  // per node instead of one per node pair and Gauss point): this runs once
  // per sample of every curve.
  double c[8];
  for (int a = 0; a < n; ++a) {
    double den = 1;
    for (int b = 0; b < n; ++b) {
      if (b != a) den *= xs[a] - xs[b];
    }
    c[a] = ys[a] / den;
  }
  double sum = 0;
  for (int g = 0; g < 3; ++g) {
    const double x = mid + half * gx[g];
    double p = 0;
    for (int a = 0; a < n; ++a) {
      double l = c[a];
      for (int b = 0; b < n; ++b) {
        if (b != a) l *= x - xs[b];
      }
      p += l;
    }
    sum += gw[g] * p;
  }
  return sum * half;
}

}  // namespace rackopt
