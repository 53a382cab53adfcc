// Metrics of the contact geometry and the rack layout.
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
  r.push_back({"supports_per_metre", "1/m", std::nullopt, "",
               "rack supports (hinges) per metre of rack, 1/rack.span: a cost proxy", ModelSet{}, 0, "",
               true, {}, "definition",
               [](const ModelResults& m, const MetricRequest&) {
                 if (!(m.drive->rack.span > 0)) throw DesignError("non_finite", "rack.span is not positive");
                 return MetricOutcome{1.0 / m.drive->rack.span};
               }});
}

}  // namespace rackopt::metrics
