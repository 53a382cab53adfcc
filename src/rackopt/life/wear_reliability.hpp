// Wear life at reliability R (issue 3; physics.md 12): the deterministic wear
// life of the nominal drive, then one wear life per Monte Carlo sample of the
// problem's random inputs, then the fitted life distribution, R(t) and the life
// at each requested R (from the fit and empirically, with intervals).
//
// Determinism: sample i's inputs depend only on (reliability.seed, i) and the
// lives are stored by index, so the result is the same on any thread count.
// A sample the model rejects (e.g. a contact ratio below the allowed one)
// fails at once with life 0 and is counted, never a crash.
//
// Example:
//   Drive d = load_problem("problems/ship_lift.yaml");
//   WearReliabilityResult r = run_wear_reliability(d, {});
//   r.nominal.life_years; r.summary.life[0].fit->estimate / kSecondsPerYear;
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/reliability/reliability.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt {

class ProgressBar;

struct WearReliabilityOptions {
  long samples = -1;        // > 0 overrides reliability.samples
  long seed = -1;           // >= 0 overrides reliability.seed
  unsigned threads = 0;     // 0 = hardware concurrency; results do not depend on it
  ProgressBar* progress = nullptr;  // ticked once per sample
  int bootstrap_replicates = 200;   // KS critical values and fit intervals
};

// When the drive has exactly one random input and the life is a monotone
// function of it, R(t) and the life at R follow exactly from that input's
// quantiles (no sampling error); a bisection on the probability inverts R(t).
struct ExactReliability {
  bool available = false;
  std::string input;                    // the random input's key
  bool life_increases = true;           // with the input
  double failed_at_start = 0;           // probability of a sample outside [max(1, [eps]), eps_max] (life 0)
  std::vector<double> life_at_R_years;  // for reliability.reliabilities
  std::vector<double> R_at_times;       // for reliability.times
};

struct WearReliabilityResult {
  WearLifeResult nominal;                       // deterministic life of the nominal drive
  std::vector<std::string> input_keys;          // random inputs, in order
  std::vector<std::vector<double>> input_values;  // [sample][input], SI
  std::vector<reliability::SampleResult> lives; // value = life [s]
  std::vector<std::string> criteria;            // failure criterion per sample ("" when failed to evaluate)
  reliability::ReliabilitySummary summary;      // fits, R(t), life at R (seconds)
  ExactReliability exact;
  double nominal_ms = 0, samples_ms = 0, fit_ms = 0;
  unsigned threads_used = 1;
};

// Throws InputError when wear, duty or reliability is not configured enough
// to run (no wear coefficient, no duty, no random input for a reliability run).
// With no random inputs only the nominal life is computed (summary empty).
WearReliabilityResult run_wear_reliability(const Drive& drive, const WearReliabilityOptions& options);

// The WearSample that realises values x (SI, one per input) for `drive`.
WearSample wear_sample_for(const Drive& drive, const std::vector<RandomInput>& inputs,
                           const std::vector<double>& x);

}  // namespace rackopt
