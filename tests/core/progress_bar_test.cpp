// ProgressBar (core/progress_bar.hpp) as a program's stderr sees it: nothing
// for short runs or when stderr is not a terminal (unless forced), "\r" +
// the line for a long run, the done or stopped line and one '\n' at the
// end. format_progress_line's text itself is progress_line_test.cpp's.
#include "rackopt/core/progress_bar.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "support/file_text.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

// Points this process's stderr at a file (not a terminal) while it lives,
// with COLUMNS set so the width does not depend on where the test runs.
class CapturedStderr {
 public:
  explicit CapturedStderr(const std::string& name) : path_(test_support::scratch_dir("progress_bar") + "/" + name) {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
    ::setenv("COLUMNS", "120", 1);
  }
  ~CapturedStderr() { restore(); }
  // What was written so far.
  std::string text() {
    std::fflush(stderr);
    return test_support::read_text(path_);
  }
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
    ::unsetenv("COLUMNS");
  }

 private:
  std::string path_;
  int saved_ = -1;
};

// The bar draws nothing during a run's first second.
void wait_past_the_first_second() { std::this_thread::sleep_for(std::chrono::milliseconds(1100)); }

long count(const std::string& text, char c) { return static_cast<long>(std::count(text.begin(), text.end(), c)); }

TEST(ProgressBar, NotATerminalAndNotForcedPrintsNothing) {
  CapturedStderr err("not_forced.txt");
  {
    ProgressBar bar(10, "samples");
    bar.tick(3);
    wait_past_the_first_second();
    bar.tick(2);
    bar.update(6, 10, "best 1");
    EXPECT_EQ(bar.done(), 6);  // it still counts
    bar.finish(true);
  }
  EXPECT_EQ(err.text(), "");
}

TEST(ProgressBar, AShortRunPrintsNothingEvenWhenForced) {
  CapturedStderr err("short.txt");
  {
    ProgressBar bar(10, "samples", true);
    for (int i = 0; i < 10; ++i) bar.tick();
    EXPECT_EQ(bar.done(), 10);
    bar.finish(true);
  }
  EXPECT_EQ(err.text(), "");  // not even the final '\n'
}

TEST(ProgressBar, ALongRunRedrawsOneLineAndFinishesItOnce) {
  CapturedStderr err("long.txt");
  ProgressBar bar(10, "samples", true);
  bar.tick(3);
  EXPECT_EQ(err.text(), "");  // within the first second
  wait_past_the_first_second();
  bar.tick(1);
  const std::string running = err.text();
  ASSERT_EQ(running.rfind("\r", 0), 0u) << running;  // redrawn in place
  EXPECT_NE(running.find("4/10 samples"), std::string::npos) << running;
  EXPECT_NE(running.find("left"), std::string::npos) << running;  // an exact total has an estimate
  EXPECT_EQ(count(running, '\n'), 0) << running;
  bar.tick(6);  // within 100 ms of the last draw: not necessarily drawn, but counted
  bar.finish(true);
  const std::string done = err.text();
  ASSERT_FALSE(done.empty());
  EXPECT_EQ(done.back(), '\n');
  EXPECT_EQ(count(done, '\n'), 1) << done;
  const std::string last = done.substr(done.rfind('\r') + 1);
  EXPECT_NE(last.find("10/10 samples"), std::string::npos) << last;
  EXPECT_NE(last.find("done in"), std::string::npos) << last;
  EXPECT_EQ(last.find("left"), std::string::npos) << last;
  EXPECT_LE(last.size() - 1, 119u) << last;  // at most COLUMNS - 1 (without the '\n')
  bar.finish(true);  // later calls do nothing
  bar.finish(false);
  EXPECT_EQ(err.text(), done);
}

TEST(ProgressBar, UpdateShowsTheDetailAndABudgetAndStoppedEndsIt) {
  CapturedStderr err("update.txt");
  {
    ProgressBar bar(0, "evaluations", true);
    wait_past_the_first_second();
    bar.update(12, 400, "best 0.25, 1 failed", true);
    const std::string running = err.text();
    EXPECT_NE(running.find("12 evaluations (budget 400), best 0.25, 1 failed"), std::string::npos) << running;
    bar.finish(false);
  }
  const std::string text = err.text();
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_NE(last.find("stopped after"), std::string::npos) << last;
  EXPECT_EQ(count(text, '\n'), 1) << text;
}

// A shorter line after a longer one leaves no characters of the longer one.
TEST(ProgressBar, AShorterLineBlanksWhatIsLeftOfTheLongerOne) {
  CapturedStderr err("blank.txt");
  ProgressBar bar(0, "evaluations", true);
  wait_past_the_first_second();
  bar.update(5, 0, "a long detail that makes this line wide");
  const std::string first = err.text();
  ASSERT_FALSE(first.empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // past the redraw interval
  bar.update(6, 0, "");
  const std::string both = err.text();
  ASSERT_GT(both.size(), first.size()) << both;
  const std::string second = both.substr(first.size());
  ASSERT_EQ(second.rfind("\r", 0), 0u) << second;
  EXPECT_EQ(second.size(), first.size()) << "'" << second << "'";  // padded to the longer line's width
  EXPECT_EQ(second.find("long detail"), std::string::npos) << second;
  bar.finish(true);
}

// The destructor ends the line: done normally, stopped when an exception
// is unwinding the stack.
TEST(ProgressBar, TheDestructorFinishesAsStoppedDuringAnException) {
  CapturedStderr err("unwind.txt");
  try {
    ProgressBar bar(10, "samples", true);
    wait_past_the_first_second();
    bar.tick(2);
    throw std::runtime_error("interrupted");
  } catch (const std::runtime_error&) {
  }
  const std::string text = err.text();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.substr(text.rfind('\r') + 1).find("stopped after"), std::string::npos) << text;
}

}  // namespace
}  // namespace rackopt
