// The one thread pool: independent jobs by index on a few threads.
#pragma once

#include <cstddef>
#include <functional>

namespace rackopt {

// The thread count a "threads" setting means: `requested` when > 0, else
// every core the machine reports (at least 1).
unsigned resolve_threads(unsigned requested);

// What a caller may watch and steer while the jobs run (both may be empty).
struct ParallelControl {
  // Polled before each job is handed out (from the worker threads: must be
  // thread-safe); true hands out no more jobs, and parallel_for returns
  // normally once the jobs under way are done: the caller reports the stop.
  std::function<bool()> stop;
  // After each job, finished or failed, serialized: (jobs done, count).
  std::function<void(std::size_t done, std::size_t count)> progress;
};

// Runs body(i) for i = 0..count-1 on `threads` threads (0 counts as 1; never
// more threads than jobs; the calling thread is one of them). Threads take
// the next index from a shared counter, so jobs of unequal cost balance
// themselves. body must write only to slot i of its outputs: then the result
// does not depend on the thread count. An exception stops handing out work;
// once every thread has joined, the exception of the lowest index that threw
// is rethrown (the same one on any thread count when the jobs are
// deterministic).
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const ParallelControl& control = {});

}  // namespace rackopt
