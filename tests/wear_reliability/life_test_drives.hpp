// The drive several life tests share (one definition, so the test files can
// be compiled together in a unity build).
#pragma once

#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::test {

// problems/ship_lift.yaml with the tooth profile held as cut (no update by the
// wear): cheaper, and the statistics are what these tests check.
inline Drive ship_lift_fixed_profile() {
  Drive d = test_support::load_shipped_problem("ship_lift.yaml");
  d.wear.update_profile = false;
  return d;
}

}  // namespace rackopt::test
