// The wear reliability analysis of a reliability study's design, set up
// the same way by every process that takes part in it (rank 0 and the
// ranks that compute shares of its Monte Carlo).
#pragma once

#include "rackopt/core/drive.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/wear_reliability/wear_reliability.hpp"

namespace rackopt::study {

// The problem's options (wear_reliability_options) with the study's sample
// count, seed and bootstrap replicates, on `threads` threads.
WearReliabilityOptions study_reliability_options(const StudySpec& spec, const Drive& design, unsigned threads);

}  // namespace rackopt::study
