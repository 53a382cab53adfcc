// The one wrapper of GSL's Sobol sequence (gsl_qrng_sobol), as exact
// integers. Every value GSL returns is numerator / 2^30 (SOBOL_BIT_COUNT in
// gsl/qrng/sobol.c), so the numerators carry the sequence without rounding;
// each user turns them into its own points: the study sweeps with a digital
// shift (doe/samplers.hpp), the Monte Carlo with a random shift modulo 1
// (statistics/sampling.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rackopt {

inline constexpr int kSobolBits = 30;
inline constexpr double kSobolScale = 1073741824.0;  // 2^30: value = numerator / kSobolScale
// GSL's sequence counter overflows at 2^30 points.
inline constexpr std::size_t kSobolMaxIndex = (std::size_t{1} << kSobolBits) - 1;

// GSL's largest dimension (its direction-number table; above it GSL would
// silently return zeros).
std::size_t sobol_max_dimension();

// The numerators of sequence indices first .. first + count - 1, point after
// point (`dimension` each); index 0 is the origin, which GSL itself never
// returns. Throws std::invalid_argument for dimension 0 or above
// sobol_max_dimension(), or an index above kSobolMaxIndex, and
// std::runtime_error when GSL fails.
std::vector<std::uint32_t> sobol_numerators(std::size_t first, std::size_t count, std::size_t dimension);

}  // namespace rackopt
