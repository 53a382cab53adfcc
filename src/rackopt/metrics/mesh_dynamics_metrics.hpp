// The metrics a gear dynamicist reads off the stiffness curve: the mesh
// ripple (stiffness fluctuation within each mesh period) and the static
// transmission error under load (docs/metrics.md,
// docs/models/transmission_error.md). Their definitions join the registry
// and their values come from the stiffness model and its curve, computed
// only when one of them is requested.
//
// Example (evaluate_metrics):
//   MeshDynamicsFigures dyn = mesh_dynamics_figures(model, curve, requests);
//   if (is_mesh_dynamics_metric(name)) value = mesh_dynamics_value(dyn, name);
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/transmission_error.hpp"

namespace rackopt::metrics {

// Appends mesh_ripple_max, mesh_ripple_mean, transmission_error_pp,
// transmission_error_pp_period_max, transmission_error_pp_period_mean.
void add_mesh_dynamics_definitions(std::vector<MetricDefinition>& registry);

// True for the names add_mesh_dynamics_definitions defines.
bool is_mesh_dynamics_metric(std::string_view name);

// What the requested mesh dynamics metrics need; each part only when asked for.
struct MeshDynamicsFigures {
  std::optional<MeshRipple> ripple;
  std::optional<TransmissionError> transmission_error;
};

// Computes the ripple when a mesh_ripple_* metric is requested and the
// transmission error when a transmission_error_* one is; nothing otherwise.
MeshDynamicsFigures mesh_dynamics_figures(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                          std::span<const MetricRequest> requests);

// Value [SI] of the mesh dynamics metric `name` (is_mesh_dynamics_metric)
// from figures computed for a request list that contained it.
double mesh_dynamics_value(const MeshDynamicsFigures& figures, std::string_view name);

}  // namespace rackopt::metrics
