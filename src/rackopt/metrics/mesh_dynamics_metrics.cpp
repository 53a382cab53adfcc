#include "rackopt/metrics/mesh_dynamics_metrics.hpp"

#include <string>
#include <string_view>
#include <vector>

#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"
#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::metrics {
namespace {

constexpr std::string_view kEffects =
    "pinion_tooth, root_segment, fillet_foundation, fillet_calibration, rack_tooth, rack_foundation, hertz, pair_coupling, rack_span, supported_rack, couple_term, "
    "body_axial, body_shear, interference_limit, spalling (and the profile relief keys)";

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

void append_mesh_dynamics_metrics(std::vector<MetricDefinition>& r) {
  const ModelSet curve{Model::kStiffnessCurve};
  r.push_back({"mesh_ripple_max", "-", QuantityKind::kDimensionless, "",
               "worst mesh period's stiffness ripple (k_max - k_min)/k_mean within one period p = pi m of "
               "travel, over one rack span (loaded stiffness when a profile relief is set)",
               curve, 0, kEffects, false, {},
               "period extremes from the curve's one-sided limits and golden-section refinement "
               "(docs/models/transmission_error.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.dynamics().ripple.value().max}; }});
  r.push_back({"mesh_ripple_mean", "-", QuantityKind::kDimensionless, "",
               "mean over the mesh periods of one rack span of the per-period stiffness ripple", curve, 0, kEffects,
               false, {}, "as mesh_ripple_max",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.dynamics().ripple.value().mean}; }});
  r.push_back({"transmission_error_pp", "m", QuantityKind::kLength, "um",
               "peak-to-peak over one rack span of the static transmission error: the mesh deflection along the "
               "line of action that carries load.force (includes the rack body's slow deflection)",
               curve, 0, kEffects, false, {},
               "loaded contact solve (C + diag c) f = delta 1 - e, f >= 0, sum f = F; delta = F/K without relief "
               "(docs/models/transmission_error.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.dynamics().transmission_error.value().peak_to_peak}; }});
  r.push_back({"transmission_error_pp_period_max", "m", QuantityKind::kLength, "um",
               "worst mesh period's peak-to-peak static transmission error over one rack span", curve, 0, kEffects,
               false, {}, "as transmission_error_pp, per period p = pi m of travel",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.dynamics().transmission_error.value().period_max}; }});
  r.push_back({"transmission_error_pp_period_mean", "m", QuantityKind::kLength, "um",
               "mean over the mesh periods of one rack span of the peak-to-peak static transmission error", curve, 0,
               kEffects, false, {}, "as transmission_error_pp_period_max",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.dynamics().transmission_error.value().period_mean}; }});
}

MeshDynamicsFigures mesh_dynamics_figures(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                          std::span<const MetricRequest> requests) {
  bool ripple = false, te = false;
  for (const MetricRequest& r : requests) {
    ripple = ripple || starts_with(r.name, "mesh_ripple_");
    te = te || starts_with(r.name, "transmission_error_");
  }
  MeshDynamicsFigures out;
  if (ripple) out.ripple = mesh_ripple(period_stats(model, curve, CurveQuantity::kStiffness));
  if (te) out.transmission_error = transmission_error(period_stats(model, curve, CurveQuantity::kApproach));
  return out;
}

}  // namespace rackopt::metrics
