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

 private:
  void draw(bool final_line);
  long total_;
  std::string what_;
  bool enabled_;
  std::atomic<long> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
  std::mutex mutex_;
};

}  // namespace rackopt
