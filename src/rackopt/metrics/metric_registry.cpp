#include "rackopt/metrics/metric_registry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "rackopt/core/error.hpp"
#include "rackopt/core/suggest.hpp"
#include "rackopt/metrics/metric_families.hpp"

namespace rackopt::metrics {
namespace {

std::vector<MetricDefinition> build_registry() {
  std::vector<MetricDefinition> r;
  append_stiffness_metrics(r);
  append_mesh_dynamics_metrics(r);
  append_drive_dynamics_metrics(r);
  append_geometry_metrics(r);
  append_wear_metrics(r);
  append_stress_metrics(r);
  append_size_metrics(r);
  check_registry(r);
  return r;
}

[[noreturn]] void bad_metric(const std::string& message) {
  throw InputError(SourceMark{"<metric>", 0, 0}, "metric", message);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string format_double(double v) {
  std::array<char, 64> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), res.ptr);
}

}  // namespace

std::string_view model_name(Model m) {
  switch (m) {
    case Model::kGeometry: return "geometry";
    case Model::kStiffnessCurve: return "stiffness_curve";
    case Model::kWearLife: return "wear_life";
    case Model::kWearReliability: return "wear_reliability";
    case Model::kStress: return "stress";
    case Model::kMeshRipple: return "mesh_ripple";
    case Model::kTransmissionError: return "transmission_error";
    case Model::kDynamics: return "dynamics";
  }
  return "?";
}

std::vector<std::string> ModelSet::names() const {
  std::vector<std::string> out;
  for (Model m : {Model::kGeometry, Model::kStiffnessCurve, Model::kWearLife, Model::kWearReliability,
                  Model::kStress, Model::kMeshRipple, Model::kTransmissionError, Model::kDynamics}) {
    if (contains(m)) out.emplace_back(model_name(m));
  }
  return out;
}

void check_registry(const std::vector<MetricDefinition>& registry) {
  for (std::size_t i = 0; i < registry.size(); ++i) {
    const MetricDefinition& d = registry[i];
    const std::string who = "metric registry: '" + std::string(d.name) + "'";
    if (d.name.empty()) throw std::logic_error("metric registry: a definition without a name");
    if (!d.compute) throw std::logic_error(who + " has no computation");
    if (d.unit.empty() || d.description.empty() || d.source.empty())
      throw std::logic_error(who + " lacks its unit, description or source");
    for (std::size_t j = 0; j < i; ++j) {
      if (registry[j].name == d.name) throw std::logic_error(who + " is defined twice");
    }
  }
}

const std::vector<MetricDefinition>& metric_registry() {
  static const std::vector<MetricDefinition> registry = build_registry();
  return registry;
}

const MetricDefinition& find_metric(std::string_view name) {
  const auto& reg = metric_registry();
  for (const MetricDefinition& d : reg) {
    if (d.name == name) return d;
  }
  std::string msg = "unknown metric '" + std::string(name) + "'";
  std::vector<std::string> names;
  for (const MetricDefinition& d : reg) names.emplace_back(d.name);
  if (const auto best = closest_name(name, names)) msg += " (did you mean '" + *best + "'?)";
  msg += "; valid metrics:";
  for (const MetricDefinition& d : reg) {
    msg += " ";
    msg += d.name;
  }
  bad_metric(msg);
}

MetricRequest resolve_request(const MetricRequest& request) {
  const MetricDefinition& def = find_metric(request.name);
  MetricRequest out = request;
  const ParameterSpec& p = def.parameter;
  const std::string who = "metric '" + request.name + "'";
  switch (p.use) {
    case ParameterSpec::Use::kNone:
      if (request.parameter) bad_metric(who + " takes no parameter");
      return out;
    case ParameterSpec::Use::kRequired:
      if (!request.parameter) {
        bad_metric(who + " needs its parameter " + std::string(p.name) + " (" + std::string(p.meaning) +
                   "), e.g. '" + request.name + "(0.9)'");
      }
      break;
    case ParameterSpec::Use::kOptional:
      if (!request.parameter) out.parameter = p.default_value;
      break;
  }
  const double v = *out.parameter;
  if (!std::isfinite(v) || !(v > p.lower) || !(v < p.upper)) {
    bad_metric(who + ": parameter " + std::string(p.name) + " = " + format_double(v) +
               " must lie strictly between " + format_double(p.lower) + " and " + format_double(p.upper) +
               " (" + std::string(p.meaning) + ")");
  }
  return out;
}

MetricRequest parse_metric_request(std::string_view text) {
  const std::string_view t = trim(text);
  MetricRequest req;
  const std::size_t open = t.find('(');
  if (open == std::string_view::npos) {
    if (t.find(')') != std::string_view::npos) bad_metric("'" + std::string(text) + "': ')' without '('");
    req.name = std::string(t);
  } else {
    if (t.back() != ')') bad_metric("'" + std::string(text) + "': expected 'name(number)'");
    req.name = std::string(trim(t.substr(0, open)));
    const std::string_view arg = trim(t.substr(open + 1, t.size() - open - 2));
    double v = 0;
    const char* first = arg.data();
    const char* last = arg.data() + arg.size();
    if (!arg.empty() && *first == '+') ++first;
    const auto res = std::from_chars(first, last, v);
    if (arg.empty() || res.ec != std::errc() || res.ptr != last) {
      bad_metric("'" + std::string(text) + "': the parameter '" + std::string(arg) + "' is not a number");
    }
    req.parameter = v;
  }
  if (req.name.empty()) bad_metric("'" + std::string(text) + "': no metric name");
  resolve_request(req);  // checks name and parameter; the request keeps what was written
  return req;
}

std::string to_string(const MetricRequest& request) {
  if (!request.parameter) return request.name;
  return request.name + "(" + format_double(*request.parameter) + ")";
}

}  // namespace rackopt::metrics
