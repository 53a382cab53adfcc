// Helpers the marked_yaml tests share (one definition, so the test files can
// be compiled together in a unity build).
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt::test {

// Runs `load` and checks that it throws an InputError at line:column of
// "t.yaml" naming `key` with `fragment` in its message.
inline void expect_input_error(const std::function<void()>& load, int line, int column, const std::string& key,
                               const std::string& fragment) {
  try {
    load();
    ADD_FAILURE() << "no error; expected " << fragment;
  } catch (const InputError& e) {
    EXPECT_EQ(e.mark().file, "t.yaml") << e.what();
    EXPECT_EQ(e.mark().line, line) << e.what();
    EXPECT_EQ(e.mark().column, column) << e.what();
    EXPECT_EQ(e.key_path(), key) << e.what();
    EXPECT_NE(e.message().find(fragment), std::string::npos) << "message: " << e.message() << "\nwanted: " << fragment;
  }
}

}  // namespace rackopt::test
