#include "rackopt/stiffness/curve_numerics.hpp"

#include <cmath>

namespace rackopt {

double lagrange_interval_integral(const double* xs, const double* ys, int n, double x1, double x2) {
  static const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double mid = 0.5 * (x1 + x2), half = 0.5 * (x2 - x1);
  // Lagrange basis with its denominators once per interval (one division
  // per node instead of one per node pair and Gauss point).
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
