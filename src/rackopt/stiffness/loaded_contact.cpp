#include "rackopt/stiffness/loaded_contact.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace rackopt {
namespace {

using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;

// The solution on one active set and how far it is from satisfying all
// conditions (0 = it is the solution).
struct Candidate {
  Vec f;                 // all n pairs (0 off the set)
  double delta = 0;
  double K = 0;          // 1^T C_A^-1 1
  double violation = 0;  // largest negative force or penetration, scaled
  unsigned mask = 0;     // the active set
};

}  // namespace

LoadedContact solve_loaded_contact(std::span<const double> C_in, std::span<const double> gap, double F) {
  const std::size_t n = gap.size();
  if (n == 0 || n > 8 || C_in.size() != n * n) {
    throw std::invalid_argument("solve_loaded_contact: need 1..8 pairs and an n x n matrix");
  }
  if (!(F >= 0) || !std::isfinite(F)) throw std::invalid_argument("solve_loaded_contact: load must be >= 0");
  Mat C(n, n);
  Vec g(n);
  double c_scale = 0, g_scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    g[i] = gap[i];
    g_scale = std::max(g_scale, std::abs(gap[i]));
    for (std::size_t k = 0; k < n; ++k) C(i, k) = C_in[i * n + k];
    c_scale = std::max(c_scale, C(i, i));
  }
  // Tolerances relative to the problem's own scales: forces against F,
  // displacements against the deflection F*c plus the gaps.
  const double F_scale = std::max(F, 1e-300);
  const double d_scale = std::max(F * c_scale + g_scale, 1e-300);
  const double f_tol = 1e-12 * F_scale;
  const double d_tol = 1e-12 * d_scale;

  auto try_set = [&](unsigned mask) {
    std::size_t idx[8];
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (mask & (1u << i)) idx[m++] = i;
    }
    Mat CA(m, m);
    Vec gA(m);
    for (std::size_t a = 0; a < m; ++a) {
      gA[a] = g[idx[a]];
      for (std::size_t b = 0; b < m; ++b) CA(a, b) = C(idx[a], idx[b]);
    }
    const Eigen::LLT<Mat> llt(CA);
    if (llt.info() != Eigen::Success) throw std::runtime_error("mesh flexibility matrix is not positive definite");
    const Vec u = llt.solve(Vec::Ones(m));  // C_A^-1 1
    const Vec w = llt.solve(gA);            // C_A^-1 g_A
    Candidate c;
    c.K = u.sum();
    if (!(c.K > 0) || !std::isfinite(c.K)) throw std::runtime_error("mesh flexibility matrix is not positive definite");
    // f_A = delta u - w with sum f_A = F.
    c.delta = (F + w.sum()) / c.K;
    c.mask = mask;
    c.f = Vec::Zero(n);
    for (std::size_t a = 0; a < m; ++a) {
      const double fa = c.delta * u[a] - w[a];
      c.f[idx[a]] = fa;
      if (fa < -f_tol) c.violation = std::max(c.violation, -fa / F_scale);
    }
    // Open pairs must not penetrate: (C f)_i + g_i - delta >= 0.
    const Vec Cf = C * c.f;
    for (std::size_t i = 0; i < n; ++i) {
      if (mask & (1u << i)) continue;
      const double gap_left = Cf[i] + g[i] - c.delta;
      if (gap_left < -d_tol) c.violation = std::max(c.violation, -gap_left / d_scale);
    }
    return c;
  };

  // n <= 8 (in practice 2..4): try the active sets, largest first. The
  // problem is strictly convex, so exactly one set satisfies all conditions
  // (up to ties at a threshold, where both give the same answer). Should
  // rounding leave none exact, the least violating one is taken.
  const unsigned full = (1u << n) - 1u;
  Candidate best;
  best.violation = std::numeric_limits<double>::infinity();
  for (int size = static_cast<int>(n); size >= 1 && best.violation > 0; --size) {
    for (unsigned mask = full; mask >= 1 && best.violation > 0; --mask) {
      if (std::popcount(mask) != size) continue;
      Candidate c = try_set(mask);
      if (c.violation < best.violation) best = std::move(c);
    }
  }
  LoadedContact out;
  out.approach = best.delta;
  out.tangent_stiffness = best.K;
  out.force.resize(n);
  out.loaded.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.force[i] = std::max(best.f[i], 0.0);
    out.loaded[i] = (best.mask & (1u << i)) != 0;
  }
  return out;
}

}  // namespace rackopt
