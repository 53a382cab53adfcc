// Small helpers several FE tests share (one definition, so the test files
// can be compiled together in a unity build).
#pragma once

#include <sys/resource.h>

#include <string>
#include <vector>

#include "rackopt/fe/mesh_position_fe.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe::testing {

// The gantry axis as shipped (z 20, m 4 mm, 20 deg: the smallest shipped design).
inline Drive gantry() { return test_support::load_shipped_problem("gantry_axis.yaml"); }

// The gantry axis made small for FE (14 teeth, x = +0.3, 12 mm rack body)
// with `more` overrides: a few seconds per solve, every effect still there.
inline Drive small_gantry(const std::vector<std::string>& more = {}) {
  std::vector<std::string> set = {"pinion.teeth=14", "pinion.profile_shift=0.3", "rack.body_height=12 mm"};
  set.insert(set.end(), more.begin(), more.end());
  return test_support::load_shipped_problem("gantry_axis.yaml", set);
}

// Sum of the load shares of a position's pairs (1 when the pairs' contact
// forces carry the whole load).
inline double share_sum(const FePosition& p) {
  double s = 0;
  for (const FePair& q : p.pairs) s += q.load_share;
  return s;
}

// CPU seconds of this process and its finished children (ccx) so far.
inline double cpu_seconds() {
  double t = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    getrusage(who, &u);
    t += u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return t;
}

}  // namespace rackopt::fe::testing
