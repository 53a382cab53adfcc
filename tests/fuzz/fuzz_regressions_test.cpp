// Replays every input the fuzzer found (tests/fuzz/regressions/, one file
// each, named after what it broke) through the same function the fuzz target
// runs: each must now be refused with InputError/DesignError or load, never
// crash, hang, exhaust memory or throw anything else. Also replays the seed
// corpus (the shipped problems and studies), which must load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input_fuzz_case.hpp"

namespace rackopt::fuzz {
namespace {

namespace fs = std::filesystem;

const std::string kSource = RACKOPT_SOURCE_DIR;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> files_in(const fs::path& dir, const std::string& extension = "") {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(FuzzRegressions, EveryFoundInputIsHandled) {
  const auto files = files_in(kSource + "/tests/fuzz/regressions");
  ASSERT_FALSE(files.empty()) << "tests/fuzz/regressions/ holds the inputs the fuzzer found";
  for (const auto& f : files) {
    if (f.filename() == "README.md") continue;
    EXPECT_NO_THROW(run_input_fuzz_case(read_all(f), kSource + "/studies")) << f.filename();
  }
}

TEST(FuzzRegressions, SeedCorpusRunsClean) {
  for (const char* dir : {"/problems", "/studies"}) {
    for (const auto& f : files_in(kSource + dir, ".yaml")) {
      EXPECT_NO_THROW(run_input_fuzz_case(read_all(f), kSource + "/studies")) << f;
    }
  }
}

}  // namespace
}  // namespace rackopt::fuzz
