// The one thread pool: independent jobs by index on a few threads.
#pragma once

#include <cstddef>
#include <functional>

namespace rackopt {

// Runs body(i) for i = 0..count-1 on `threads` threads (0 counts as 1; never
// more threads than jobs; the calling thread is one of them). Threads take
// the next index from a shared counter, so jobs of unequal cost balance
// themselves. body must write only to slot i of its outputs: then the result
// does not depend on the thread count. The first exception thrown stops
// handing out work and is rethrown once every thread has joined.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body);

}  // namespace rackopt
