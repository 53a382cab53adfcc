// Named metrics: the quantities a study may use as objectives or constraints,
// each with its unit, the models it needs and whether it is smooth in the
// design. docs/metrics.md has the table, the methods and the measured cost.
//
// A metric is asked for by a MetricRequest: a name and, for the metrics that
// take one, a parameter. The text form is "name" or "name(parameter)", e.g.
// "contact_ratio", "wear_life_at_R(0.9)", "min_stiffness_ks(200)";
// parse_metric_request reads it and to_string writes it back.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/units/units.hpp"

namespace rackopt::metrics {

// The models a metric reads. Each is computed at most once per
// evaluate_metrics call, and only when a requested metric needs it.
enum class Model : std::uint8_t {
  kGeometry = 1,         // build_mesh_geometry (microseconds)
  kStiffnessCurve = 2,   // MeshStiffnessModel(drive).curve() (about 1 ms)
  kWearLife = 4,         // WearModel(drive).life() (about 0.3 ms)
  kWearReliability = 8,  // life at reliability R (exact quantile or Monte Carlo)
  kStress = 16,          // tooth-root and flank stresses, ISO 6336-style simplified
  // Per-mesh-period figures derived from the stiffness curve (a metric that
  // reads one declares the curve too): computed only when a metric asks.
  kMeshRipple = 32,         // per-period stiffness ripple (mesh_ripple.hpp)
  kTransmissionError = 64,  // loaded static transmission error per period (transmission_error.hpp)
  // The drive as a vibrating system (dynamics/drive_dynamics.hpp): only the
  // parts the requested metrics read (a K_V sweep, the response at the
  // operating speed, the Floquet map); the natural frequencies always.
  kDynamics = 128,
};

// A small set of models (bit set over Model).
class ModelSet {
 public:
  constexpr ModelSet() = default;
  constexpr ModelSet(std::initializer_list<Model> models) {
    for (Model m : models) insert(m);
  }
  constexpr void insert(Model m) { bits_ |= static_cast<std::uint8_t>(m); }
  constexpr void insert(ModelSet s) { bits_ |= s.bits_; }
  constexpr bool contains(Model m) const { return (bits_ & static_cast<std::uint8_t>(m)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr bool operator==(const ModelSet&) const = default;
  // Names in Model order, e.g. {"geometry", "stress"}.
  std::vector<std::string> names() const;

 private:
  std::uint8_t bits_ = 0;
};

// "geometry", "stiffness_curve", "wear_life", "wear_reliability", "stress".
std::string_view model_name(Model m);

// What must be configured for a metric to be computable at all. Missing
// configuration is a set-up error of the study (InputError before any model
// runs), not an infeasible design.
enum class Requirement : std::uint8_t {
  kWear = 1,               // problem `wear` section (wear.coefficient > 0)
  kDuty = 2,               // duty.rack_meshes_per_year > 0 (lives in seconds)
  kAllowableBending = 4,   // sigma_FP of both members: materials.<name>.allowable_bending (or MetricOptions)
  kAllowableContact = 8,   // sigma_HP of both members: materials.<name>.allowable_contact (or MetricOptions)
  kSpeed = 16,             // load.speed > 0 (drive power, pinion speed)
  kBodyHeight = 32,        // a rectangular rack body (rack.body_height), not an explicit section
  kRackLength = 64,        // a rack length for the pinion's share of the cost (metric option or duty.stroke)
  kMovingMass = 128,       // problem `dynamics` section (dynamics.moving_mass > 0)
};

// How a metric uses its parameter.
struct ParameterSpec {
  enum class Use { kNone, kOptional, kRequired };
  Use use = Use::kNone;
  std::string_view name;         // "R", "rho"
  double default_value = 0;      // kOptional: used when the request gives none
  double lower = 0, upper = 0;   // allowed open interval (lower, upper)
  std::string_view meaning;
};

struct ModelResults;   // metrics/model_results.hpp
struct MetricRequest;

// A metric's value for one design, in its SI unit, and an optional remark
// ("rack governs", which Monte Carlo path gave a life). A computation that
// cannot give a value throws DesignError (code + why); the models it reads
// re-raise their own failures that way.
struct MetricOutcome {
  double value = 0;
  std::string remark;
};

// How a metric's value is computed from the models it declared. Lives beside
// the definition (metrics/*_metrics.cpp), so a metric cannot exist without it.
using MetricCompute = MetricOutcome (*)(const ModelResults& models, const MetricRequest& request);

struct MetricDefinition {
  std::string_view name;
  std::string_view unit;                // SI unit text: "N/m", "Pa", "s", "1/m", "-"
  std::optional<QuantityKind> kind;     // for format_quantity; nullopt when no kind fits ("1/m")
  std::string_view display_unit;        // unit used in MetricValue::display ("MN/m", "MPa", "yr")
  std::string_view description;
  ModelSet models;                      // models it reads
  std::uint8_t requirements = 0;        // Requirement bits
  // drive.effects switches that change the value ("" = none); documentation
  // and a hint for studies that vary an effect.
  std::string_view effects;
  // True when the value is a continuous, piecewise differentiable function of
  // the continuous design keys, so finite-difference gradients make sense.
  bool smooth = false;
  ParameterSpec parameter;
  std::string_view source;              // where the formula comes from
  MetricCompute compute = nullptr;      // never null in metric_registry() (checked when it is built)
};

// Every metric, in a stable order (the order of docs/metrics.md). Built once,
// on first use, and checked then: a metric without a computation, a repeated
// name or a missing unit/description/source throws std::logic_error, so such a
// registry fails at start-up (every program asks for it before any design).
const std::vector<MetricDefinition>& metric_registry();

// The checks metric_registry() applies, for a registry under construction.
// Throws std::logic_error naming the first faulty definition.
void check_registry(const std::vector<MetricDefinition>& registry);

// The definition called `name`. Throws InputError (key "metric") for an
// unknown name; the message lists every valid name and, for a near miss
// (edit distance <= 1/3 of the name, at least 2), "did you mean '...'".
const MetricDefinition& find_metric(std::string_view name);

// A metric asked for by a study.
struct MetricRequest {
  std::string name;
  std::optional<double> parameter;  // wear_life_at_R: R; *_ks: rho
};

// "name" or "name(number)" (blanks allowed around the parts). Throws
// InputError (key "metric") for an unknown name, a malformed text, a
// parameter given to a metric that takes none, a missing required parameter,
// or a parameter outside its allowed range.
MetricRequest parse_metric_request(std::string_view text);

// The request checked against its definition and with the default parameter
// filled in. Same errors as parse_metric_request.
MetricRequest resolve_request(const MetricRequest& request);

// "name" or "name(parameter)", parameter in the shortest text that reads back
// to the same double. Used as the label of each result.
std::string to_string(const MetricRequest& request);

}  // namespace rackopt::metrics
