#include "rackopt/study/reliability_options.hpp"

namespace rackopt::study {

WearReliabilityOptions study_reliability_options(const StudySpec& spec, const Drive& design, unsigned threads) {
  WearReliabilityOptions wo = wear_reliability_options(design);
  if (spec.metric_options.reliability_samples) wo.samples = *spec.metric_options.reliability_samples;
  if (spec.metric_options.reliability_seed) wo.seed = *spec.metric_options.reliability_seed;
  if (spec.metric_options.bootstrap_replicates) wo.bootstrap_replicates = *spec.metric_options.bootstrap_replicates;
  wo.threads = threads;
  return wo;
}

}  // namespace rackopt::study
