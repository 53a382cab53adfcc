#include "rackopt/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rackopt {

unsigned resolve_threads(unsigned requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const ParallelControl& control) {
  const std::size_t nthreads = std::max<std::size_t>(1, std::min<std::size_t>(threads == 0 ? 1 : threads, count));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::size_t error_index = count;
  std::size_t done = 0;
  std::mutex mutex;  // error, error_index, done and the progress callback
  auto worker = [&] {
    for (;;) {
      if (failed.load() || (control.stop && control.stop())) return;
      const std::size_t i = next.fetch_add(1);
      if (i >= count) return;
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (i < error_index) {
          error = std::current_exception();
          error_index = i;
        }
        failed.store(true);
      }
      if (control.progress) {
        const std::lock_guard<std::mutex> lock(mutex);
        control.progress(++done, count);
      }
    }
  };
  if (nthreads == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(nthreads - 1);
    for (std::size_t t = 1; t < nthreads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace rackopt
