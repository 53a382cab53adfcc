#include "rackopt/core/run_limits.hpp"

#include "rackopt/core/error.hpp"

namespace rackopt {

std::string range_text(CountLimit limit) { return std::to_string(limit.lo) + " .. " + std::to_string(limit.hi); }

void check_count(long long value, CountLimit limit, const std::string& name, const std::string& source) {
  if (value >= limit.lo && value <= limit.hi) return;
  throw InputError(SourceMark{source, 0, 0}, name,
                   std::to_string(value) + " is out of range; allowed: " + range_text(limit));
}

void check_path_text(const std::string& path, const std::string& what) {
  const std::size_t nul = path.find('\0');
  if (nul == std::string::npos) return;
  std::string shown;  // the NUL written as \0, so that the message shows the whole path
  for (char c : path) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
  throw InputError(SourceMark{shown, 0, 0}, "",
                   "the " + what + " path holds a NUL byte (at character " + std::to_string(nul + 1) +
                       "); no file name can");
}

}  // namespace rackopt
