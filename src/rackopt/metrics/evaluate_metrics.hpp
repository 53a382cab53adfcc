// Values of named metrics for one design (a Drive), computing only the models
// the requested metrics need, each at most once.
//
// Example:
//   ProblemTree tree = load_problem_tree_file("problems/rack_railway.yaml");
//   std::vector<std::pair<std::string, double>> x{{"pinion.module", 0.03}};
//   Drive drive = drive_with_values(tree, x);
//   std::vector<MetricRequest> want{parse_metric_request("min_stiffness_ks(200)"),
//                                   parse_metric_request("contact_ratio")};
//   MetricValues v = evaluate_metrics(drive, want, {});
//   if (v.all_ok()) use(v.values[0].value, v.values[1].value);
//   else report(v.first_failure()->error_code, v.first_failure()->message);
#pragma once

#include <span>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/metrics/tooth_stress.hpp"

namespace rackopt::metrics {

// Load factors that override the problem's (load.*): each 0 = not given,
// take the drive's. An override applies to the one factor it names; a
// K_Hbeta override also moves a derived K_Fbeta (load.face_load_factor_bending
// absent), since that follows K_Hbeta.
struct LoadFactorOverrides {
  double application = 0;         // K_A      (load.application_factor)
  double dynamic = 0;             // K_V      (load.dynamic_factor)
  double face_bending = 0;        // K_Fbeta  (load.face_load_factor_bending)
  double transverse_bending = 0;  // K_Falpha (load.transverse_load_factor)
  double face_contact = 0;        // K_Hbeta  (load.face_load_factor)
  double transverse_contact = 0;  // K_Halpha (load.transverse_load_factor)
};

// Weights of the cost proxy `cost_per_metre` (docs/metrics.md): cost units
// (any currency) per kg of rack and of pinion steel and per rack support.
// The pinion's cost is spread over the installed rack length.
struct CostWeights {
  double rack_per_kg = 1.0;
  double pinion_per_kg = 1.0;
  double per_support = 0.0;
  double rack_length = 0.0;  // [m]; 0 = the problem's duty.stroke
};

// Overrides of problem keys for the stress metrics, and settings of the
// metric computations. Every stress input is a problem key (docs/yaml.md);
// a value here > 0 wins over the drive's, 0 (the default) takes the drive's.
struct MetricOptions {
  LoadFactorOverrides load_factors;
  // Permissible stresses [Pa]. 0: from the member's material
  // (materials.<name>.allowable_bending / allowable_contact). A rack value
  // that neither this nor the rack's material gives falls back to the
  // pinion's value given here (the pre-problem-key behaviour).
  double allowable_bending_pinion = 0;    // sigma_FP pinion
  double allowable_bending_rack = 0;      // sigma_FP rack
  double allowable_contact_pinion = 0;    // sigma_HP pinion
  double allowable_contact_rack = 0;      // sigma_HP rack
  double rack_root_radius = 0;            // rack root round [m]; 0 = rack.root_radius

  CostWeights cost;                       // cost_per_metre

  // wear_life_at_R (docs/metrics.md)
  bool exact_quantile = true;      // one random input: life at R from its quantile (no sampling error)
  // Each of the next three, when given, overrides the problem's reliability
  // section; absent, the problem's value is used.
  std::optional<long> reliability_samples;   // Monte Carlo path: > 0
  std::optional<long> reliability_seed;      // >= 0 (common random numbers either way)
  std::optional<int> bootstrap_replicates;   // Monte Carlo path: KS test and fit choice (>= 20)
  unsigned threads = 1;            // Monte Carlo path threads; results do not depend on it

  // Travel samples per mesh period of the stiffness curve the metrics read
  // (4 ... 10000); absent: the problem's numerics.positions_per_period. The
  // curve's extremes are refined inside each smooth piece and do not depend
  // on it; the mean converges as O(h^4), the KS aggregates, the ripple and
  // the transmission error read the samples themselves (docs/accuracy.md,
  // "Positions per period for the metrics").
  std::optional<int> positions_per_period;
};

// One requested metric's outcome.
struct MetricValue {
  MetricRequest request;     // as asked
  std::string label;         // to_string(request), e.g. "wear_life_at_R(0.9)"
  bool ok = false;
  double value = 0;          // SI (the definition's unit); finite when ok, 0 when failed
  std::string display;       // value in the definition's display unit, e.g. "61.2 yr", "812 MPa"
  std::string error_code;    // when failed: the DesignError code, or "non_finite"
  std::string message;       // when failed: why; when ok: a remark or ""
  // When failed: what failed. A model name ("geometry", "stiffness_curve",
  // "wear_life", "wear_reliability", "stress") when a model could not be
  // computed, "geometry" whenever the drive's geometry itself is impossible
  // (whichever model met it), "metric" when the metric's own computation
  // failed (e.g. a non-finite value).
  std::string cause;
};

struct MetricValues {
  std::vector<MetricValue> values;  // one per request, in request order
  ModelSet models_run;              // models actually computed (attempted) in this call
  // Model computations made: geometry, stiffness curve, stress count one each;
  // the wear computation counts one whether it serves wear_life, the life at
  // R or both (run_wear_reliability also yields the nominal life). So it never
  // exceeds the number of models in models_run: each model is computed once.
  int model_runs = 0;
  std::vector<std::string> warnings;  // from the models (undercut, clamped rack root round, ...)
  double seconds = 0;               // wall time of the call (the only non-deterministic field)

  bool all_ok() const;
  const MetricValue* first_failure() const;  // nullptr when all are ok
  // The value with this label; throws std::out_of_range when absent.
  const MetricValue& at(std::string_view label) const;
};

// The stress inputs evaluate_metrics uses: options over the drive, as
// MetricOptions describes. An allowable stays 0 when neither gives it.
struct StressInputs {
  LoadFactors factors;
  double allowable_bending_pinion = 0, allowable_bending_rack = 0;  // [Pa]
  double allowable_contact_pinion = 0, allowable_contact_rack = 0;  // [Pa]
  double rack_root_radius = 0;  // [m]; 0 = pinion cutter tip radius
};
StressInputs resolve_stress_inputs(const Drive& drive, const MetricOptions& options);

// Throws InputError when a request is invalid (resolve_request) or its
// requirements are not configured (wear section, duty, allowables), or an
// option is out of range, naming what is missing: for an allowable, the
// problem key to add (materials.<the member's material>.allowable_bending).
// Cheap; evaluate_metrics calls it first, and a study can call it once
// before its first design.
void check_metric_requests(const Drive& drive, std::span<const MetricRequest> requests,
                           const MetricOptions& options);

// Values of `requests` for `drive`. Computes only the models the requests
// need (MetricDefinition::models), each once. A DesignError of a model makes
// every metric that needs that model fail with its code and message; the
// other metrics are still computed. A non-finite value fails with code
// "non_finite". Never returns NaN. Throws only what check_metric_requests
// throws (and InputError a model raises for input it cannot use).
// A pure function of its arguments: thread-safe, deterministic (the Monte
// Carlo of wear_life_at_R uses a fixed seed, so neighbouring designs see the
// same random numbers).
MetricValues evaluate_metrics(const Drive& drive, std::span<const MetricRequest> requests,
                              const MetricOptions& options = {});

}  // namespace rackopt::metrics
