// The limits on the counts a caller hands a run directly, besides its files:
// Monte Carlo samples, random seeds, worker threads, stiffness positions per
// mesh period (docs/input_limits.md, "Run arguments"). One table for the
// file loaders, the command line and the library entry points (the Python
// bindings call those), so the three cannot accept different ranges.
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"

namespace rackopt {

// An inclusive range of whole numbers.
struct CountLimit {
  long lo;
  long hi;
};

// Monte Carlo samples of one reliability run (kMaxReliabilitySamples, drive.hpp).
inline constexpr CountLimit kSamplesLimit{1, kMaxReliabilitySamples};
// A random seed: what an int holds with room to spare, as every file key.
inline constexpr CountLimit kSeedLimit{0, 2000000000L};
// Worker threads; 0 means one per core (parallel_for.hpp).
inline constexpr CountLimit kThreadsLimit{0, 1024};
// Travel samples per mesh period of a stiffness curve.
inline constexpr CountLimit kPositionsPerPeriodLimit{4, 10000};

// "lo .. hi", the way every range message writes it.
std::string range_text(CountLimit limit);

// Throws InputError at SourceMark{source} with key `name` ("samples",
// "metric_options.reliability_seed") when `value` is outside `limit`:
// "<arguments>: samples: -1 is out of range; allowed: 1 .. 1000000".
void check_count(long long value, CountLimit limit, const std::string& name, const std::string& source = "<arguments>");

// Throws InputError at SourceMark{path} when `path` holds a NUL byte: the
// system would open only the text before it, another file.
void check_path_text(const std::string& path, const std::string& what);

}  // namespace rackopt
