// Metrics of Archard wear: the deterministic life and the life at reliability R.
#include <algorithm>
#include <vector>

#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {
namespace {

constexpr std::uint8_t kWearBits = static_cast<std::uint8_t>(Requirement::kWear);
constexpr std::uint8_t kDutyBits = static_cast<std::uint8_t>(Requirement::kDuty);
constexpr std::string_view kWearEffects =
    "pinion_tooth, fillet_foundation, fillet_calibration, rack_tooth, rack_foundation, hertz, pair_coupling, "
    "interference_limit";

std::string ended_by(const WearLifeResult& w) { return "ended by " + w.criterion + ": " + w.reason; }

}  // namespace

void append_wear_metrics(std::vector<MetricDefinition>& r) {
  r.push_back({"wear_life", "s", QuantityKind::kTime, "yr",
               "deterministic Archard wear life of the nominal drive", ModelSet{Model::kWearLife},
               static_cast<std::uint8_t>(kWearBits | kDutyBits), kWearEffects, false, {},
               "WearModel(drive).life(WearSample{}) (docs/models/wear.md)",
               [](const ModelResults& m, const MetricRequest&) {
                 const WearLifeResult& w = m.wear_life();
                 return MetricOutcome{w.life_years * kSecondsPerYear, ended_by(w)};
               }});
  r.push_back({"wear_life_cycles", "-", QuantityKind::kDimensionless, "",
               "deterministic wear life in rack passes (no duty needed)", ModelSet{Model::kWearLife},
               kWearBits, kWearEffects, false, {}, "WearLifeResult::life_cycles",
               [](const ModelResults& m, const MetricRequest&) {
                 const WearLifeResult& w = m.wear_life();
                 return MetricOutcome{w.life_cycles, ended_by(w)};
               }});
  r.push_back({"wear_life_at_R", "s", QuantityKind::kTime, "yr",
               "wear life reached with probability R under the problem's reliability inputs "
               "(fixed seed: common random numbers across designs)",
               ModelSet{Model::kWearReliability}, static_cast<std::uint8_t>(kWearBits | kDutyBits),
               kWearEffects, false,
               {ParameterSpec::Use::kRequired, "R", 0.0, 0.0, 1.0, "reliability, strictly inside (0, 1)"},
               "exact input quantile (one monotone input) or run_wear_reliability (docs/models/reliability.md)",
               [](const ModelResults& m, const MetricRequest& q) {
                 const LifeAtR& l = m.life_at_R();
                 const auto it = std::find(l.reliabilities.begin(), l.reliabilities.end(), *q.parameter);
                 const auto k = static_cast<std::size_t>(it - l.reliabilities.begin());
                 return MetricOutcome{l.life_s.at(k), l.remark.at(k)};
               }});
}

}  // namespace rackopt::metrics
