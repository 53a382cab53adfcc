// The metric families that make up the registry (metric_registry.cpp builds it
// from these, in this order, which is the order of docs/metrics.md). Each
// family file holds its definitions together with their computations.
#pragma once

#include <string_view>
#include <vector>

#include "rackopt/metrics/metric_registry.hpp"

namespace rackopt::metrics {

void append_stiffness_metrics(std::vector<MetricDefinition>& registry);  // stiffness_metrics.cpp
void append_mesh_dynamics_metrics(std::vector<MetricDefinition>& registry);  // mesh_dynamics_metrics.cpp
void append_drive_dynamics_metrics(std::vector<MetricDefinition>& registry);  // drive_dynamics_metrics.cpp
void append_geometry_metrics(std::vector<MetricDefinition>& registry);   // geometry_metrics.cpp
void append_wear_metrics(std::vector<MetricDefinition>& registry);       // wear_metrics.cpp
void append_stress_metrics(std::vector<MetricDefinition>& registry);     // stress_metrics.cpp
void append_size_metrics(std::vector<MetricDefinition>& registry);       // size_metrics.cpp

// Switches of drive.effects that change the stiffness curve (documentation).
inline constexpr std::string_view kStiffnessEffects =
    "pinion_tooth, root_segment, fillet_foundation, fillet_calibration, rack_tooth, rack_foundation, hertz, pair_coupling, rack_span, supported_rack, couple_term, "
    "body_axial, body_shear, interference_limit, spalling";

}  // namespace rackopt::metrics
