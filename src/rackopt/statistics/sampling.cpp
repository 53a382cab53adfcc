#include "rackopt/statistics/sampling.hpp"


#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "rackopt/core/error.hpp"

namespace rackopt::statistics {

namespace {
[[noreturn]] void bad(const std::string& message) {
  throw InputError(SourceMark{}, "reliability.sampling", message);
}
// Distinct constants keep the three words of counter_uniform from cancelling.
constexpr std::uint64_t kStreamSalt = 0xD1B54A32D192ED03ULL;
constexpr std::uint64_t kCounterSalt = 0x8CB92BA72F3D8DD7ULL;
// Stream tag of the Cranley-Patterson shifts (far from any sample index).
constexpr std::uint64_t kShiftStream = 0xC0FFEE0000000001ULL;
constexpr double kSobolEdge = 1.0 / 2147483648.0;  // 2^-31
}  // namespace

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

double counter_uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  std::uint64_t h = mix64(seed);
  h = mix64(h ^ (stream * kStreamSalt));
  h = mix64(h ^ (counter * kCounterSalt));
  // (k + 0.5) 2^-53 with k in [0, 2^53): strictly inside (0,1).
  return (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53;
}

PointSet pseudo_random_points(std::size_t count, std::size_t dimension, std::uint64_t seed) {
  if (count < 1 || dimension < 1) bad("a point set needs at least one sample and one dimension");
  PointSet p{count, dimension, std::vector<double>(count * dimension)};
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < dimension; ++j) p.u[i * dimension + j] = counter_uniform(seed, i, j);
  return p;
}

PointSet sobol_points(std::size_t count, std::size_t dimension, bool randomize,
                      std::uint64_t seed) {
  if (count < 1 || dimension < 1) bad("a point set needs at least one sample and one dimension");
  if (dimension > sobol_max_dimension())
    bad("Sobol sampling supports at most " + std::to_string(sobol_max_dimension()) +
        " random inputs (GSL gsl_qrng_sobol), got " + std::to_string(dimension) +
        "; use pseudo-random sampling");
  if (count > (std::size_t{1} << 30))
    bad("Sobol sampling supports at most 2^30 points (GSL's 30-bit sequence), got " +
        std::to_string(count));
  PointSet p{count, dimension, std::vector<double>(count * dimension)};
  // Randomized: from the origin, which the shift moves inside; plain: from
  // index 1 (the origin is on the edge of every input's range).
  const std::vector<std::uint32_t> k = sobol_numerators(randomize ? 0 : 1, count, dimension);
  for (std::size_t i = 0; i < k.size(); ++i) p.u[i] = static_cast<double>(k[i]) / kSobolScale;
  if (randomize) {
    for (std::size_t j = 0; j < dimension; ++j) {
      const double s = counter_uniform(seed, kShiftStream, j);
      for (std::size_t i = 0; i < count; ++i) {
        double& u = p.u[i * dimension + j];
        u += s;
        if (u >= 1.0) u -= 1.0;
      }
    }
  }
  for (double& u : p.u) u = std::clamp(u, kSobolEdge, 1.0 - kSobolEdge);
  return p;
}

std::vector<SampleResult> evaluate_samples(std::size_t count, unsigned threads,
                                           const std::function<double(std::size_t)>& f,
                                           std::atomic<std::size_t>* completed) {
  std::vector<SampleResult> out(count);
  parallel_for(count, threads, [&](std::size_t i) {
    SampleResult& r = out[i];
    try {
      const double v = f(i);
      if (std::isfinite(v)) {
        r.status = SampleResult::Status::kOk;
        r.value = v;
      } else {
        r.status = SampleResult::Status::kFailed;
        r.code = "non_finite";
        r.message = "sample " + std::to_string(i) + " returned a non-finite value";
      }
    } catch (const DesignError& e) {
      r.status = SampleResult::Status::kDesignError;
      r.code = e.code();
      r.message = e.what();
    } catch (const InputError& e) {
      r.status = SampleResult::Status::kInputError;
      r.message = e.what();
    } catch (const std::exception& e) {
      r.status = SampleResult::Status::kFailed;
      r.message = e.what();
    } catch (...) {
      r.status = SampleResult::Status::kFailed;
      r.message = "unknown exception";
    }
    if (completed) completed->fetch_add(1);
  });
  return out;
}

}  // namespace rackopt::statistics
