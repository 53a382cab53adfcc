#include "rackopt/study/fidelity_settings.hpp"

#include "rackopt/wear_reliability/life_scaling.hpp"

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::study {

std::vector<std::pair<std::string, std::string>> fidelity_settings(const Drive& d, const StudySpec& spec) {
  std::vector<std::pair<std::string, std::string>> out;
  auto num = [](double v) { return format_number(v, 6); };
  auto on = [](bool b) { return std::string(b ? "on" : "off"); };
  out.emplace_back("numerics.quadrature_order", d.numerics.adaptive_quadrature ? "adaptive (GSL QAGS)"
                                                                                : num(d.numerics.quadrature_order));
  out.emplace_back("numerics.positions_per_period", num(d.numerics.positions_per_period));
  // The metrics' curve may be sampled more coarsely than the plotted one.
  if (spec.metric_options.positions_per_period)
    out.emplace_back("metric_options.positions_per_period", num(*spec.metric_options.positions_per_period) +
                                                                " (the metrics' curve; the plots use the problem's)");
  if (d.wear.coefficient > 0) {
    out.emplace_back("wear.profile_points", num(d.wear.profile_points));
    out.emplace_back("wear.block_fraction", num(d.wear.block_fraction));
    out.emplace_back("wear.update_profile", on(d.wear.update_profile));
  }
  bool life_at_R = false;
  // Any metric that runs the wear reliability model samples with these settings.
  for (const auto& m : spec.all_metrics())
    life_at_R = life_at_R || metrics::find_metric(m.name).models.contains(metrics::Model::kWearReliability);
  if (life_at_R) {
    const metrics::MetricOptions& o = spec.metric_options;
    const std::size_t inputs = d.reliability.inputs.size();
    const bool exact = inputs == 1 && o.exact_quantile;
    out.emplace_back("reliability inputs", num(static_cast<double>(inputs)));
    if (exact) {
      out.emplace_back("life at R", "exact quantile of the one random input (no sampling)");
    } else if (inputs > 0) {
      out.emplace_back("reliability samples", num(o.reliability_samples ? static_cast<double>(*o.reliability_samples)
                                                                         : d.reliability.samples));
      out.emplace_back("reliability seed", num(o.reliability_seed ? static_cast<double>(*o.reliability_seed)
                                                                    : static_cast<double>(d.reliability.seed)));
      out.emplace_back("reliability sampling", d.reliability.sobol ? "sobol" : "pseudo");
      out.emplace_back("bootstrap replicates", num(o.bootstrap_replicates.value_or(d.reliability.bootstrap_replicates)));
      // The table runs along the one input that shapes the life (contact
      // ratio or load); the wear coefficient and the hardness only scale it
      // (wear_reliability/life_scaling.hpp).
      std::size_t shaping = 0;
      for (const auto& in : d.reliability.inputs) shaping += input_scales_life(in.key) ? 0 : 1;
      out.emplace_back("life table", shaping == 0   ? std::string("not needed (the inputs only scale the nominal life)")
                                     : shaping == 1 ? on(d.reliability.life_table) + ", tolerance " +
                                                          num(d.reliability.life_table_tolerance)
                                                    : std::string("off (two inputs shape the life)"));
    }
  }
  return out;
}

}  // namespace rackopt::study
