// Integrals of a few smooth functions from a variable lower limit x to a fixed
// upper limit b, tabulated once so that each x costs a short polynomial
// evaluation instead of a quadrature of the functions.
//
// The pinion tooth's energy integrals run from the contact's involute angle
// to the root; their integrands do not depend on the contact otherwise (the
// load angle enters only as factors in front), so a curve that asks for
// hundreds of contacts integrates the same functions over nested intervals.
//
// [a, b] is cut into panels that shrink geometrically towards a (the pinion
// tip, where the integrands are steepest); on each panel every function is
// interpolated at kNodes Chebyshev points and the interpolant's
// antiderivative kept as a Chebyshev series. On smooth integrands the error
// falls geometrically with the degree; docs/accuracy.md has the measured
// error against adaptive quadrature.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace rackopt {

class CumulativeIntegrals {
 public:
  static constexpr std::size_t kFunctions = 4;
  static constexpr std::size_t kNodes = 12;  // Chebyshev points per panel
  using Values = std::array<double, kFunctions>;

  CumulativeIntegrals() = default;

  // Tabulates the integrals of f (x -> Values) over [x, b] for x in [a, b],
  // a < b, with `panels` panels, each `ratio` (>= 1) times wider than the
  // one nearer to a. f is called panels * kNodes times, inside (a, b).
  template <class F>
  CumulativeIntegrals(F&& f, double a, double b, int panels, double ratio);

  // The integrals of every function from x to b; x is clamped to [a, b].
  Values from(double x) const;

  bool empty() const { return edges_.empty(); }

 private:
  static constexpr std::size_t kTerms = kNodes + 1;  // antiderivative: one degree more
  struct Panel {
    // Chebyshev coefficients of each function's antiderivative on the
    // panel in t in [-1, 1], zero at t = 1 (the panel's upper edge).
    std::array<std::array<double, kTerms>, kFunctions> antiderivative{};
    Values beyond{};  // the integrals from the panel's upper edge to b
  };
  void set_panel(Panel& panel, const std::array<Values, kNodes>& samples) const;
  // Chebyshev points of the first kind, t_m = cos(pi (m + 1/2) / n).
  static const std::array<double, kNodes>& nodes();

  std::vector<double> edges_;  // panels + 1 increasing edges, edges_.front() = a, back() = b
  std::vector<Panel> panels_;
};

template <class F>
CumulativeIntegrals::CumulativeIntegrals(F&& f, double a, double b, int panels, double ratio) {
  const auto n = static_cast<std::size_t>(panels);
  edges_.resize(n + 1);
  double total = 0, width = 1;
  for (std::size_t p = 0; p < n; ++p, width *= ratio) total += width;
  edges_[0] = a;
  width = (b - a) / total;
  for (std::size_t p = 1; p < n; ++p, width *= ratio) edges_[p] = edges_[p - 1] + width;
  edges_[n] = b;
  panels_.resize(n);
  const auto& t = nodes();
  for (std::size_t p = 0; p < n; ++p) {
    const double mid = 0.5 * (edges_[p] + edges_[p + 1]), half = 0.5 * (edges_[p + 1] - edges_[p]);
    std::array<Values, kNodes> samples;
    for (std::size_t m = 0; m < kNodes; ++m) samples[m] = f(mid + half * t[m]);
    set_panel(panels_[p], samples);
  }
  // Each panel's own integral is its antiderivative's value at t = -1 (with
  // the sign flipped), times the half width.
  Values beyond{};
  for (std::size_t p = n; p-- > 0;) {
    panels_[p].beyond = beyond;
    const double half = 0.5 * (edges_[p + 1] - edges_[p]);
    for (std::size_t k = 0; k < kFunctions; ++k) {
      double at_minus_one = 0, sign = 1;
      for (double c : panels_[p].antiderivative[k]) {
        at_minus_one += sign * c;
        sign = -sign;
      }
      beyond[k] -= half * at_minus_one;
    }
  }
}

}  // namespace rackopt
