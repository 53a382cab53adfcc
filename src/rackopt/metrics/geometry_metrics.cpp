// Metrics of the contact geometry and the rack layout.
#include <cmath>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {

void append_geometry_metrics(std::vector<MetricDefinition>& r) {
  r.push_back({"contact_ratio", "-", QuantityKind::kDimensionless, "",
               "contact ratio of the path actually used (interference limits when enabled)",
               ModelSet{Model::kGeometry}, 0, "interference_limit", true, {},
               "ContactPath::contact_ratio (docs/models/geometry.md)",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{m.geometry().path.contact_ratio};
               }});
  // The clearance as a lower bound: a study that keeps the backlash above
  // what the rack's pitch and mounting tolerances use up (the teeth must not
  // jam at the tightest point) constrains it here instead of the clearance.
  r.push_back({"backlash", "m", QuantityKind::kLength, "mm",
               "circumferential backlash on the pitch line from mounting.clearance: j_t = 2 Delta tan a0",
               ModelSet{Model::kGeometry}, 0, "", true, {},
               "MeshGeometry::backlash (docs/models/geometry.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.geometry().backlash}; }});
  r.push_back({"normal_backlash", "m", QuantityKind::kLength, "mm",
               "backlash along the line of action (the flank normal): j_n = j_t cos a0 = 2 Delta sin a0, the gap "
               "the back flanks close before they touch",
               ModelSet{Model::kGeometry}, 0, "", true, {},
               "MeshGeometry::backlash cos a0 (docs/models/geometry.md)",
               [](const ModelResults& m, const MetricRequest&) {
                 return MetricOutcome{m.geometry().backlash * std::cos(m.geometry().pressure_angle)};
               }});
  r.push_back({"supports_per_metre", "1/m", std::nullopt, "",
               "rack supports (hinges) per metre of rack, 1/rack.span: a cost proxy", ModelSet{}, 0, "",
               true, {}, "definition",
               [](const ModelResults& m, const MetricRequest&) {
                 if (!(m.drive->rack.span > 0)) throw DesignError("non_finite", "rack.span is not positive");
                 return MetricOutcome{1.0 / m.drive->rack.span};
               }});
}

}  // namespace rackopt::metrics
