// Bundled problems for validation tests, loaded from problems/.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt::test {

inline Drive problem(const std::string& file, const std::vector<std::string>& overrides = {}) {
  return load_problem(std::string(RACKOPT_SOURCE_DIR) + "/problems/" + file, overrides);
}

}  // namespace rackopt::test
