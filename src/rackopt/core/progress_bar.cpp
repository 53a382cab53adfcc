#include "rackopt/core/progress_bar.hpp"

#include <cstdio>

#include <unistd.h>

namespace rackopt {

ProgressBar::ProgressBar(long total, std::string what, bool force)
    : total_(total > 0 ? total : 1),
      what_(std::move(what)),
      enabled_(force || ::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  if (drawn_) {
    std::lock_guard<std::mutex> lock(mutex_);
    draw(true);
  }
}

void ProgressBar::tick(long n) {
  done_.fetch_add(n);
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1)) return;
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(false);
}

void ProgressBar::update(long done, long total, const std::string& detail) {
  done_.store(done);
  total_.store(total);
  if (!enabled_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  detail_ = detail;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1) || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(false);
}

void ProgressBar::draw(bool final_line) {
  const long done = done_.load();
  const long total = total_.load();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string detail = detail_.empty() ? std::string() : ", " + detail_;
  if (total <= 0 || done > total) {
    std::fprintf(stderr, "\r%ld %s%s, %.1f s elapsed   ", done, what_.c_str(), detail.c_str(), elapsed);
  } else {
    const double frac = static_cast<double>(done) / static_cast<double>(total);
    const int width = 30;
    const int filled = static_cast<int>(frac * width + 0.5);
    std::string bar(static_cast<std::size_t>(std::min(filled, width)), '#');
    bar.resize(width, ' ');
    const double eta = done > 0 ? elapsed * (1.0 / frac - 1.0) : 0.0;
    std::fprintf(stderr, "\r[%s] %ld/%ld %s%s, %.1f s elapsed, ~%.1f s left   ", bar.c_str(), done, total,
                 what_.c_str(), detail.c_str(), elapsed, eta);
  }
  if (final_line) std::fputc('\n', stderr);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace rackopt
