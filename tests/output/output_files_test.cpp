// Output files: what "verified" means per format, the atomic writer under a
// real write failure (RLIMIT_FSIZE in a forked child: writes past the limit
// fail with EFBIG, as on a full disk), the temporary-file names the cleanup
// matches, and the folder lock.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/file_check.hpp"
#include "rackopt/output/folder_lock.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

using test_support::scratch_dir;

std::string put(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The smallest valid PNG: signature, IHDR, IDAT, IEND (1x1 grey).
std::string tiny_png() {
  const unsigned char b[] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
                             0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
                             0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x08,
                             0xd7, 0x63, 0x60, 0x00, 0x00, 0x00, 0x02, 0x00, 0x01, 0xe2, 0x21, 0xbc, 0x33, 0x00,
                             0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  return std::string(reinterpret_cast<const char*>(b), sizeof b);
}

TEST(CheckOutputFile, PngNeedsSignatureAndIendAtTheEnd) {
  const std::string dir = scratch_dir("png");
  const std::string png = tiny_png();
  EXPECT_EQ(check_output_file(put(dir + "/a.png.tmp", png), "a.png"), "");
  EXPECT_EQ(check_output_file(put(dir + "/b.png.tmp", png.substr(0, png.size() - 5)), "b.png"),
            "no IEND chunk at the end (truncated PNG)");
  EXPECT_EQ(check_output_file(put(dir + "/c.png.tmp", "GIF89a" + png.substr(6)), "c.png"), "no PNG signature");
  EXPECT_EQ(check_output_file(put(dir + "/d.png.tmp", ""), "d.png"), "empty");
  EXPECT_EQ(check_output_file(dir + "/missing.png", "missing.png"), "missing");
}

TEST(CheckOutputFile, JsonMustBeOneCompleteValue) {
  EXPECT_EQ(check_json_complete("{\"a\": [1, 2, {\"b\": \"}]\\\"\"}]}\n"), "");
  EXPECT_EQ(check_json_complete("[]"), "");
  EXPECT_NE(check_json_complete("{\"a\": [1, 2"), "");
  EXPECT_NE(check_json_complete("{\"a\": \"unterminated}"), "");
  EXPECT_NE(check_json_complete("{} {}"), "");
  EXPECT_NE(check_json_complete("   "), "");
  const std::string dir = scratch_dir("json");
  EXPECT_EQ(check_output_file(put(dir + "/s.json.tmp.12", "{\"ok\":true}\n"), "summary.json"), "");
  EXPECT_NE(check_output_file(put(dir + "/t.json.tmp.12", "{\"ok\":tr"), "summary.json"), "");
}

TEST(CheckOutputFile, TextTablesEndWithANewlineAndHaveTheirSize) {
  const std::string dir = scratch_dir("csv");
  EXPECT_EQ(check_output_file(put(dir + "/a.csv", "x,y\n1,2\n"), "a.csv", 8), "");
  EXPECT_NE(check_output_file(put(dir + "/b.csv", "x,y\n1,"), "b.csv"), "");
  EXPECT_NE(check_output_file(put(dir + "/c.csv", "x,y\n1,2\n"), "c.csv", 9), "");  // short
  EXPECT_EQ(check_output_file(put(dir + "/d.svg", "<svg>\n</svg>\n"), "d.svg"), "");
  EXPECT_NE(check_output_file(put(dir + "/e.svg", "<svg>\n<g>"), "e.svg"), "");
  EXPECT_EQ(check_output_file(put(dir + "/f.html", "<!DOCTYPE html>\n<html>\n</html>\n"), "f.html"), "");
  EXPECT_EQ(check_output_file(put(dir + "/g.html", "<!DOCTYPE html>\n<html>\n<p>"), "g.html"),
            "no </html> at the end (truncated HTML)");
}

// A format the check does not know is refused, not published unverified.
TEST(CheckOutputFile, AnUnknownFormatIsRefused) {
  const std::string dir = scratch_dir("unknown");
  const std::string why = check_output_file(put(dir + "/deck.inp.tmp", "*NODE\n"), "deck.inp");
  EXPECT_NE(why.find("no completeness check for the format '.inp'"), std::string::npos) << why;
  EXPECT_NE(check_output_file(put(dir + "/README", "text\n"), "README"), "");
  EXPECT_THROW(write_file_atomic(dir + "/table.txt", "a\n"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir + "/table.txt"));
}

// Runs `body` in a forked child that may write at most `limit` bytes per
// file, SIGXFSZ ignored; returns the child's exit code.
template <class F>
int with_file_size_limit(long limit, F body) {
  const pid_t pid = fork();
  if (pid == 0) {
    const rlimit lim{static_cast<rlim_t>(limit), static_cast<rlim_t>(limit)};
    setrlimit(RLIMIT_FSIZE, &lim);
    signal(SIGXFSZ, SIG_IGN);
    _exit(body());
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(WriteFileAtomic, AWriteFailureLeavesNeitherTheFileNorATemporary) {
  const std::string dir = scratch_dir("full");
  const std::string path = dir + "/table.csv";
  std::string big;
  while (big.size() < 100000) big += "0.123456789,0.987654321\n";
  const int code = with_file_size_limit(16384, [&] {
    try {
      write_file_atomic(path, big);
      return 1;  // must not succeed
    } catch (const std::runtime_error& e) {
      return std::string(e.what()).find("table.csv") != std::string::npos ? 0 : 2;
    }
  });
  EXPECT_EQ(code, 0);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(dir)) << "a temporary file was left";
  // An older complete version is left as it was.
  write_file_atomic(path, "old\n");
  EXPECT_EQ(with_file_size_limit(16384, [&] {
              try {
                write_file_atomic(path, big);
              } catch (const std::runtime_error&) {
                return 0;
              }
              return 1;
            }),
            0);
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "old\n");
  // Under the limit it works.
  EXPECT_EQ(with_file_size_limit(1 << 20, [&] {
              write_file_atomic(path, big);
              return 0;
            }),
            0);
  EXPECT_EQ(fs::file_size(path), big.size());
}

TEST(WriteFileAtomic, RefusesToPublishIncompleteJson) {
  const std::string dir = scratch_dir("json_refused");
  EXPECT_THROW(write_file_atomic(dir + "/summary.json", "{\"ok\": tr"), std::runtime_error);
  EXPECT_THROW(write_file_atomic(dir + "/empty.csv", ""), std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(PublishVerified, ATruncatedImageIsRemovedNotRenamed) {
  const std::string dir = scratch_dir("publish");
  const std::string png = tiny_png();
  put(dir + "/p.png.tmp", png.substr(0, 40));
  EXPECT_EQ(publish_verified(dir + "/p.png.tmp", dir + "/p.png"), "no IEND chunk at the end (truncated PNG)");
  EXPECT_TRUE(fs::is_empty(dir));
  put(dir + "/q.png.tmp", png);
  EXPECT_EQ(publish_verified(dir + "/q.png.tmp", dir + "/q.png"), "");
  EXPECT_TRUE(fs::exists(dir + "/q.png"));
  EXPECT_FALSE(fs::exists(dir + "/q.png.tmp"));
}

TEST(StaleTemporaries, OnlyOurWritersNamesAreMatched) {
  EXPECT_TRUE(is_rackopt_temporary("summary.json.tmp.12345"));
  EXPECT_TRUE(is_rackopt_temporary("stiffness.png.tmp"));
  EXPECT_TRUE(is_rackopt_temporary("pareto.svg.tmp"));
  EXPECT_TRUE(is_rackopt_temporary(".evaluations.csv.tmpA1b2C3"));
  EXPECT_FALSE(is_rackopt_temporary("summary.json"));
  EXPECT_FALSE(is_rackopt_temporary("notes.tmp.txt"));
  EXPECT_FALSE(is_rackopt_temporary("x.tmp.12a"));
  EXPECT_FALSE(is_rackopt_temporary(".tmp.123"));
  EXPECT_FALSE(is_rackopt_temporary("data.tmp"));
  EXPECT_FALSE(is_rackopt_temporary(".evaluations.csv.tmpA1b-C3"));
}

TEST(FolderLock, ASecondHolderIsRefusedAndStaleTemporariesGo) {
  const std::string dir = scratch_dir("lock");
  put(dir + "/report.md.tmp.99999", "partial");
  put(dir + "/keep.txt", "mine");
  {
    const FolderLock lock(dir);
    ASSERT_EQ(lock.removed().size(), 1u);
    EXPECT_EQ(lock.removed()[0], "report.md.tmp.99999");
    EXPECT_FALSE(fs::exists(dir + "/report.md.tmp.99999"));
    EXPECT_TRUE(fs::exists(dir + "/keep.txt"));
    try {
      const FolderLock second(dir);
      ADD_FAILURE() << "a second lock was granted";
    } catch (const OutputFolderInUse& e) {
      EXPECT_NE(std::string(e.what()).find("(pid " + std::to_string(::getpid()) + ")"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(FolderLock{dir});  // released with the first
}

}  // namespace
}  // namespace rackopt
