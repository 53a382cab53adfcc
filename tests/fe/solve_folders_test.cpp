// Solve folders left behind by a killed run: each names its owner (pid and
// start token), a failed solve's folder is marked kept, and the first solve
// of a process removes the folders of ended owners only: a dead pid, a pid
// reused by another process (same pid, other start), but never a live
// owner's, a kept one, one without an owner file, another program's or a
// symbolic link.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/solve_folders.hpp"

namespace rackopt::fe {
namespace {

namespace fs = std::filesystem;

class Parent {
 public:
  Parent() {
    std::string pattern = (fs::temp_directory_path() / "rackopt-solve-folders-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    path_ = pattern;
  }
  ~Parent() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  // A solve folder `name` whose owner file says `pid` and `token`.
  fs::path folder(const std::string& name, long pid, const std::string& token) const {
    const fs::path d = path_ / name;
    fs::create_directories(d);
    std::ofstream(d / "owner") << "pid " << pid << "\nstart " << token << "\n";
    std::ofstream(d / "job.inp") << "*HEADING\n";
    return d;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The pid of a process that has ended (forked, exited, reaped).
long dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(SolveFolders, OnlyFoldersOfEndedOwnersAreRemoved) {
  const Parent p;
  const long me = ::getpid();
  const std::string my_token = process_start_token(static_cast<int>(me));
  ASSERT_FALSE(my_token.empty()) << "/proc/self/stat not readable";
  const long dead = dead_pid();
  const fs::path gone = p.folder("rackopt-ccx-dead01", dead, "boot/123");
  const fs::path reused = p.folder("rackopt-ccx-reuse1", me, "another-boot/42");  // our pid, not our start
  const fs::path live = p.folder("rackopt-ccx-live01", me, my_token);
  const fs::path kept = p.folder("rackopt-ccx-kept01", dead, "boot/123");
  std::ofstream(kept / "kept") << "kept for inspection: CalculiX exited with status 201\n";
  const fs::path ownerless = p.path() / "rackopt-ccx-noown1";
  fs::create_directories(ownerless);
  const fs::path other = p.folder("someone-else-dead", dead, "boot/123");
  const fs::path target = p.folder("target", dead, "boot/123");
  fs::create_directory_symlink(target, p.path() / "rackopt-ccx-link01");

  EXPECT_TRUE(solve_folder_owner_ended(static_cast<int>(dead), "boot/123"));
  EXPECT_TRUE(solve_folder_owner_ended(static_cast<int>(me), "another-boot/42"));
  EXPECT_FALSE(solve_folder_owner_ended(static_cast<int>(me), my_token));
  EXPECT_FALSE(solve_folder_owner_ended(static_cast<int>(me), ""));  // cannot tell: alive

  EXPECT_EQ(remove_abandoned_solve_folders(p.path().string()), 2);
  EXPECT_FALSE(fs::exists(gone));
  EXPECT_FALSE(fs::exists(reused));
  for (const fs::path& f : {live, kept, ownerless, other, target}) EXPECT_TRUE(fs::exists(f)) << f;
  EXPECT_TRUE(fs::is_symlink(p.path() / "rackopt-ccx-link01"));
  EXPECT_EQ(remove_abandoned_solve_folders((p.path() / "missing").string()), 0);  // no such parent: nothing, no throw
}

// Through run_ccx: its first solve under a parent removes a dead owner's
// folder; a failed solve's folder names this process and is marked kept, so
// a later clean-up leaves it.
TEST(SolveFolders, RunCcxCleansUpFirstAndMarksAFailedSolveKept) {
  const Parent p;
  const fs::path gone = p.folder("rackopt-ccx-dead02", dead_pid(), "boot/7");
  const fs::path fake = p.path() / "fake_ccx";
  std::ofstream(fake) << "#!/bin/sh\necho ' *ERROR in fake_ccx: no convergence'\nexit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  CcxOptions o;
  o.program = fake.string();
  o.work_parent = p.path().string();
  std::string deck;
  try {
    run_ccx("*HEADING\n", [](const std::string&) {}, o);
    FAIL() << "no CcxError";
  } catch (const CcxError& e) {
    deck = e.deck();
  }
  EXPECT_FALSE(fs::exists(gone));
  const fs::path folder = fs::path(deck).parent_path();
  ASSERT_TRUE(fs::exists(folder / "kept"));
  std::ifstream owner(folder / "owner");
  std::string key;
  long pid = 0;
  owner >> key >> pid;
  EXPECT_EQ(key, "pid");
  EXPECT_EQ(pid, static_cast<long>(::getpid()));
  std::ifstream kept(folder / "kept");
  std::string reason;
  std::getline(kept, reason);
  EXPECT_NE(reason.find("exited with status 1"), std::string::npos) << reason;
  EXPECT_EQ(remove_abandoned_solve_folders(p.path().string()), 0);
  EXPECT_TRUE(fs::exists(folder));
}

}  // namespace
}  // namespace rackopt::fe
