#include "rackopt/doe/samplers.hpp"

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "rackopt/core/sobol_sequence.hpp"

namespace rackopt::doe {
namespace {

void check_box(std::span<const double> lower, std::span<const double> upper, const char* who) {
  if (lower.size() != upper.size()) {
    throw std::invalid_argument(std::string(who) + ": lower bounds have " +
                                std::to_string(lower.size()) + " entries but upper bounds " +
                                std::to_string(upper.size()));
  }
  if (lower.empty()) throw std::invalid_argument(std::string(who) + ": the box has no variable");
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if (!std::isfinite(lower[i]) || !std::isfinite(upper[i]) || lower[i] > upper[i]) {
      throw std::invalid_argument(std::string(who) + ": variable " + std::to_string(i) +
                                  " needs finite bounds with lower <= upper, got [" +
                                  std::to_string(lower[i]) + ", " + std::to_string(upper[i]) + "]");
    }
  }
}

// Uniform in [0, 1) from the top 53 bits: exact, portable (unlike
// std::uniform_real_distribution, whose algorithm is implementation-defined).
double unit_uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// Uniform integer in [0, bound) by rejection of the biased top range.
std::uint64_t uniform_below(std::mt19937_64& rng, std::uint64_t bound) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % bound;
  std::uint64_t r = rng();
  while (r >= limit) r = rng();
  return r % bound;
}

// Maps t in [0, 1] to [lo, hi], never stepping outside through rounding.
double to_box(double lo, double hi, double t) {
  const double v = lo + (hi - lo) * t;
  return v < lo ? lo : (v > hi ? hi : v);
}

}  // namespace

std::vector<std::vector<double>> full_grid(const std::vector<std::vector<double>>& levels,
                                           std::size_t max_points) {
  if (levels.empty()) throw std::invalid_argument("full_grid: no variable to sweep");
  std::size_t count = 1;
  for (std::size_t v = 0; v < levels.size(); ++v) {
    const std::size_t n = levels[v].size();
    if (n == 0) {
      throw std::invalid_argument("full_grid: variable " + std::to_string(v) + " has no level");
    }
    for (double x : levels[v]) {
      if (!std::isfinite(x)) {
        throw std::invalid_argument("full_grid: variable " + std::to_string(v) +
                                    " has a non-finite level");
      }
    }
    // count * n > max_points, tested without overflowing.
    if (count > max_points / n) {
      throw std::invalid_argument("full_grid: the grid has more than " +
                                  std::to_string(max_points) +
                                  " points (the limit); use fewer levels or a sampler "
                                  "(latin_hypercube, sobol)");
    }
    count *= n;
  }
  std::vector<std::vector<double>> points;
  points.reserve(count);
  std::vector<std::size_t> index(levels.size(), 0);  // odometer, last digit fastest
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<double>& p = points.emplace_back(levels.size());
    for (std::size_t v = 0; v < levels.size(); ++v) p[v] = levels[v][index[v]];
    for (std::size_t v = levels.size(); v-- > 0;) {
      if (++index[v] < levels[v].size()) break;
      index[v] = 0;
    }
  }
  return points;
}

std::vector<double> linspace_levels(double lo, double hi, int n) {
  if (n < 1) throw std::invalid_argument("linspace_levels: need at least 1 level, got " + std::to_string(n));
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw std::invalid_argument("linspace_levels: need finite lo <= hi, got [" + std::to_string(lo) +
                                ", " + std::to_string(hi) + "]");
  }
  if (n == 1) return {lo + 0.5 * (hi - lo)};
  std::vector<double> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    // Interpolating from both ends keeps each level within rounding of the
    // exact value and makes the last one exactly hi.
    const double t = static_cast<double>(i) / (n - 1);
    out[static_cast<std::size_t>(i)] = to_box(lo, hi, t);
  }
  out.back() = hi;
  return out;
}

std::vector<std::vector<double>> latin_hypercube(std::span<const double> lower,
                                                 std::span<const double> upper, std::size_t n,
                                                 std::uint64_t seed) {
  check_box(lower, upper, "latin_hypercube");
  const std::size_t dim = lower.size();
  std::vector<std::vector<double>> points(n, std::vector<double>(dim));
  if (n == 0) return points;
  std::mt19937_64 rng(seed);
  std::vector<std::size_t> stratum(n);
  for (std::size_t d = 0; d < dim; ++d) {
    for (std::size_t i = 0; i < n; ++i) stratum[i] = i;
    for (std::size_t i = n - 1; i > 0; --i) {  // Fisher-Yates
      std::swap(stratum[i], stratum[uniform_below(rng, i + 1)]);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double t = (static_cast<double>(stratum[i]) + unit_uniform(rng)) / static_cast<double>(n);
      points[i][d] = to_box(lower[d], upper[d], t);
    }
  }
  return points;
}

std::vector<std::vector<double>> sobol_points(std::span<const double> lower,
                                              std::span<const double> upper, std::size_t n,
                                              std::uint64_t seed) {
  check_box(lower, upper, "sobol_points");
  const std::size_t dim = lower.size();
  if (dim > kSobolMaxDimension || dim > sobol_max_dimension()) {
    throw std::invalid_argument("sobol_points: " + std::to_string(dim) +
                                " variables, but the Sobol sequence (GSL) supports at most " +
                                std::to_string(kSobolMaxDimension) +
                                "; use latin_hypercube for more variables");
  }
  if (n > kSobolMaxIndex) {
    throw std::invalid_argument("sobol_points: at most 2^30 - 1 points, asked for " + std::to_string(n));
  }
  std::vector<std::vector<double>> points(n, std::vector<double>(dim));
  if (n == 0) return points;

  // Digital-shift masks (30 bits per dimension); all zero for seed 0.
  std::vector<std::uint32_t> mask(dim, 0);
  if (seed != 0) {
    std::mt19937_64 rng(seed);
    for (auto& m : mask) m = static_cast<std::uint32_t>(rng() >> (64 - kSobolBits));
  }
  auto place = [&](std::vector<double>& p, std::size_t d, std::uint32_t k) {
    p[d] = to_box(lower[d], upper[d], static_cast<double>(k ^ mask[d]) / kSobolScale);
  };

  // From the origin (index 0) on.
  const std::vector<std::uint32_t> k = sobol_numerators(0, n, dim);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < dim; ++d) place(points[i], d, k[i * dim + d]);
  return points;
}

}  // namespace rackopt::doe
