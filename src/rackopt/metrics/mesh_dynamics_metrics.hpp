// The metrics a gear dynamicist reads off the stiffness curve: the mesh
// ripple (stiffness fluctuation within each mesh period) and the static
// transmission error under load (docs/metrics.md,
// docs/models/transmission_error.md). Their definitions join the registry
// and their values come from the stiffness model and its curve, computed
// only when one of them is requested.
//
// evaluate_metrics computes the figures with the stiffness curve
// (mesh_dynamics_figures) and the metric computations read them from
// ModelResults (metric_families.hpp: append_mesh_dynamics_metrics).
#pragma once

#include <optional>
#include <span>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/stiffness/mesh_ripple.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/transmission_error.hpp"

namespace rackopt::metrics {

// What the requested mesh dynamics metrics need; each part only when asked for.
struct MeshDynamicsFigures {
  std::optional<MeshRipple> ripple;
  std::optional<TransmissionError> transmission_error;
};

// Computes the ripple when `needed` holds Model::kMeshRipple and the
// transmission error when it holds Model::kTransmissionError (the models the
// requested metrics declare in the registry); nothing otherwise.
MeshDynamicsFigures mesh_dynamics_figures(const MeshStiffnessModel& model, const StiffnessCurve& curve,
                                          const ModelSet& needed);

}  // namespace rackopt::metrics
