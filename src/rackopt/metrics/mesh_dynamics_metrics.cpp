#include "rackopt/metrics/mesh_dynamics_metrics.hpp"

#include <string>
#include <string_view>
#include <vector>

#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"
#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::metrics {

void append_mesh_dynamics_metrics(std::vector<MetricDefinition>& r) {
  // The per-period figures follow the curve's switches, and a profile relief
  // changes the loaded contact they come from. Static: the registry keeps views.
  static const std::string kEffects = std::string(kStiffnessEffects) + " (and the profile relief keys)";
  const ModelSet ripple{Model::kStiffnessCurve, Model::kMeshRipple};
  const ModelSet te{Model::kStiffnessCurve, Model::kTransmissionError};
  r.push_back({"mesh_ripple_max", "-", QuantityKind::kDimensionless, "",
               "worst mesh period's stiffness ripple (k_max - k_min)/k_mean within one period p = pi m of "
               "travel, over one rack span (loaded stiffness when a profile relief is set)",
               ripple, 0, kEffects, false, {},
               "period extremes from the curve's one-sided limits and golden-section refinement "
               "(docs/models/transmission_error.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.mesh_ripple().max}; }});
  r.push_back({"mesh_ripple_mean", "-", QuantityKind::kDimensionless, "",
               "mean over the mesh periods of one rack span of the per-period stiffness ripple", ripple, 0, kEffects,
               false, {}, "as mesh_ripple_max",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.mesh_ripple().mean}; }});
  r.push_back({"transmission_error_pp", "m", QuantityKind::kLength, "um",
               "peak-to-peak over one rack span of the static transmission error: the mesh deflection along the "
               "line of action that carries load.force (includes the rack body's slow deflection)",
               te, 0, kEffects, false, {},
               "loaded contact solve (C + diag c) f = delta 1 - e, f >= 0, sum f = F; delta = F/K without relief "
               "(docs/models/transmission_error.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.transmission_error().peak_to_peak}; }});
  r.push_back({"transmission_error_pp_period_max", "m", QuantityKind::kLength, "um",
               "worst mesh period's peak-to-peak static transmission error over one rack span", te, 0, kEffects,
               false, {}, "as transmission_error_pp, per period p = pi m of travel",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.transmission_error().period_max}; }});
  r.push_back({"transmission_error_pp_period_mean", "m", QuantityKind::kLength, "um",
               "mean over the mesh periods of one rack span of the peak-to-peak static transmission error", te, 0,
               kEffects, false, {}, "as transmission_error_pp_period_max",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.transmission_error().period_mean}; }});
}

MeshDynamicsFigures mesh_dynamics_figures(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                          const ModelSet& needed) {
  MeshDynamicsFigures out;
  if (needed.contains(Model::kMeshRipple))
    out.ripple = mesh_ripple(period_stats(model, curve, CurveQuantity::kStiffness));
  if (needed.contains(Model::kTransmissionError))
    out.transmission_error = transmission_error(period_stats(model, curve, CurveQuantity::kApproach));
  return out;
}

}  // namespace rackopt::metrics
