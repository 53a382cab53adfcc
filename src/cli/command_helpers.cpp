#include <chrono>
#include <iostream>

#include "cli.hpp"

namespace rackopt::cli {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void report_stale_temporaries(const rackopt::FolderLock& lock) {
  for (const std::string& name : lock.removed()) {
    std::cerr << "rackopt: removed " << name << ", a temporary file left by an interrupted run\n";
  }
}

}  // namespace rackopt::cli
