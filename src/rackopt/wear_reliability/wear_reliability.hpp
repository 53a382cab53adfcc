// Wear life at reliability R (docs/models/reliability.md): the deterministic wear
// life of the nominal drive, then one wear life per Monte Carlo sample of the
// problem's random inputs, then the fitted life distribution, R(t) and the life
// at each requested R (from the fit and empirically, with intervals).
//
// Determinism: sample i's inputs depend only on (reliability.seed, i) and the
// lives are stored by index, so the result is the same on any thread count.
// A sampled contact ratio outside [max(1, [eps]), eps_max] fails at once with
// life 0 and is counted in R(t); a sampled value outside its input's domain
// (not finite, or <= 0 for a load, coefficient or hardness) is a failed
// evaluation, excluded and counted (wear_reliability/sample_domain.hpp). Neither is a
// crash, and neither gives the nominal life.
//
// Example:
//   Drive d = load_problem("problems/ship_lift.yaml");
//   WearReliabilityResult r = run_wear_reliability(d, {});
//   r.nominal.life_years; r.summary.life[0].fit->estimate / kSecondsPerYear;
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string_view>
#include <string>
#include <utility>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/statistics/reliability.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt {

class ProgressBar;

// The Monte Carlo samples' part of a run: what the sample loop gives, for
// every sample or for one share of them.
struct SampleLives {
  std::vector<statistics::SampleResult> lives;  // seconds, in sample order
  std::vector<std::string> criteria;           // the end-of-life criterion of each sample
  std::size_t interpolated = 0;                // of them, lives read from the life table or scaled
  unsigned processes = 1;                      // processes that computed them (MPI ranks)
};

struct WearReliabilityOptions {
  // Each checked against core/run_limits.hpp by run_wear_reliability.
  std::optional<long> samples;  // overrides reliability.samples (kSamplesLimit)
  std::optional<long> seed;     // overrides reliability.seed (kSeedLimit)
  unsigned threads = 0;     // 0 = hardware concurrency (kThreadsLimit); results do not depend on it
  ProgressBar* progress = nullptr;  // ticked once per sample
  // Polled before each sample, through the distribution fits and their
  // bootstrap (statistics::ReliabilityRequest::stop) and before each exact
  // R(t) (Ctrl-C; thread-safe): once true the remaining work is skipped and
  // run_wear_reliability throws rackopt::Interrupted within a step over the
  // lives (well under a second at a million samples).
  std::function<bool()> stop;
  // KS critical values and fit intervals. At 100 the critical value's
  // bootstrap sd is 0.0015 against 0.0010 at 200, i.e. 5 % against 3.5 % of
  // its value (docs/models/reliability.md, "Bootstrap replicates"); at 200
  // the bootstrap alone takes twice the 100 ms budget of a life-at-R run.
  int bootstrap_replicates = 100;
  // One random input: the lives of the samples and the exact quantile map
  // come from a verified table of life(input) (statistics/function_table.hpp)
  // instead of one model life per sample (docs/models/reliability.md, "Life
  // table"). Several inputs of which at most one is the contact ratio or the
  // load: the table along that input (or the nominal life) times each
  // sample's exact factor for the wear coefficient and the hardness
  // (wear_reliability/life_scaling.hpp); both of them: the two-input table
  // below, times that factor. false = one direct life per sample and R(t) by
  // bisection.
  bool life_table = true;
  int life_table_nodes = 5;               // initial nodes, uniform in the input (refined by the check)
  double life_table_tolerance = 5e-4;     // relative midpoint check of every interval
  int life_table_max_evaluations = 96;    // model lives the table may use
  // Two inputs that shape the life (the contact ratio and the load): a
  // verified table over both (statistics/function_table_2d.hpp). Its nodes
  // along the first are those of the one-input table along it (at the
  // second's design value, with the options above); along the second,
  // life_table_2d_nodes uniform ones. Every cell is checked at its centre to
  // life_table_tolerance; failing cells are quartered up to max_levels times
  // while the grid's lives stay within max_evaluations; samples in cells
  // left unverified get direct lives. Quartering is off by default: a
  // quarter-grid costs 8 or 9 lives, more than the direct lives of the few
  // samples a cell holds at 1000 samples (on the ship lift, 5 quartered
  // cells cost 40 lives and left the same 16 samples direct).
  int life_table_2d_nodes = 7;
  int life_table_2d_max_levels = 0;
  int life_table_2d_max_evaluations = 360;
  // For a caller that reads only the exact results (the wear_life_at_R
  // metric's exact path): when the exact quantile map is available (one
  // random input with a valid value of positive probability), no Monte Carlo
  // sample is drawn: lives, input_values, criteria and summary stay empty,
  // status is nullopt and samples_used 0. Otherwise (several inputs, or no
  // valid value) the samples are drawn as usual.
  bool exact_only = false;
  // What the nominal life fills in (WearModel::Detail): everything for the
  // wear report; the life alone for a caller that reads its life, criterion
  // and warnings only (the metrics).
  WearModel::Detail nominal_detail = WearModel::Detail::kFull;
  // Samples [first, last) only: the run does the same set-up (the nominal
  // life, the samples' inputs, the life table), computes those samples and
  // returns at once with share_lives set (no summary, no exact results).
  // What another process runs for its share of a Monte Carlo.
  std::optional<std::pair<std::size_t, std::size_t>> sample_share;
  // Every sample's life computed by several processes (the ranks of an MPI
  // job, each running its share with sample_share): given the sample count
  // and `here`, which computes samples [first, last) on this process's
  // threads, returns what the sample loop alone would give, bit for bit.
  // Empty: this process's threads.
  using SamplesHere = std::function<SampleLives(std::size_t first, std::size_t last)>;
  std::function<SampleLives(std::size_t samples, const SamplesHere& here)> sample_executor;
};

// The options a problem asks for: bootstrap_replicates, life_table and
// life_table_tolerance from its `reliability` section (everything else at
// the defaults above). Callers then override what the command line or a
// study sets.
WearReliabilityOptions wear_reliability_options(const Drive& drive);

// How the life table was used (empty when it was not): over the one random
// input, over the one input that shapes the life when every other input
// scales it exactly (wear_reliability/life_scaling.hpp), or over the two that
// shape it (the two-input table: input and input2).
struct LifeTableReport {
  bool used = false;
  std::string not_used;            // why not (option off, model error, ...)
  std::string input;               // the tabulated input's key
  std::string input2;              // the second tabulated input's key (two shaping inputs), else empty
  // Several inputs: those applied to each sample as the exact factor on the
  // table's life, or on the nominal life when no input shapes it (then
  // used = false and samples_interpolated counts those samples).
  std::vector<std::string> scaling_inputs;
  double x_min = 0, x_max = 0;     // tabulated input range (SI): the [1e-9, 1 - 1e-9] quantiles
                                   // clipped to the inputs that do not fail at once
  double y_min = 0, y_max = 0;     // the second input's range (two shaping inputs)
  int nodes = 0;                   // two shaping inputs: of the initial grid
  int cells = 0, cells_verified = 0, cells_with_switch = 0;  // two shaping inputs: the finest cells
  int evaluations = 0;             // model lives spent on the table (nodes + checks)
  double max_check_error = 0;      // largest relative midpoint error accepted
  double uncovered_fraction = 0;   // of [x_min, x_max], left to direct evaluation
  std::vector<std::pair<double, double>> breaks;  // input brackets where the failure mode switches
  std::size_t samples_interpolated = 0, samples_direct = 0;
};

// When the drive has exactly one random input and the life is a monotone
// function of it, R(t) and the life at R follow exactly from that input's
// quantiles (no sampling error). The life at R is one model life at the
// input's quantile. R(t) inverts life(input): with the life table, the table
// is inverted and the root polished with two model lives (secant); without
// it, 60 bisection steps on the probability.
struct ExactReliability {
  bool available = false;
  bool monotone_verified = false;       // the table's nodes are monotone (false without a table:
                                        // monotonicity is then assumed, checked at 2 points only)
  int model_evaluations = 0;            // model lives spent on the exact map
  std::string input;                    // the random input's key
  bool life_increases = true;           // with the input
  double failed_at_start = 0;           // probability of a valid sample outside [max(1, [eps]), eps_max] (life 0)
  double outside_domain = 0;            // probability of a value outside the input's domain (<= 0 for a
                                        // positive input): excluded, R is conditional on a valid sample
  std::vector<double> life_at_R_years;  // for reliability.reliabilities
  std::vector<double> R_at_times;       // for reliability.times
};

// How the Monte Carlo of the wear life ended (to_string gives the text of
// the JSON and the reports).
enum class SamplingStatus {
  kOk,
  kEverySampleFailsAtOnce,  // every evaluated sample has life 0: the life at every R is 0, R(t) = 0
  kNoValidSample,           // no sample could be evaluated: no R(t), no life at R, no exact path
};
// "ok", "every_sample_fails_at_once", "no_valid_sample".
std::string_view to_string(SamplingStatus status);
inline std::ostream& operator<<(std::ostream& out, SamplingStatus status) { return out << to_string(status); }

struct WearReliabilityResult {
  WearLifeResult nominal;                       // deterministic life of the nominal drive
  std::vector<std::string> input_keys;          // random inputs, in order
  std::vector<std::vector<double>> input_values;  // [sample][input], SI
  std::vector<statistics::SampleResult> lives; // value = life [s]
  std::vector<std::string> criteria;            // failure criterion per sample ("" when failed to evaluate)
  // Per input: samples whose value lies outside the input's domain
  // (wear_reliability/sample_domain.hpp); those samples are failed evaluations.
  std::vector<std::size_t> outside_domain_samples;
  // nullopt when nothing was sampled (no random inputs, or exact_only).
  std::optional<SamplingStatus> status;
  statistics::ReliabilitySummary summary;      // fits, R(t), life at R (seconds)
  ExactReliability exact;
  LifeTableReport table;
  // samples_ms: the sample lives (with the table: building it and
  // interpolating); fit_ms: summary + exact map, of which exact_ms the map.
  double nominal_ms = 0, samples_ms = 0, fit_ms = 0, exact_ms = 0;
  unsigned threads_used = 1;
  unsigned processes_used = 1;  // processes that computed the samples (Options::sample_executor: MPI ranks)
  std::uint64_t seed_used = 0;  // the Monte Carlo seed in effect (options.seed, else reliability.seed)
  long samples_used = 0;        // the sample count in effect
  // A life at R >= 0.5 above the nominal life (wear_reliability/life_at_R_check.hpp),
  // one per R: from the exact quantile path when there is one, else from the
  // sampled summary (lower end of its interval) when more than one sample
  // was drawn.
  std::vector<std::string> warnings;
  // Options::sample_share: that share's samples, first to last (the rest of
  // the result is the set-up only).
  std::optional<SampleLives> share_lives;
};

// Throws InputError when wear, duty or reliability is not configured enough
// to run (no wear coefficient, no duty, no random input for a reliability run).
// With no random inputs only the nominal life is computed (summary empty).
WearReliabilityResult run_wear_reliability(const Drive& drive, const WearReliabilityOptions& options);

// The WearSample that realises values x (SI, one per input) for `drive`.
WearSample wear_sample_for(const Drive& drive, const std::vector<RandomInput>& inputs,
                           const std::vector<double>& x);

}  // namespace rackopt
