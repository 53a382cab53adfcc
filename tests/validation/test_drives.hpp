// Bundled problems for validation tests, loaded from problems/.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::test {

inline Drive problem(const std::string& file, const std::vector<std::string>& overrides = {}) {
  return test_support::load_shipped_problem(file, overrides);
}

}  // namespace rackopt::test
