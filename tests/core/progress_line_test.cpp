// The progress line as a pure function of its state and the terminal width.
#include "rackopt/core/progress_bar.hpp"

#include <gtest/gtest.h>

#include <string>

namespace rackopt {
namespace {

ProgressState state(long done, long total, bool bound, ProgressState::End end = ProgressState::End::kRunning) {
  ProgressState s;
  s.done = done;
  s.total = total;
  s.total_is_bound = bound;
  s.what = "evaluations";
  s.detail = "best 0.0312, 2 failed, pareto point 3";
  s.elapsed_s = 2.0;
  s.end = end;
  return s;
}

TEST(ProgressLine, ExactTotalShowsBarCountsAndEstimate) {
  const std::string line = format_progress_line(state(100, 400, false), 200);
  EXPECT_EQ(line, "[########                      ] 100/400 evaluations, best 0.0312, 2 failed, pareto point 3, "
                  "2.0 s, ~6.0 s left");
}

// A finished Pareto run used to show "475/1601 ... ~5.7 s left".
TEST(ProgressLine, DoneShowsCountOverCountAndNoTimeLeft) {
  const std::string line = format_progress_line(state(475, 1601, true, ProgressState::End::kDone), 200);
  EXPECT_NE(line.find("475/475 evaluations"), std::string::npos) << line;
  EXPECT_NE(line.find("done in 2.0 s"), std::string::npos) << line;
  EXPECT_EQ(line.find("left"), std::string::npos) << line;
  EXPECT_EQ(line.find("1601"), std::string::npos) << line;
  EXPECT_EQ(line.rfind("[##############################] ", 0), 0u) << line;
}

TEST(ProgressLine, AnUpperBoundIsShownAsABudgetWithoutEstimate) {
  const std::string line = format_progress_line(state(475, 1601, true), 200);
  EXPECT_EQ(line, "475 evaluations (budget 1601), best 0.0312, 2 failed, pareto point 3, 2.0 s");
}

TEST(ProgressLine, StoppedSaysSo) {
  const std::string line = format_progress_line(state(120, 400, false, ProgressState::End::kStopped), 200);
  EXPECT_NE(line.find("120/400 evaluations"), std::string::npos) << line;
  EXPECT_NE(line.find("stopped after 2.0 s"), std::string::npos) << line;
  EXPECT_EQ(line.find("left"), std::string::npos) << line;
}

TEST(ProgressLine, UnknownTotalOrPastItShowsTheCountOnly) {
  EXPECT_EQ(format_progress_line(state(7, 0, false), 200), "7 evaluations, best 0.0312, 2 failed, pareto point 3, 2.0 s");
  EXPECT_EQ(format_progress_line(state(500, 400, false), 200).rfind("500 evaluations, ", 0), 0u);
}

TEST(ProgressLine, NeverWiderThanTheTerminalMinusOne) {
  for (int width = 2; width <= 160; ++width) {
    for (const auto& s : {state(100, 400, false), state(475, 1601, true), state(475, 1601, true, ProgressState::End::kDone),
                          state(3, 0, false), state(12, 400, false, ProgressState::End::kStopped)}) {
      const std::string line = format_progress_line(s, width);
      EXPECT_LE(line.size(), static_cast<std::size_t>(width - 1)) << width << ": " << line;
      EXPECT_EQ(line.find_first_of("\r\n"), std::string::npos);
    }
  }
}

TEST(ProgressLine, NarrowTerminalsKeepTheCountsFirst) {
  // 80 columns: the bar gave way, everything else is there.
  EXPECT_EQ(format_progress_line(state(100, 400, false), 80),
            "100/400 evaluations, best 0.0312, 2 failed, pareto point 3, 2.0 s, ~6.0 s left");
  // 60 columns: the detail is shortened.
  const std::string l60 = format_progress_line(state(100, 400, false), 60);
  EXPECT_EQ(l60, "100/400 evaluations, best 0.0312, 2..., 2.0 s, ~6.0 s left");
  // 40 columns: no bar, no detail, the counts and the time.
  const std::string l40 = format_progress_line(state(100, 400, false), 40);
  EXPECT_EQ(l40.rfind("100/400 evaluations, 2.0 s", 0), 0u) << l40;
}

}  // namespace
}  // namespace rackopt
