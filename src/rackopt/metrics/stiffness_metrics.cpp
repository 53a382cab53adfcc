// Metrics of the mesh stiffness curve over one rack span.
#include <cmath>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/metrics/ks_aggregate.hpp"
#include "rackopt/metrics/metric_families.hpp"
#include "rackopt/metrics/model_results.hpp"

namespace rackopt::metrics {
namespace {

// KS aggregation weight on ln k: relative gap to the true extreme <= ln(N)/rho.
constexpr ParameterSpec kRho{ParameterSpec::Use::kOptional, "rho", 500.0, 0.0, 1e7,
                             "KS weight on ln k; relative gap to the true extreme at most ln(N)/rho"};

// KS on ln k over the samples plus the refined extremes (so the bounds hold
// against k_min/k_max themselves, not only against the samples). On the
// logarithm the aggregate is scale-free: its relative gap is at most
// ln(N)/rho whatever the stiffness level, and exp(KS(ln k)) =
// (sum k_i^-rho)^(-1/rho) is a power mean.
struct KsBounds {
  double lo = 0, hi = 0;
};
// k of every sample and of the refined extremes.
std::vector<double> stiffness_values(const StiffnessCurve& c) {
  std::vector<double> k;
  k.reserve(c.samples.size() + 2);
  bool positive = c.k_min > 0;
  for (const MeshState& s : c.samples) {
    positive = positive && s.stiffness > 0;
    k.push_back(s.stiffness);
  }
  if (!positive) {
    throw DesignError("non_finite", "mesh stiffness not positive somewhere: the KS aggregate of ln k is undefined");
  }
  k.push_back(c.k_min);
  k.push_back(c.k_max);
  return k;
}
// Each metric computes only the side it reports.
double ks_lower_bound(const StiffnessCurve& c, double rho) { return power_mean_min(stiffness_values(c), rho); }
double ks_upper_bound(const StiffnessCurve& c, double rho) { return power_mean_max(stiffness_values(c), rho); }
KsBounds ks_bounds(const StiffnessCurve& c, double rho) {
  const std::vector<double> k = stiffness_values(c);
  return {power_mean_min(k, rho), power_mean_max(k, rho)};
}

}  // namespace

void append_stiffness_metrics(std::vector<MetricDefinition>& r) {
  const ModelSet curve{Model::kStiffnessCurve};
  r.push_back({"stiffness_fluctuation", "-", QuantityKind::kDimensionless, "",
               "(k_max - k_min)/k_mean of the mesh stiffness over one rack span", curve, 0,
               kStiffnessEffects, false, {}, "StiffnessCurve::k_fluctuation (docs/models/mesh.md)",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.curve().k_fluctuation}; }});
  r.push_back({"min_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "smallest mesh stiffness over one rack span (refined inside smooth pieces)", curve, 0,
               kStiffnessEffects, false, {}, "StiffnessCurve::k_min",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.curve().k_min}; }});
  r.push_back({"max_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "largest mesh stiffness over one rack span", curve, 0, kStiffnessEffects, false, {},
               "StiffnessCurve::k_max",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.curve().k_max}; }});
  r.push_back({"mean_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "mean mesh stiffness over one rack span (piecewise cubic quadrature)", curve, 0,
               kStiffnessEffects, true, {}, "StiffnessCurve::k_mean",
               [](const ModelResults& m, const MetricRequest&) { return MetricOutcome{m.curve().k_mean}; }});
  r.push_back({"min_stiffness_ks", "N/m", QuantityKind::kStiffness, "MN/m",
               "Kreisselmeier-Steinhauser smooth minimum of the stiffness samples: a lower bound of "
               "min_stiffness",
               curve, 0, kStiffnessEffects, true, kRho,
               "exp(KS(ln k)) = (sum k_i^-rho)^(-1/rho) over the curve samples and the refined extremes "
               "(Kreisselmeier & Steinhauser 1979)",
               [](const ModelResults& m, const MetricRequest& q) {
                 return MetricOutcome{ks_lower_bound(m.curve(), *q.parameter)};
               }});
  r.push_back({"max_stiffness_ks", "N/m", QuantityKind::kStiffness, "MN/m",
               "Kreisselmeier-Steinhauser smooth maximum of the stiffness samples: an upper bound of "
               "max_stiffness",
               curve, 0, kStiffnessEffects, true, kRho, "exp(KS(ln k)) = (sum k_i^rho)^(1/rho)",
               [](const ModelResults& m, const MetricRequest& q) {
                 return MetricOutcome{ks_upper_bound(m.curve(), *q.parameter)};
               }});
  r.push_back({"stiffness_fluctuation_ks", "-", QuantityKind::kDimensionless, "",
               "(max_stiffness_ks - min_stiffness_ks)/k_mean: a smooth upper bound of "
               "stiffness_fluctuation",
               curve, 0, kStiffnessEffects, true, kRho, "from the two KS aggregates",
               [](const ModelResults& m, const MetricRequest& q) {
                 const KsBounds b = ks_bounds(m.curve(), *q.parameter);
                 return MetricOutcome{(b.hi - b.lo) / m.curve().k_mean};
               }});
}

}  // namespace rackopt::metrics
