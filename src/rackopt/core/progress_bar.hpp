// A progress bar on stderr for long runs: shown only when stderr is a
// terminal (or when forced) and the run has lasted longer than a second, so
// short runs, pipes and CI logs stay clean. Thread-safe: workers call tick().
// The line never exceeds the terminal's width, says when its total is only
// an upper bound (a study's evaluation budget), and its last state says how
// the run ended (done: count/count and the time taken; stopped).
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace rackopt {

// Everything one progress line shows.
struct ProgressState {
  enum class End { kRunning, kDone, kStopped };
  long done = 0;
  long total = 0;               // <= 0: unknown
  bool total_is_bound = false;  // total is an upper bound (a budget), not the expected count
  std::string what;             // "samples", "evaluations"
  std::string detail;           // "best 0.231, 2 failed"; may be empty
  double elapsed_s = 0;
  End end = End::kRunning;
};

// The line for `s` in a terminal `width` columns wide, without '\r' or '\n'
// and at most width - 1 characters (the last column would wrap on some
// terminals). Running with an exact total: "[####   ] 120/400 samples,
// <detail>, 3.2 s, ~5.7 s left"; with an upper bound: "120 evaluations
// (budget 400), <detail>, 3.2 s" (no estimate: the run may end long before);
// done: "[#######] 475/475 evaluations, <detail>, done in 3.2 s"; stopped:
// "... stopped after 3.2 s". What does not fit goes in this order: the bar
// narrows (to 10, then none), the detail is shortened then dropped, the
// estimate is dropped, then the line is cut.
std::string format_progress_line(const ProgressState& s, int width);

// Columns of the terminal on stderr (TIOCGWINSZ), else the COLUMNS
// environment variable, else 80.
int terminal_columns();

class ProgressBar {
 public:
  // total > 0 units of work described by `what` ("samples", "evaluations").
  // force = true shows the bar even when stderr is not a terminal.
  ProgressBar(long total, std::string what, bool force = false);
  // finish() if it was not called: done, or stopped when an exception is
  // unwinding the stack.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // One more unit done; redraws at most ten times a second.
  void tick(long n = 1);
  long done() const { return done_.load(); }

  // Absolute progress for runs that report it themselves (a study): `done`
  // units of `total` (total <= 0: unknown, no bar and no estimate, or the
  // total grew past it), total_is_bound when `total` is only an upper bound,
  // and `detail` shown after the counts ("best 0.231, 2 failed"). Same
  // drawing rules as tick(). Call from one thread at a time.
  void update(long done, long total, const std::string& detail, bool total_is_bound = false);

  // The run ended: `completed` draws the done line (count/count, time
  // taken), else the stopped line; then the line is finished with '\n' (only
  // when something was drawn). Later calls do nothing.
  void finish(bool completed);

 private:
  void draw(ProgressState::End end);
  std::atomic<long> total_;
  std::atomic<bool> bound_{false};
  std::string what_;
  std::string detail_;  // guarded by mutex_
  bool enabled_;
  std::atomic<long> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
  bool finished_ = false;
  std::size_t last_length_ = 0;
  std::mutex mutex_;
};

}  // namespace rackopt
