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
// ln k of every sample and of the refined extremes.
std::vector<double> ln_stiffness(const StiffnessCurve& c) {
  std::vector<double> lnk;
  lnk.reserve(c.samples.size() + 2);
  bool positive = c.k_min > 0;
  for (const MeshState& s : c.samples) {
    positive = positive && s.stiffness > 0;
    if (positive) lnk.push_back(std::log(s.stiffness));
  }
  if (!positive) {
    throw DesignError("non_finite", "mesh stiffness not positive somewhere: the KS aggregate of ln k is undefined");
  }
  lnk.push_back(std::log(c.k_min));
  lnk.push_back(std::log(c.k_max));
  return lnk;
}
// Each metric computes only the side it reports (an exponential per sample
// and side).
double ks_lower_bound(const StiffnessCurve& c, double rho) { return std::exp(ks_min(ln_stiffness(c), rho, 1.0)); }
double ks_upper_bound(const StiffnessCurve& c, double rho) { return std::exp(ks_max(ln_stiffness(c), rho, 1.0)); }
KsBounds ks_bounds(const StiffnessCurve& c, double rho) {
  const std::vector<double> lnk = ln_stiffness(c);
  return {std::exp(ks_min(lnk, rho, 1.0)), std::exp(ks_max(lnk, rho, 1.0))};
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
