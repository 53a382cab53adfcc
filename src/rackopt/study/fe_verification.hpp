// `verify: fe` of a study: the best design (the chosen front point of a
// pareto study) compared with the FE reference once the study has ended, by
// the comparison `rackopt fe` makes (rackopt/fe/fe_comparison.hpp).
#pragma once

#include "rackopt/study/study_runner.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study {

// Does nothing without spec.verify_fe. Else, when the study was not stopped
// and has a best_drive, runs compare_with_fe on it (positions, level and
// extended contact of the spec; options.threads; options.fe_calls;
// options.stop) and sets result.fe_verification. Never throws for the FE:
// what went wrong (no design to verify, ccx missing or failed with its
// kept deck, an impossible FE body, a stop) goes to
// result.fe_verification_error, so the study's own results are reported
// whatever happens to the verification. A stop during the FE solves also
// sets result.status to kStopped (and result.stopped_during): the run was
// interrupted, and --resume verifies again.
void verify_best_design_by_fe(const StudySpec& spec, const RunOptions& options, StudyResult& result);

// The FeComparisonOptions `verify` asks for.
fe::FeComparisonOptions fe_verification_options(const FeVerifySpec& verify, const RunOptions& options);

}  // namespace rackopt::study
