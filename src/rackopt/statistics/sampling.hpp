// Point sets in the open unit cube (0,1)^d for Monte Carlo, and a
// thread-count-independent evaluator (docs/models/reliability.md).
//
// Determinism: every pseudo-random value is a pure function of
// (seed, sample index, dimension) -- a counter-based hash, no generator state --
// so the same seed gives bit-identical points whatever the thread count or the
// order in which samples are evaluated. Sobol points are generated serially
// (GSL's generator is sequential) before any thread starts.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rackopt/core/parallel_for.hpp"
#include "rackopt/core/sobol_sequence.hpp"  // sobol_max_dimension()

namespace rackopt::statistics {

// N points in d dimensions, row-major: point i, coordinate j is u[i*d + j].
// Every coordinate is strictly inside (0,1), never exactly 0 or 1, so that
// Distribution::quantile accepts it.
struct PointSet {
  std::size_t count = 0;
  std::size_t dimension = 0;
  std::vector<double> u;
  double at(std::size_t sample, std::size_t coordinate) const { return u[sample * dimension + coordinate]; }
};

// splitmix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix.
std::uint64_t mix64(std::uint64_t x);

// A uniform double in (0,1) from (seed, stream, counter) alone: 53 random bits
// from a nested mix64 of the three words, placed at the centre of their
// 2^-53 cell, so the result is never 0 or 1. Same inputs -> same value, always.
double counter_uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter);

// Pseudo-random points: coordinate j of sample i is counter_uniform(seed, i, j).
// count >= 1 and dimension >= 1, else InputError.
PointSet pseudo_random_points(std::size_t count, std::size_t dimension, std::uint64_t seed);

// Sobol points from GSL's gsl_qrng_sobol.
//  * dimension > sobol_max_dimension() throws InputError: GSL would silently
//    return all zeros there (docs/dependencies.md, "GSL 2.7").
//  * randomize = false: GSL's sequence as is. GSL skips the origin, so the first
//    point is (0.5, ..., 0.5); none of the first 2^30 points has a coordinate 0.
//  * randomize = true: Cranley-Patterson rotation u = frac(x + s) with one shift
//    s per dimension from counter_uniform(seed, ...), starting from the origin
//    (which the shift moves inside the cube), so the first 2^m points form the
//    complete shifted (t,m,s)-net. Different seeds give independent replicates
//    for QMC error estimates.
//  In both cases each coordinate is finally clamped to [2^-31, 1 - 2^-31] (half
//  GSL's 2^-30 resolution) so that it is never exactly 0 or 1.
// count < 1 or more than 2^30 points throws InputError.
PointSet sobol_points(std::size_t count, std::size_t dimension, bool randomize,
                      std::uint64_t seed);

// Outcome of one sample evaluation.
struct SampleResult {
  enum class Status { kOk, kDesignError, kInputError, kFailed };
  Status status = Status::kFailed;
  double value = 0.0;   // the function's result when status == kOk
  std::string code;     // DesignError::code() for kDesignError, "non_finite" for a NaN/inf result
  std::string message;  // what() of the exception, empty when ok
  bool ok() const { return status == Status::kOk; }
};

// Evaluates f(i) for i = 0..count-1 on `threads` std::threads (0 = 1 thread).
// Results are written by sample index, so the returned vector is identical for
// any thread count provided f(i) depends on i alone (give it the point from a
// PointSet, not from a shared generator). An exception from f(i) -- or a
// non-finite result -- is recorded in that sample's SampleResult (status and
// message) and the run goes on. Threads take samples from a shared atomic
// counter (dynamic load balance; costs do not need to be equal).
// `completed`, when given, is incremented after each sample (for a progress bar
// read by another thread).
std::vector<SampleResult> evaluate_samples(std::size_t count, unsigned threads,
                                           const std::function<double(std::size_t)>& f,
                                           std::atomic<std::size_t>* completed = nullptr);


}  // namespace rackopt::statistics
