#include <chrono>

#include "cli.hpp"

namespace rackopt::cli {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace rackopt::cli
