#include "rackopt/metrics/mesh_dynamics_metrics.hpp"

#include <stdexcept>
#include <string>

#include "rackopt/stiffness/period_stats.hpp"

namespace rackopt::metrics {
namespace {

constexpr std::string_view kEffects =
    "pinion_tooth, root_segment, fillet_foundation, rack_tooth, hertz, rack_span, couple_term, "
    "body_axial, body_shear, interference_limit, spalling (and the profile relief keys)";

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

void add_mesh_dynamics_definitions(std::vector<MetricDefinition>& r) {
  const ModelSet curve{Model::kStiffnessCurve};
  r.push_back({"mesh_ripple_max", "-", QuantityKind::kDimensionless, "",
               "worst mesh period's stiffness ripple (k_max - k_min)/k_mean within one period p = pi m of "
               "travel, over one rack span (loaded stiffness when a profile relief is set)",
               curve, 0, kEffects, false, {},
               "period extremes from the curve's one-sided limits and golden-section refinement "
               "(docs/models/transmission_error.md)"});
  r.push_back({"mesh_ripple_mean", "-", QuantityKind::kDimensionless, "",
               "mean over the mesh periods of one rack span of the per-period stiffness ripple", curve, 0, kEffects,
               false, {}, "as mesh_ripple_max"});
  r.push_back({"transmission_error_pp", "m", QuantityKind::kLength, "um",
               "peak-to-peak over one rack span of the static transmission error: the mesh deflection along the "
               "line of action that carries load.force (includes the rack body's slow deflection)",
               curve, 0, kEffects, false, {},
               "loaded contact solve (C + diag c) f = delta 1 - e, f >= 0, sum f = F; delta = F/K without relief "
               "(docs/models/transmission_error.md)"});
  r.push_back({"transmission_error_pp_period_max", "m", QuantityKind::kLength, "um",
               "worst mesh period's peak-to-peak static transmission error over one rack span", curve, 0, kEffects,
               false, {}, "as transmission_error_pp, per period p = pi m of travel"});
  r.push_back({"transmission_error_pp_period_mean", "m", QuantityKind::kLength, "um",
               "mean over the mesh periods of one rack span of the peak-to-peak static transmission error", curve, 0,
               kEffects, false, {}, "as transmission_error_pp_period_max"});
}

bool is_mesh_dynamics_metric(std::string_view name) {
  return name == "mesh_ripple_max" || name == "mesh_ripple_mean" || name == "transmission_error_pp" ||
         name == "transmission_error_pp_period_max" || name == "transmission_error_pp_period_mean";
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

double mesh_dynamics_value(const MeshDynamicsFigures& f, std::string_view name) {
  if (name == "mesh_ripple_max") return f.ripple.value().max;
  if (name == "mesh_ripple_mean") return f.ripple.value().mean;
  if (name == "transmission_error_pp") return f.transmission_error.value().peak_to_peak;
  if (name == "transmission_error_pp_period_max") return f.transmission_error.value().period_max;
  if (name == "transmission_error_pp_period_mean") return f.transmission_error.value().period_mean;
  throw std::logic_error("not a mesh dynamics metric: " + std::string(name));
}

}  // namespace rackopt::metrics
