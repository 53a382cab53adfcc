// Metrics of the ISO 6336-style tooth-root and flank stresses.
#include <algorithm>
#include <vector>

#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {
namespace {

constexpr std::uint8_t kBendBits = static_cast<std::uint8_t>(Requirement::kAllowableBending);
constexpr std::uint8_t kContactBits = static_cast<std::uint8_t>(Requirement::kAllowableContact);

}  // namespace

void append_stress_metrics(std::vector<MetricDefinition>& r) {
  const ModelSet stress{Model::kGeometry, Model::kStress};
  r.push_back({"root_bending_stress", "Pa", QuantityKind::kModulus, "MPa",
               "pinion tooth-root bending stress, load at the tip, 30 deg tangent critical section "
               "of the generated fillet",
               stress, 0, "interference_limit", true, {},
               "ISO 6336-3:1996 method C (Y_F, Y_S, Y_eps at the tip) on the real tooth",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.stress().pinion_root_stress}; }});
  r.push_back({"rack_root_bending_stress", "Pa", QuantityKind::kModulus, "MPa",
               "rack tooth-root bending stress, load at the highest rack contact, 30 deg tangent on "
               "the rack root round",
               stress, 0, "interference_limit", true, {}, "ISO 6336-3 form, trapezoid rack tooth",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.stress().rack_root_stress}; }});
  r.push_back({"root_bending_safety", "-", QuantityKind::kDimensionless, "",
               "min(S_F pinion, S_F rack), S_F = allowable bending / root stress", stress, kBendBits,
               "interference_limit", true, {}, "ISO 6336-3 S_F = sigma_FP / sigma_F",
               [](const ModelResults& m, const MetricRequest&) {
                 const ToothStress& s = m.stress();
                 const double sp = m.stress_inputs.allowable_bending_pinion / s.pinion_root_stress;
                 const double sr = m.stress_inputs.allowable_bending_rack / s.rack_root_stress;
                 return MetricOutcome{std::min(sp, sr), sp <= sr ? "pinion governs" : "rack governs"};
               }});
  r.push_back({"contact_stress", "Pa", QuantityKind::kModulus, "MPa",
               "nominal flank contact stress Z_E Z_H Z_eps sqrt(F_t/(b d)) (rack: u -> infinity)",
               stress, 0, "interference_limit", true, {}, "ISO 6336-2 (Z_B, Z_beta = 1)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.stress().contact_stress}; }});
  r.push_back({"contact_safety", "-", QuantityKind::kDimensionless, "",
               "S_H = allowable contact stress (weaker member) / contact stress", stress, kContactBits,
               "interference_limit", true, {}, "ISO 6336-2 S_H = sigma_HP / sigma_H",
               [](const ModelResults& m, const MetricRequest&) {
                 // One contact stress for both flanks: the weaker material governs.
                 const double ap = m.stress_inputs.allowable_contact_pinion;
                 const double ar = m.stress_inputs.allowable_contact_rack;
                 return MetricOutcome{std::min(ap, ar) / m.stress().contact_stress,
                                      ap < ar ? "pinion governs" : ar < ap ? "rack governs" : ""};
               }});
}

}  // namespace rackopt::metrics
