// What an InputError must say: where (file:line:column), which key, and
// fragments of its message. A field left unset is not checked, so each test
// states exactly what it relies on.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt::test_support {

struct ExpectedInputError {
  std::optional<std::string> file;
  std::optional<int> line;
  std::optional<int> column;
  std::optional<std::string> mark;  // the whole "file:line:column" (to_string of the mark)
  std::optional<std::string> key;
  std::vector<std::string> in_message;  // each in message()
  std::vector<std::string> in_what;     // each in what(): "file:line:column: key: message"
};

inline void expect_input_error_matches(const InputError& e, const ExpectedInputError& want) {
  const std::string what = e.what();
  if (want.file) {
    EXPECT_EQ(e.mark().file, *want.file) << what;
  }
  if (want.line) {
    EXPECT_EQ(e.mark().line, *want.line) << what;
  }
  if (want.column) {
    EXPECT_EQ(e.mark().column, *want.column) << what;
  }
  if (want.mark) {
    EXPECT_EQ(to_string(e.mark()), *want.mark) << what;
  }
  if (want.key) {
    EXPECT_EQ(e.key_path(), *want.key) << what;
  }
  for (const auto& part : want.in_message) {
    EXPECT_NE(e.message().find(part), std::string::npos) << "message: " << e.message() << "\nwanted: " << part;
  }
  for (const auto& part : want.in_what) {
    EXPECT_NE(what.find(part), std::string::npos) << "what: " << what << "\nwanted: " << part;
  }
}

// Calls `action`, which must throw an InputError matching `want`. Any other
// exception escapes and fails the test.
template <class Action>
void expect_input_error(Action&& action, const ExpectedInputError& want) {
  try {
    std::forward<Action>(action)();
    ADD_FAILURE() << "no InputError" << (want.key ? " for " + *want.key : std::string());
  } catch (const InputError& e) {
    expect_input_error_matches(e, want);
  }
}

}  // namespace rackopt::test_support
