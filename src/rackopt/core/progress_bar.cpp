#include "rackopt/core/progress_bar.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <sys/ioctl.h>
#include <unistd.h>

namespace rackopt {
namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

std::string bar_text(double fraction, int width) {
  const int filled = std::clamp(static_cast<int>(fraction * width + 0.5), 0, width);
  return "[" + std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(width - filled), ' ') +
         "] ";
}

}  // namespace

std::string format_progress_line(const ProgressState& s, int width) {
  using End = ProgressState::End;
  const std::size_t room = static_cast<std::size_t>(std::max(width, 2) - 1);
  const bool done = s.end == End::kDone;
  // Done: the count is the total, whatever was planned.
  const long total = done ? s.done : s.total;
  const bool exact = total > 0 && s.done <= total && (!s.total_is_bound || done);
  std::string counts;
  if (exact) {
    counts = std::to_string(s.done) + "/" + std::to_string(total) + " " + s.what;
  } else if (total > 0 && s.total_is_bound && s.done <= total) {
    counts = std::to_string(s.done) + " " + s.what + " (budget " + std::to_string(total) + ")";
  } else {
    counts = std::to_string(s.done) + " " + s.what;
  }
  std::string time_text;
  std::string estimate;
  switch (s.end) {
    case End::kDone: time_text = "done in " + seconds(s.elapsed_s); break;
    case End::kStopped: time_text = "stopped after " + seconds(s.elapsed_s); break;
    case End::kRunning:
      time_text = seconds(s.elapsed_s);
      if (exact && s.done > 0) {
        const double frac = static_cast<double>(s.done) / static_cast<double>(total);
        estimate = ", ~" + seconds(s.elapsed_s * (1.0 / frac - 1.0)) + " left";
      }
      break;
  }
  std::string detail = s.detail;
  auto length = [&](const std::string& d, const std::string& est) {
    return counts.size() + (d.empty() ? 0 : 2 + d.size()) + 2 + time_text.size() + est.size();
  };
  // The detail gives way first (shortened, then dropped), then the estimate.
  if (length(detail, estimate) > room && !detail.empty()) {
    const std::size_t fixed = length("", estimate) + 2;
    if (fixed + 8 <= room) {
      detail.resize(room - fixed - 3);
      while (!detail.empty() && (detail.back() == ' ' || detail.back() == ',')) detail.pop_back();
      detail += "...";
    } else {
      detail.clear();
    }
  }
  if (length(detail, estimate) > room) estimate.clear();
  std::string line = counts + (detail.empty() ? "" : ", " + detail) + ", " + time_text + estimate;
  if (exact) {
    const std::size_t free = room > line.size() ? room - line.size() : 0;
    const int bar_width = static_cast<int>(std::min<std::size_t>(30, free >= 3 ? free - 3 : 0));
    if (bar_width >= 10) {
      line = bar_text(static_cast<double>(s.done) / static_cast<double>(total), bar_width) + line;
    }
  }
  if (line.size() > room) line.resize(room);
  return line;
}

int terminal_columns() {
  struct winsize ws{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
  if (const char* env = std::getenv("COLUMNS")) {
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && v > 0 && v < 10000) return static_cast<int>(v);
  }
  return 80;
}

ProgressBar::ProgressBar(long total, std::string what, bool force)
    : total_(total > 0 ? total : 0),
      what_(std::move(what)),
      enabled_(force || ::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(std::uncaught_exceptions() == 0); }

void ProgressBar::tick(long n) {
  done_.fetch_add(n);
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1)) return;
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_ || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(ProgressState::End::kRunning);
}

void ProgressBar::update(long done, long total, const std::string& detail, bool total_is_bound) {
  done_.store(done);
  total_.store(total);
  bound_.store(total_is_bound);
  if (!enabled_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  detail_ = detail;
  const auto now = std::chrono::steady_clock::now();
  if (finished_ || now - start_ < std::chrono::seconds(1) || now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  draw(ProgressState::End::kRunning);
}

void ProgressBar::finish(bool completed) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (!drawn_) return;
  draw(completed ? ProgressState::End::kDone : ProgressState::End::kStopped);
  std::fputc('\n', stderr);
  std::fflush(stderr);
}

void ProgressBar::draw(ProgressState::End end) {
  ProgressState s;
  s.done = done_.load();
  s.total = total_.load();
  s.total_is_bound = bound_.load();
  s.what = what_;
  s.detail = detail_;
  s.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  s.end = end;
  const std::string line = format_progress_line(s, terminal_columns());
  // Blank what is left of a longer previous line.
  const std::string pad(last_length_ > line.size() ? last_length_ - line.size() : 0, ' ');
  std::fprintf(stderr, "\r%s%s", line.c_str(), pad.c_str());
  std::fflush(stderr);
  last_length_ = line.size();
  drawn_ = true;
}

}  // namespace rackopt
