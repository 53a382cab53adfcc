// The study layer's types under the names the report uses: the report
// presents what study/ computed and never defines results of its own.
#pragma once

#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"

namespace rackopt::study_report {

using study::ConstraintSpec;
using study::DesignResult;
using study::DesignVariable;
using study::StudyResult;
using study::StudySpec;

}  // namespace rackopt::study_report
