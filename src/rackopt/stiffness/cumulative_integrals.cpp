#include "rackopt/stiffness/cumulative_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rackopt {
namespace {

constexpr std::size_t kN = CumulativeIntegrals::kNodes;

// cos(pi j (m + 1/2) / n): the discrete cosine transform from the samples at
// the Chebyshev points to the interpolant's coefficients. Computed once per
// process, not per design.
const std::array<std::array<double, kN>, kN>& cosine_table() {
  static const auto table = [] {
    std::array<std::array<double, kN>, kN> c{};
    for (std::size_t j = 0; j < kN; ++j) {
      for (std::size_t m = 0; m < kN; ++m) {
        c[j][m] = std::cos(std::numbers::pi * static_cast<double>(j) * (static_cast<double>(m) + 0.5) /
                           static_cast<double>(kN));
      }
    }
    return c;
  }();
  return table;
}

}  // namespace

const std::array<double, CumulativeIntegrals::kNodes>& CumulativeIntegrals::nodes() {
  static const auto t = [] {
    std::array<double, kN> out{};
    for (std::size_t m = 0; m < kN; ++m) out[m] = cosine_table()[1][m];
    return out;
  }();
  return t;
}

void CumulativeIntegrals::set_panel(Panel& panel, const std::array<Values, kNodes>& samples) const {
  const auto& cos_jm = cosine_table();
  for (std::size_t k = 0; k < kFunctions; ++k) {
    // Interpolant c_0 / 2 + sum c_j T_j; c_n = c_{n+1} = 0 beyond its degree.
    std::array<double, kN + 2> c{};
    for (std::size_t j = 0; j < kN; ++j) {
      double sum = 0;
      for (std::size_t m = 0; m < kN; ++m) sum += samples[m][k] * cos_jm[j][m];
      c[j] = 2.0 / static_cast<double>(kN) * sum;
    }
    // Antiderivative term by term: the integral of T_j is
    // T_{j+1} / (2 (j + 1)) - T_{j-1} / (2 (j - 1)), so C_j = (c_{j-1} - c_{j+1}) / (2 j);
    // C_0 makes it vanish at t = 1, where every T_j is 1.
    auto& C = panel.antiderivative[k];
    double sum = 0;
    for (std::size_t j = 1; j < kTerms; ++j) {
      C[j] = (c[j - 1] - c[j + 1]) / (2.0 * static_cast<double>(j));
      sum += C[j];
    }
    C[0] = -sum;
  }
}

CumulativeIntegrals::Values CumulativeIntegrals::from(double x) const {
  x = std::clamp(x, edges_.front(), edges_.back());
  // The first edge above x (a handful of panels: a linear scan).
  std::size_t p = 0;
  while (p + 2 < edges_.size() && edges_[p + 1] <= x) ++p;
  const double lo = edges_[p], hi = edges_[p + 1];
  const double half = 0.5 * (hi - lo);
  const double t = (x - lo) / half - 1.0;
  const Panel& panel = panels_[p];
  Values out{};
  // Clenshaw's recurrence for sum C_j T_j(t), the functions side by side.
  std::array<double, kFunctions> b1{}, b2{};
  for (std::size_t j = kTerms; j-- > 1;) {
    for (std::size_t k = 0; k < kFunctions; ++k) {
      const double b0 = panel.antiderivative[k][j] + 2.0 * t * b1[k] - b2[k];
      b2[k] = b1[k];
      b1[k] = b0;
    }
  }
  for (std::size_t k = 0; k < kFunctions; ++k) {
    const double G = panel.antiderivative[k][0] + t * b1[k] - b2[k];  // antiderivative at t, 0 at t = 1
    out[k] = panel.beyond[k] - half * G;
  }
  return out;
}

}  // namespace rackopt
