#include "rackopt/core/sobol_sequence.hpp"

#include <gsl/gsl_qrng.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace rackopt {

std::size_t sobol_max_dimension() { return gsl_qrng_sobol->max_dimension; }

std::vector<std::uint32_t> sobol_numerators(std::size_t first, std::size_t count, std::size_t dimension) {
  if (dimension == 0 || dimension > sobol_max_dimension())
    throw std::invalid_argument("the Sobol sequence (GSL) has 1 to " + std::to_string(sobol_max_dimension()) +
                                " dimensions, asked for " + std::to_string(dimension));
  if (count > 0 && first + count - 1 > kSobolMaxIndex)
    throw std::invalid_argument("the Sobol sequence (GSL) has at most 2^30 - 1 points after the origin, asked for "
                                "index " + std::to_string(first + count - 1));
  std::vector<std::uint32_t> out(count * dimension, 0);
  if (count == 0) return out;
  std::unique_ptr<gsl_qrng, decltype(&gsl_qrng_free)> q(
      gsl_qrng_alloc(gsl_qrng_sobol, static_cast<unsigned>(dimension)), &gsl_qrng_free);
  if (!q) throw std::runtime_error("GSL could not allocate the Sobol generator");
  std::vector<double> u(dimension);
  // gsl_qrng_get starts at index 1; the origin (index 0) stays all zeros.
  const std::size_t last = first + count - 1;
  for (std::size_t index = 1; index <= last; ++index) {
    if (gsl_qrng_get(q.get(), u.data()) != 0)
      throw std::runtime_error("the GSL Sobol generator failed at point " + std::to_string(index));
    if (index < first) continue;
    for (std::size_t d = 0; d < dimension; ++d)
      out[(index - first) * dimension + d] = static_cast<std::uint32_t>(std::llround(u[d] * kSobolScale));
  }
  return out;
}

}  // namespace rackopt
