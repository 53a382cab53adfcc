// A progress bar on stderr for long runs: shown only when stderr is a
// terminal and the run has lasted longer than a second (issue 3), so short
// runs, pipes and CI logs stay clean. Thread-safe: workers call tick().
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace rackopt {

class ProgressBar {
 public:
  // total > 0 units of work described by `what` ("samples", "evaluations").
  // force = true shows the bar even when stderr is not a terminal.
  ProgressBar(long total, std::string what, bool force = false);
  ~ProgressBar();  // finishes the line if anything was drawn
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // One more unit done; redraws at most ten times a second.
  void tick(long n = 1);
  long done() const { return done_.load(); }

  // Absolute progress for runs that report it themselves (a study): `done`
  // units of `total` (total <= 0: unknown, no bar and no estimate, or the
  // total grew past it), and `detail` shown after the counts ("best 0.231,
  // 2 failed"). Same drawing rules as tick(). Call from one thread at a time.
  void update(long done, long total, const std::string& detail);

 private:
  void draw(bool final_line);
  std::atomic<long> total_;
  std::string what_;
  std::string detail_;  // guarded by mutex_
  bool enabled_;
  std::atomic<long> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
  std::mutex mutex_;
};

}  // namespace rackopt
