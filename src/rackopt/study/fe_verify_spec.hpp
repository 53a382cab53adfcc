// A study's `verify: fe`: after the study, the best design (the chosen front
// point of a pareto study) is compared with the FE reference by the same
// comparison as `rackopt fe` (rackopt/fe/fe_comparison.hpp), and the report
// gets the table and the errors (docs/studies.md, `verify`).
#pragma once

#include "rackopt/core/error.hpp"

namespace rackopt::study {

struct FeVerifySpec {
  int positions = 4;              // travel positions over one mesh period, 1..64
  int level = 0;                  // FE refinement level, 0..6 (0 = module / 6)
  bool extended_contact = false;  // also the neighbouring flanks (reported, not compared)
  bool rack_supports = false;     // the rack on its hinged supports in both codes (FeOptions::rack_on_supports)
  SourceMark mark;                // where `verify` is written
};

}  // namespace rackopt::study
