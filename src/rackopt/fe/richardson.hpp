// Observed order of convergence and Richardson extrapolation of a quantity
// computed on three meshes refined by a constant ratio (Roache, "Quantification
// of uncertainty in computational fluid dynamics", Annu. Rev. Fluid Mech. 1997):
// if f(h) = f* + C h^p, the levels h, h/r, h/r^2 give
//   p = ln((f1 - f0) / (f2 - f1)) / ln r,   f* = f2 + (f2 - f1) / (r^p - 1),
// both exact. A sequence that is not like that (its differences change sign,
// or do not shrink) gets a status saying so and no extrapolated value.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace rackopt::fe {

enum class ConvergenceStatus {
  kAsymptotic,   // monotone, the differences shrink: order and extrapolation valid
  kResolved,     // the finest difference is at the read resolution: f* = the finest value, order unknown
  kOscillating,  // the differences change sign: no order
  kDiverging,    // the differences do not shrink: no order
};

// "asymptotic", "resolved", "oscillating", "diverging".
std::string to_string(ConvergenceStatus status);

struct RichardsonEstimate {
  ConvergenceStatus status = ConvergenceStatus::kAsymptotic;
  double order = 0;         // observed p (NaN unless kAsymptotic)
  double extrapolated = 0;  // f* (the finest value when kResolved, NaN when no estimate)
  // Per level, coarse to fine: |f_k - f*| / |f*| (NaN when no estimate).
  std::vector<double> relative_error;
};

// `values` coarse to fine (at least three; the last three make the
// estimate, every level gets its error), each level's size 1/ratio of the
// previous. `resolution`: relative precision of the values (e.g. 1e-6 for
// seven printed digits); differences within it count as zero: a finest
// difference within it gives kResolved. Throws std::invalid_argument for
// fewer than three values, a non-finite value, ratio <= 1 or resolution < 0.
RichardsonEstimate richardson(std::span<const double> values, double ratio = 2, double resolution = 0);

}  // namespace rackopt::fe
