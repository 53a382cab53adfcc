// Size, mass, torque, power and cost: what "sizing" means when it must mean
// small. docs/metrics.md gives every formula and its hand check.
#include <algorithm>
#include <cmath>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/pinion_section.hpp"
#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {
namespace {

constexpr auto bit = [](Requirement r) { return static_cast<std::uint8_t>(r); };

double pitch_radius(const Drive& d) { return 0.5 * d.pinion.module * d.pinion.teeth; }

// Tangential force on the rack F_t = F_n cos a0 (the rack's operating
// pressure angle is a0 whatever the shift or clearance).
double thrust(const Drive& d) { return d.load.force * std::cos(d.pinion.pressure_angle); }

double rack_face_width(const Drive& d) { return d.rack.face_width > 0 ? d.rack.face_width : d.pinion.face_width; }

// Trapezoidal rack tooth between its root line and tip line (the root
// rounds are left out: a few per mille of the tooth).
double rack_tooth_area(const Drive& d) {
  const double m = d.pinion.module;
  const double t = std::tan(d.pinion.pressure_angle);
  const double ha = d.rack.addendum_coef * m, hf = d.rack.dedendum_coef * m;
  const double width_root = 0.5 * M_PI * m + 2 * hf * t;
  const double width_tip = 0.5 * M_PI * m - 2 * ha * t;
  return 0.5 * (width_root + width_tip) * (ha + hf);
}

double rack_mass_per_metre(const Drive& d) {
  const double pitch = M_PI * d.pinion.module;
  return d.rack.material.density * (d.rack.section.area + rack_tooth_area(d) * rack_face_width(d) / pitch);
}

double pinion_mass(const ModelResults& m) {
  const Drive& d = *m.drive;
  const double area = pinion_outline_area(d.pinion, m.geometry()) - M_PI * d.pinion.bore_radius * d.pinion.bore_radius;
  return d.pinion.material.density * d.pinion.face_width * area;
}

}  // namespace

void append_size_metrics(std::vector<MetricDefinition>& r) {
  const ModelSet none{};
  const ModelSet geometry{Model::kGeometry};
  r.push_back({"pinion_pitch_diameter", "m", QuantityKind::kLength, "mm", "pinion pitch diameter d = m z", none, 0, "",
               true, {}, "definition (ISO 21771)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{2 * pitch_radius(*m.drive)}; }});
  r.push_back({"pinion_tip_diameter", "m", QuantityKind::kLength, "mm",
               "pinion tip diameter d_a = m z + 2 (h_a* + x) m: the size of the pinion", none, 0, "", true, {},
               "definition (ISO 21771)",
               [](const ModelResults& m, const MetricRequest&) {
                 const PinionSpec& p = m.drive->pinion;
                 return MetricOutcome{p.module * p.teeth + 2 * (p.addendum_coef + p.profile_shift) * p.module};
               }});
  r.push_back({"face_width_ratio", "-", QuantityKind::kDimensionless, "",
               "common face width over module, b/m: alignment and load distribution across the face "
               "(rules of thumb: 6..12 for mounted rack drives, up to 20 on rigid precise housings)",
               none, 0, "", true, {}, "b = min(pinion, rack face width)",
               [](const ModelResults& m, const MetricRequest&) {
                 const Drive& d = *m.drive;
                 return MetricOutcome{std::min(d.pinion.face_width, rack_face_width(d)) / d.pinion.module};
               }});
  r.push_back({"pinion_mass", "kg", QuantityKind::kMass, "kg",
               "pinion mass: density x face width x the area of the generated outline (tips, involutes, "
               "trochoidal fillets, root) less the bore",
               geometry, 0, "", true, {}, "pinion_outline_area (geometry/pinion_section.hpp)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{pinion_mass(m)}; }});
  r.push_back({"rack_mass_per_metre", "kg/m", std::nullopt, "",
               "rack mass per metre: density x (body section + trapezoidal tooth area x rack face width / pitch)",
               none, 0, "", true, {}, "rack.section.area and the rack tooth proportions",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{rack_mass_per_metre(*m.drive)}; }});
  r.push_back({"rack_section_height", "m", QuantityKind::kLength, "mm",
               "rack height from the body's underside to the tooth tips: body_height + (h_a2* + h_f2*) m", none,
               bit(Requirement::kBodyHeight), "", true, {}, "definition",
               [](const ModelResults& m, const MetricRequest&) {
                 const Drive& d = *m.drive;
                 return MetricOutcome{d.rack.body_height +
                                      (d.rack.addendum_coef + d.rack.dedendum_coef) * d.pinion.module};
               }});
  r.push_back({"pinion_torque", "N*m", QuantityKind::kTorque, "kN*m",
               "pinion torque for the design load T = F_n r_b = F_t r", none, 0, "", true, {}, "statics",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{thrust(*m.drive) * pitch_radius(*m.drive)};
               }});
  r.push_back({"pinion_speed", "1/s", QuantityKind::kRate, "1/min",
               "pinion revolutions per unit time at load.speed: v / (pi m z)", none, bit(Requirement::kSpeed), "",
               true, {}, "kinematics",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{m.drive->load.speed / (2 * M_PI * pitch_radius(*m.drive))};
               }});
  r.push_back({"drive_power", "W", QuantityKind::kPower, "kW",
               "power the drive must deliver for the thrust at load.speed through load.efficiency: F_t v / eta", none,
               bit(Requirement::kSpeed), "", true, {}, "P = F_t v / eta",
               [](const ModelResults& m, const MetricRequest&) {
                 const Drive& d = *m.drive;
                 return MetricOutcome{thrust(d) * d.load.speed / d.load.efficiency};
               }});
  r.push_back({"cost_per_metre", "1/m", std::nullopt, "",
               "cost proxy per metre of rack: rack_per_kg x rack mass per metre + per_support / span + "
               "pinion_per_kg x pinion mass / rack length (weights: the study's metric_options.cost)",
               geometry, bit(Requirement::kRackLength), "", true, {}, "definition (weights chosen by the study)",
               [](const ModelResults& m, const MetricRequest&) {
                 const Drive& d = *m.drive;
                 const CostWeights& w = m.options->cost;
                 const double length = w.rack_length > 0 ? w.rack_length : d.duty.stroke;
                 double c = w.rack_per_kg * rack_mass_per_metre(d) + w.per_support / d.rack.span;
                 if (w.pinion_per_kg > 0) c += w.pinion_per_kg * pinion_mass(m) / length;
                 return MetricOutcome{c};
               }});
}

}  // namespace rackopt::metrics
