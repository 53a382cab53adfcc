// Design-of-experiments samplers over a continuous box [lower, upper] (SI).
//
// Every sampler is a pure function of its arguments: the same seed gives the
// same points bit for bit, on any machine and with any number of threads (the
// samplers are serial and use a fixed engine, std::mt19937_64, with our own
// integer-to-real and shuffle mappings, never the implementation-defined
// std:: distributions). Discrete variables are snapped by the study layer;
// these functions only know continuous boxes.
//
// Bad arguments (empty box, lower > upper, non-finite bounds, too many points,
// Sobol dimension above 40) throw std::invalid_argument with a message naming
// the limit; the study layer turns it into an InputError at the YAML key.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rackopt::doe {

// Largest Sobol dimension: GSL's direction-number table stops at 40
// (gsl_qrng_sobol->max_dimension; GSL would silently return zeros above it).
inline constexpr std::size_t kSobolMaxDimension = 40;

// Cartesian product of per-variable levels. Point k lists one level of every
// variable; the first variable varies slowest and the last fastest (row-major,
// like nested for-loops written in variable order). Size = product of the
// level counts. Throws std::invalid_argument when there is no variable, a
// variable has no level, a level is not finite, or the product exceeds
// max_points (checked before anything is allocated).
std::vector<std::vector<double>> full_grid(const std::vector<std::vector<double>>& levels,
                                           std::size_t max_points = 1'000'000);

// n equally spaced levels from lo to hi, both ends exact (the last level is hi
// itself, not lo + (n-1)*step). n == 1 gives the centre (lo+hi)/2: a single
// level stands for the whole range. Throws std::invalid_argument for n < 1,
// non-finite ends or lo > hi (lo == hi gives n copies of lo).
std::vector<double> linspace_levels(double lo, double hi, int n);

// Latin hypercube of n points: each dimension's range is cut into n equal
// strata and every stratum holds exactly one point in every dimension. The
// stratum order is an independent random permutation per dimension, and the
// position inside a stratum is uniformly random (not centred), so each
// coordinate is marginally uniform on [lower, upper] and the design is not
// confined to a lattice. n == 0 gives no point; n == 1 gives one uniform
// random point. Dimensions with lower == upper are constant.
std::vector<std::vector<double>> latin_hypercube(std::span<const double> lower,
                                                 std::span<const double> upper, std::size_t n,
                                                 std::uint64_t seed);

// The first n points of the Sobol sequence (GSL's direction numbers, 30-bit
// resolution) mapped to the box, dimension 1..40.
//  * First point: unlike gsl_qrng_get, which skips it, the sequence starts at
//    its index-0 point (the origin of the unit cube before randomization), so
//    that the first 2^m points form a (t,m,s)-net: every coordinate hits each
//    of the 2^m equal intervals exactly once. Prefer n a power of two.
//  * seed == 0: the plain sequence; the first point is the lower corner, the
//    second the box centre, values are exact dyadic fractions of the range.
//  * seed != 0: a random digital shift: every coordinate's 30-bit integer is
//    XORed with a mask drawn from mt19937_64(seed), one mask per dimension.
//    This keeps the net property (so the balance above still holds) while
//    giving independent randomized replicates for different seeds.
// Points lie in [lower, upper). Throws std::invalid_argument above 40
// dimensions (use latin_hypercube there) or for n >= 2^30.
std::vector<std::vector<double>> sobol_points(std::span<const double> lower,
                                              std::span<const double> upper, std::size_t n,
                                              std::uint64_t seed);

}  // namespace rackopt::doe
