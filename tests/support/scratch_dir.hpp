// Folders for a test's files under the temp dir, in a folder of this process
// alone that is removed when the program ends. The pid in its name keeps it
// apart from every other test process running at the same time: ctest -j
// runs each test case as a process of its own, and a sanitizer build or a
// second checkout may run the same program at once.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace rackopt::test_support {

inline std::filesystem::path scratch_root() {
  return std::filesystem::temp_directory_path() /
         (std::string("rackopt_") + RACKOPT_TEST_PROGRAM + "_" + std::to_string(::getpid()));
}

// `name` in the scratch folder with nothing there: for a folder the code
// under test must create itself (and for checking that it did not).
inline std::string scratch_path(const std::string& name) {
  const std::filesystem::path p = scratch_root() / name;
  std::filesystem::remove_all(p);
  return p.string();
}

// `name` in the scratch folder as an empty folder that exists.
inline std::string scratch_dir(const std::string& name) {
  const std::string p = scratch_path(name);
  std::filesystem::create_directories(p);
  return p;
}

namespace detail {

class RemoveScratchRoot : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scratch_root(), ec);
  }
};

// Registered once per program, whichever of its files include this header.
[[maybe_unused]] inline ::testing::Environment* const remove_scratch_root =
    ::testing::AddGlobalTestEnvironment(new RemoveScratchRoot);

}  // namespace detail

}  // namespace rackopt::test_support
