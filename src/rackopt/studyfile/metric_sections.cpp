#include "rackopt/studyfile/study_sections.hpp"

#include <set>
#include <span>

#include "rackopt/core/run_limits.hpp"
#include "rackopt/core/text.hpp"
#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"
#include "rackopt/statistics/goodness_of_fit.hpp"  // kMinBootstrapReplicates

namespace rackopt::studyfile {

using namespace rackopt::study;
namespace {

const char* const kMetricExamples = "a metric such as contact_ratio, min_stiffness_ks(200) or wear_life_at_R(0.9)";

metrics::MetricRequest read_metric(const MarkedNode& node, const std::string& path) {
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(node.mark, path, std::string("expected ") + kMetricExamples + ", found " + node.type_name());
  }
  try {
    return metrics::resolve_request(metrics::parse_metric_request(node.scalar));
  } catch (const InputError& e) {
    throw InputError(node.mark, path, e.message());
  }
}

// A bound written in the metric's unit: its QuantityKind when it has one
// (bare number = the kind's default unit), else a bare number in the
// metric's SI unit, optionally followed by that unit ("0.8 1/m").
double read_metric_quantity(const MarkedNode& node, const std::string& path, const metrics::MetricDefinition& def) {
  const std::string unit(def.unit);
  if (node.type != MarkedNode::Type::kScalar) {
    throw InputError(
        node.mark, path,
        "expected a value of " + std::string(def.name) + " (unit " + unit + "), found " + node.type_name());
  }
  if (def.kind) return parse_quantity(node.scalar, *def.kind, node.mark, path);
  std::string text = trim(node.scalar);
  if (unit != "-" && text.size() > unit.size() && text.compare(text.size() - unit.size(), unit.size(), unit) == 0) {
    text = trim(std::string_view(text).substr(0, text.size() - unit.size()));
  }
  try {
    return parse_quantity(text, QuantityKind::kDimensionless, node.mark, path);
  } catch (const InputError&) {
    throw InputError(node.mark, path,
                     "'" + node.scalar + "' is not a value of " + std::string(def.name) + "; expected a number in " +
                         unit + " (e.g. 0.8 or 0.8 " + unit + ")");
  }
}

std::string metric_value_text(double v, const metrics::MetricDefinition& def) {
  if (def.kind) return format_in(v, *def.kind, def.display_unit);
  return format_number(v, 10) + (def.unit == "-" ? "" : " " + std::string(def.unit));
}

void read_objectives(const SectionReader& top, StudySpec& spec, std::vector<MetricSite>& metric_sites) {
  if (const MarkedNode* objs = top.get("objectives")) {
    if (objs->type != MarkedNode::Type::kSequence) {
      throw InputError(objs->mark, "objectives",
                       "expected a list of objectives, e.g. [stiffness_fluctuation] or [{metric: wear_life, sense: "
                       "maximize}], found " +
                           objs->type_name());
    }
    std::set<std::string> labels;
    for (std::size_t i = 0; i < objs->items.size(); ++i) {
      const MarkedNode& item = objs->items[i];
      const std::string path = item_path("objectives", i);
      ObjectiveSpec o;
      o.mark = item.mark;
      SourceMark metric_mark = item.mark;
      std::string metric_path = path;
      if (item.is_map()) {
        const SectionReader s = study_section(&item, path, item.mark, {"metric", "sense", "scale"},
                                              "{metric: wear_life, sense: maximize, scale: 1}");
        const MarkedNode* m = s.get("metric");
        if (m == nullptr) s.missing("metric", kMetricExamples);
        metric_mark = m->mark;
        metric_path = s.child_path("metric");
        o.metric = read_metric(*m, metric_path);
        o.maximize = s.choice("sense", {"minimize", "maximize"}).value_or("minimize") == "maximize";
        o.scale = s.plain_number("scale", {.lo = 0, .lo_open = true}).value_or(0);
      } else {
        o.metric = read_metric(item, path);
      }
      o.label = metrics::to_string(o.metric);
      if (!labels.insert(o.label).second) {
        throw InputError(metric_mark, metric_path, "objective '" + o.label + "' is listed twice");
      }
      metric_sites.push_back(MetricSite{o.metric, metric_mark, metric_path});
      spec.objectives.push_back(std::move(o));
    }
  }
}

void read_constraints(const SectionReader& top, StudySpec& spec, std::vector<MetricSite>& metric_sites) {
  if (const MarkedNode* cons = top.get("constraints")) {
    if (cons->type != MarkedNode::Type::kSequence) {
      throw InputError(
          cons->mark, "constraints",
          "expected a list of bounds, e.g. [{metric: contact_ratio, min: 1.3}], found " + cons->type_name());
    }
    for (std::size_t i = 0; i < cons->items.size(); ++i) {
      const MarkedNode& item = cons->items[i];
      const std::string path = item_path("constraints", i);
      const SectionReader s = study_section(&item, path, item.mark, {"metric", "min", "max", "equals", "scale"},
                                            "{metric: contact_ratio, min: 1.3}");
      ConstraintSpec c;
      c.mark = item.mark;
      const MarkedNode* m = s.get("metric");
      if (m == nullptr) s.missing("metric", kMetricExamples);
      c.metric = read_metric(*m, s.child_path("metric"));
      c.label = metrics::to_string(c.metric);
      const metrics::MetricDefinition& def = metrics::find_metric(c.metric.name);
      auto bound = [&](const std::string& key) -> std::optional<double> {
        const MarkedNode* b = s.get(key);
        if (b == nullptr) return std::nullopt;
        return read_metric_quantity(*b, s.child_path(key), def);
      };
      c.min = bound("min");
      c.max = bound("max");
      c.equals = bound("equals");
      if (!c.min && !c.max && !c.equals) {
        throw InputError(
            item.mark, path,
            "a constraint needs at least one bound: min, max or equals (e.g. {metric: " + c.label + ", min: ...})");
      }
      if (c.equals && (c.min || c.max)) {
        const std::string k = c.min ? "min" : "max";
        throw InputError(s.key_mark(k), s.child_path(k), "equals excludes min and max; give either equals or min/max");
      }
      if (c.min && c.max && !(*c.min < *c.max)) {
        throw InputError(s.value_mark("max"), s.child_path("max"),
                         "min " + metric_value_text(*c.min, def) + " must be below max " +
                             metric_value_text(*c.max, def) + " (for a target value use equals)");
      }
      if (const MarkedNode* sc = s.get("scale")) {
        const double v = read_metric_quantity(*sc, s.child_path("scale"), def);
        if (!(v > 0)) {
          throw InputError(sc->mark, s.child_path("scale"),
                           metric_value_text(v, def) + " is out of range; allowed: scale > 0 (default: |the bound|)");
        }
        c.scale = v;
      }
      metric_sites.push_back(MetricSite{c.metric, m->mark, s.child_path("metric")});
      spec.constraints.push_back(std::move(c));
    }
  }
}

void read_report(const SectionReader& top, StudySpec& spec, std::vector<MetricSite>& metric_sites) {
  if (const MarkedNode* rep = top.get("report")) {
    if (rep->type != MarkedNode::Type::kSequence) {
      throw InputError(
          rep->mark, "report",
          "expected a list of metrics, e.g. [mean_stiffness, supports_per_metre], found " + rep->type_name());
    }
    for (std::size_t i = 0; i < rep->items.size(); ++i) {
      const std::string path = item_path("report", i);
      spec.report_metrics.push_back(read_metric(rep->items[i], path));
      metric_sites.push_back(MetricSite{spec.report_metrics.back(), rep->items[i].mark, path});
    }
  }
}

}  // namespace

std::vector<MetricSite> read_metric_sections(const SectionReader& top, StudySpec& spec) {
  std::vector<MetricSite> metric_sites;
  read_objectives(top, spec, metric_sites);
  read_constraints(top, spec, metric_sites);
  read_report(top, spec, metric_sites);
  return metric_sites;
}

SectionReader read_metric_options(const SectionReader& top, StudySpec& spec) {
  const SectionReader mo =
      study_section(top.get("metric_options"), "metric_options", top.key_mark("metric_options"),
                    {"exact_quantile", "reliability_samples", "reliability_seed", "bootstrap_replicates", "cost",
                     "positions_per_period"},
                    "{exact_quantile: on, reliability_samples: 1000}");
  spec.metric_options.exact_quantile = mo.flag("exact_quantile", spec.metric_options.exact_quantile);
  if (const auto samples = mo.integer("reliability_samples", {kSamplesLimit.lo, kSamplesLimit.hi}))
    spec.metric_options.reliability_samples = static_cast<long>(*samples);
  // The study seed drives every random choice, the Monte Carlo included,
  // unless the study pins the Monte Carlo seed itself.
  spec.metric_options.reliability_seed = static_cast<long>(
      mo.integer("reliability_seed", {kSeedLimit.lo, kSeedLimit.hi})
          .value_or(static_cast<long long>(spec.seed % static_cast<unsigned long long>(kSeedLimit.hi + 1))));
  if (const auto positions = mo.integer("positions_per_period", {kPositionsPerPeriodLimit.lo, kPositionsPerPeriodLimit.hi}))
    spec.metric_options.positions_per_period = static_cast<int>(*positions);
  if (const auto replicates = mo.integer("bootstrap_replicates", {statistics::kMinBootstrapReplicates, 100000}))
    spec.metric_options.bootstrap_replicates = static_cast<int>(*replicates);
  {
    const SectionReader cost = study_section(mo.get("cost"), "metric_options.cost", mo.key_mark("cost"),
                                             {"rack_per_kg", "pinion_per_kg", "per_support", "rack_length"},
                                             "{rack_per_kg: 1, pinion_per_kg: 3, per_support: 400, rack_length: 30 m}");
    metrics::CostWeights& w = spec.metric_options.cost;
    w.rack_per_kg = cost.plain_number("rack_per_kg", {.lo = 0}).value_or(w.rack_per_kg);
    w.pinion_per_kg = cost.plain_number("pinion_per_kg", {.lo = 0}).value_or(w.pinion_per_kg);
    w.per_support = cost.plain_number("per_support", {.lo = 0}).value_or(w.per_support);
    w.rack_length = cost.quantity_in("rack_length", QuantityKind::kLength, {.lo = 0}, {}, "m",
                                     expected_kind_text(QuantityKind::kLength))
                        .value_or(w.rack_length);
  }
  return mo;
}

void check_metrics_against_problem(const std::vector<MetricSite>& sites, const SectionReader& options_section,
                                   const Drive& drive, const StudySpec& spec) {
  for (const MetricSite& site : sites) {
    try {
      metrics::check_metric_requests(drive, std::span<const metrics::MetricRequest>(&site.request, 1),
                                     spec.metric_options);
    } catch (const InputError& e) {
      throw InputError(site.mark, site.path,
                       metrics::to_string(site.request) + " cannot be computed for the problem '" + spec.problem_path +
                           "': " + (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
    }
  }
  {
    const std::vector<metrics::MetricRequest> all = spec.all_metrics();
    try {
      metrics::check_metric_requests(drive, all, spec.metric_options);
    } catch (const InputError& e) {
      throw InputError(options_section.mark(), "metric_options" + (e.key_path().empty() ? "" : "." + e.key_path()),
                       e.message());
    }
  }
}

}  // namespace rackopt::studyfile
