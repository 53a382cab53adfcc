// The problem files shipped in problems/, by file name: tests that check a
// model against a paper or a documented example use the same file a user
// runs, not a copy of its values.
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"

namespace rackopt::test_support {

// problems/<file> of the source tree, e.g. "rack_railway.yaml".
inline std::string shipped_problem_path(const std::string& file) {
  return std::string(RACKOPT_SOURCE_DIR) + "/problems/" + file;
}

// problems/<file> loaded with `overrides` ("key=value", as --set).
inline Drive load_shipped_problem(const std::string& file, const std::vector<std::string>& overrides = {}) {
  return load_problem(shipped_problem_path(file), overrides);
}

}  // namespace rackopt::test_support
