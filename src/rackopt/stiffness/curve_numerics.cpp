#include "rackopt/stiffness/curve_numerics.hpp"

namespace rackopt {

double interval_integral(const double* xs, const double* ys, int n, double x1, double x2) {
  static const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double mid = 0.5 * (x1 + x2), half = 0.5 * (x2 - x1);
  double sum = 0;
  for (int g = 0; g < 3; ++g) {
    const double x = mid + half * gx[g];
    double p = 0;
    for (int a = 0; a < n; ++a) {
      double l = 1;
      for (int b = 0; b < n; ++b) {
        if (b != a) l *= (x - xs[b]) / (xs[a] - xs[b]);
      }
      p += ys[a] * l;
    }
    sum += gw[g] * p;
  }
  return sum * half;
}

}  // namespace rackopt
