// Metrics of the drive's dynamic response (docs/metrics.md, "Dynamics";
// docs/models/dynamics.md).
#include <string>
#include <vector>

#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {
namespace {

constexpr std::uint8_t kMass = static_cast<std::uint8_t>(Requirement::kMovingMass);
constexpr std::uint8_t kMassAndSpeed = kMass | static_cast<std::uint8_t>(Requirement::kSpeed);

const SteadyResponse& at_speed(const ModelResults& m) {
  const DriveDynamics& d = m.dynamics();
  if (!d.at_speed) throw std::logic_error("a dynamics metric read the response at speed without asking for it");
  return *d.at_speed;
}

std::string status_remark(const SteadyResponse& r) {
  return r.status == ResponseStatus::kConverged ? std::string() : "not periodic: " + r.message;
}

}  // namespace

void append_drive_dynamics_metrics(std::vector<MetricDefinition>& r) {
  static const std::string kEffects = std::string(kStiffnessEffects) + " (and the profile relief and dynamics keys)";
  const ModelSet dyn{Model::kGeometry, Model::kDynamics};
  r.push_back({"dynamic_factor", "-", QuantityKind::kDimensionless, "",
               "K_V: largest mesh force over the steady response / static mesh force, maximum over the speed range "
               "(dynamics.speed_range, speed rising and falling)",
               dyn, kMass, kEffects, false, {},
               "steady periodic response of the drive train on the mesh force law (docs/models/dynamics.md)",
               [](const ModelResults& m, const MetricRequest&) {
                 const DriveDynamics& d = m.dynamics();
                 return MetricOutcome{d.kv_max, d.warnings.empty() ? std::string() : d.warnings.front()};
               }});
  r.push_back({"dynamic_mesh_force_max", "N", QuantityKind::kForce, "kN",
               "largest dynamic mesh force over one span at the operating speed load.speed", dyn, kMassAndSpeed,
               kEffects, false, {}, "as dynamic_factor, at load.speed",
               [](const ModelResults& m, const MetricRequest&) {
                 const SteadyResponse& s = at_speed(m);
                 return MetricOutcome{s.mesh_force_max, status_remark(s)};
               }});
  r.push_back({"dynamic_transmission_error_pp", "m", QuantityKind::kLength, "um",
               "peak-to-peak of the dynamic transmission error (approach along the line of action) over one span "
               "at load.speed",
               dyn, kMassAndSpeed, kEffects, false, {}, "as dynamic_mesh_force_max",
               [](const ModelResults& m, const MetricRequest&) {
                 const SteadyResponse& s = at_speed(m);
                 return MetricOutcome{s.dte_peak_to_peak, status_remark(s)};
               }});
  r.push_back({"contact_loss_fraction", "-", QuantityKind::kDimensionless, "",
               "share of the time at load.speed in which neither flank carries load (teeth separated)", dyn,
               kMassAndSpeed, kEffects, false, {}, "as dynamic_mesh_force_max",
               [](const ModelResults& m, const MetricRequest&) {
                 const SteadyResponse& s = at_speed(m);
                 return MetricOutcome{s.contact_loss_fraction, status_remark(s)};
               }});
  r.push_back({"resonance_margin", "-", QuantityKind::kDimensionless, "",
               "min |v - v_res| / v_res of the operating speed from the main resonances: the mesh order and the "
               "span order on the lowest natural frequency at the mean tangent stiffness",
               dyn, kMassAndSpeed, kEffects, true, {}, "linearised drive train, Campbell crossings",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{m.dynamics().resonance_margin};
               }});
  r.push_back({"parametric_stability_margin", "-", QuantityKind::kDimensionless, "",
               "1 - the largest Floquet multiplier magnitude of the linearised drive over the speed range (> 0: "
               "parametrically stable at every speed)",
               dyn, kMass, kEffects, false, {}, "monodromy matrix over one span (docs/models/dynamics.md)",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{m.dynamics().stability_margin};
               }});
}

}  // namespace rackopt::metrics
