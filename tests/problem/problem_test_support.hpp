// Small helpers several problem-loader tests share (one definition, so the
// test files can be compiled together in a unity build).
#pragma once

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/input_error_expectations.hpp"

namespace rackopt::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;  // rad per degree
inline constexpr double kHB = 9.80665e6;                  // Pa per Brinell number

inline std::string problem_path(const std::string& name) {
  return std::string(RACKOPT_SOURCE_DIR) + "/problems/" + name;
}

// A small valid problem; line numbers matter to the tests that use it.
inline const char* const kMinimal =
    "pinion:\n"                   // 1
    "  teeth: 20\n"               // 2
    "  module: 10 mm\n"           // 3
    "  face_width: 50 mm\n"       // 4
    "rack:\n"                     // 5
    "  body_height: 80 mm\n"      // 6
    "  span: 2 m\n"               // 7
    "load:\n"                     // 8
    "  force: 10 kN\n";           // 9

// Where an InputError must point and what its message must contain.
struct Expected {
  int line;
  int column;
  std::string key;
  std::string fragment;  // must appear in the message
  std::string file = "t.yaml";
};

// Loads `text` as "t.yaml" with `overrides` and checks it throws the InputError `want`.
inline void expect_error(const std::string& text, const Expected& want, const std::vector<std::string>& overrides = {}) {
  test_support::expect_input_error([&] { (void)load_problem_text(text, "t.yaml", overrides); },
                                   {.file = want.file, .line = want.line, .column = want.column, .key = want.key,
                                    .in_message = {want.fragment}});
}

}  // namespace rackopt::test
