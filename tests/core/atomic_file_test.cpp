// The one atomic writer (core/atomic_file.hpp): the file appears whole with
// its content and ordinary permissions, or not at all, and no temporary file
// is left either way. Write failures under a real size limit are tested with
// the output folder's wrapper (tests/output/output_files_test.cpp).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "rackopt/core/atomic_file.hpp"
#include "rackopt/core/file_text.hpp"
#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

using test_support::read_text;
using test_support::scratch_dir;

std::size_t files_in(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
  return n;
}

TEST(AtomicFile, WritesTheContentReadableAndLeavesNoTemporary) {
  const std::string dir = scratch_dir("ok");
  const std::string path = dir + "/sub/table.csv";  // the parent is created
  write_file_atomically(path, "a,b\n1,2\n");
  EXPECT_EQ(read_text(path), "a,b\n1,2\n");
  struct stat st{};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
  EXPECT_EQ(files_in(dir + "/sub"), 1u);
  // Replacing keeps one file with the new content.
  write_file_atomically(path, "x\n");
  EXPECT_EQ(read_text(path), "x\n");
  EXPECT_EQ(files_in(dir + "/sub"), 1u);
}

TEST(AtomicFile, AFailedCheckLeavesTheOldFileAndNoTemporary) {
  const std::string dir = scratch_dir("check");
  const std::string path = dir + "/summary.json";
  write_file_atomically(path, "old\n");
  std::string seen;
  try {
    write_file_atomically(path, "new\n", [&](const std::string& tmp) {
      seen = read_text(tmp);  // the check sees the written bytes
      return std::string("not valid");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not valid"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(seen, "new\n");
  EXPECT_EQ(read_text(path), "old\n");
  EXPECT_EQ(files_in(dir), 1u);
}

TEST(AtomicFile, EmptyContentAndAnUnwritableFolderAreRefused) {
  const std::string dir = scratch_dir("refused");
  EXPECT_THROW(write_file_atomically(dir + "/empty.csv", ""), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir + "/empty.csv"));
  // A file where the folder should be.
  write_file_atomically(dir + "/blocker", "x\n");
  EXPECT_THROW(write_file_atomically(dir + "/blocker/inside.csv", "y\n"), std::runtime_error);
  EXPECT_EQ(files_in(dir), 1u);
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// The writer's bytes come back whole, binary included; a missing file is
// nullopt, not an empty text.
TEST(FileText, ReadsBackWhatTheAtomicWriterWrote) {
  const std::string dir = test_support::scratch_dir("file_text");
  const std::string bytes = std::string("a\0b\r\n", 5) + std::string(100000, 'x');
  write_file_atomically(dir + "/f.bin", bytes);
  EXPECT_EQ(read_file_text(dir + "/f.bin"), bytes);
  EXPECT_EQ(read_file_text(dir + "/missing"), std::nullopt);
}

}  // namespace
}  // namespace rackopt
