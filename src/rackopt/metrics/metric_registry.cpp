#include "rackopt/metrics/metric_registry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "rackopt/core/error.hpp"
#include "rackopt/core/suggest.hpp"
#include "rackopt/metrics/mesh_dynamics_metrics.hpp"  // mesh ripple, transmission error

namespace rackopt::metrics {
namespace {

constexpr std::uint8_t kWearBits = static_cast<std::uint8_t>(Requirement::kWear);
constexpr std::uint8_t kDutyBits = static_cast<std::uint8_t>(Requirement::kDuty);
constexpr std::uint8_t kBendBits = static_cast<std::uint8_t>(Requirement::kAllowableBending);
constexpr std::uint8_t kContactBits = static_cast<std::uint8_t>(Requirement::kAllowableContact);

constexpr std::string_view kStiffnessEffects =
    "pinion_tooth, root_segment, fillet_foundation, rack_tooth, hertz, rack_span, couple_term, "
    "body_axial, body_shear, interference_limit, spalling";
constexpr std::string_view kWearEffects =
    "pinion_tooth, fillet_foundation, hertz, interference_limit";

// KS aggregation weight on ln k: relative gap to the true extreme <= ln(N)/rho.
constexpr ParameterSpec kRho{ParameterSpec::Use::kOptional, "rho", 500.0, 0.0, 1e7,
                             "KS weight on ln k; relative gap to the true extreme at most ln(N)/rho"};

std::vector<MetricDefinition> build_registry() {
  const ModelSet curve{Model::kStiffnessCurve};
  const ModelSet stress{Model::kGeometry, Model::kStress};
  std::vector<MetricDefinition> r;
  r.push_back({"stiffness_fluctuation", "-", QuantityKind::kDimensionless, "",
               "(k_max - k_min)/k_mean of the mesh stiffness over one rack span", curve, 0,
               kStiffnessEffects, false, {}, "StiffnessCurve::k_fluctuation (physics.md 6.3, 7.2)"});
  r.push_back({"min_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "smallest mesh stiffness over one rack span (refined inside smooth pieces)", curve, 0,
               kStiffnessEffects, false, {}, "StiffnessCurve::k_min"});
  r.push_back({"max_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "largest mesh stiffness over one rack span", curve, 0, kStiffnessEffects, false, {},
               "StiffnessCurve::k_max"});
  r.push_back({"mean_stiffness", "N/m", QuantityKind::kStiffness, "MN/m",
               "mean mesh stiffness over one rack span (piecewise cubic quadrature)", curve, 0,
               kStiffnessEffects, true, {}, "StiffnessCurve::k_mean"});
  r.push_back({"min_stiffness_ks", "N/m", QuantityKind::kStiffness, "MN/m",
               "Kreisselmeier-Steinhauser smooth minimum of the stiffness samples: a lower bound of "
               "min_stiffness",
               curve, 0, kStiffnessEffects, true, kRho,
               "exp(KS(ln k)) = (sum k_i^-rho)^(-1/rho) over the curve samples and the refined extremes "
               "(Kreisselmeier & Steinhauser 1979)"});
  r.push_back({"max_stiffness_ks", "N/m", QuantityKind::kStiffness, "MN/m",
               "Kreisselmeier-Steinhauser smooth maximum of the stiffness samples: an upper bound of "
               "max_stiffness",
               curve, 0, kStiffnessEffects, true, kRho,
               "exp(KS(ln k)) = (sum k_i^rho)^(1/rho)"});
  r.push_back({"stiffness_fluctuation_ks", "-", QuantityKind::kDimensionless, "",
               "(max_stiffness_ks - min_stiffness_ks)/k_mean: a smooth upper bound of "
               "stiffness_fluctuation",
               curve, 0, kStiffnessEffects, true, kRho, "from the two KS aggregates"});
  add_mesh_dynamics_definitions(r);  // mesh ripple, transmission error (mesh_dynamics_metrics.cpp)
  r.push_back({"contact_ratio", "-", QuantityKind::kDimensionless, "",
               "contact ratio of the path actually used (interference limits when enabled)",
               ModelSet{Model::kGeometry}, 0, "interference_limit", true, {},
               "ContactPath::contact_ratio (physics.md 7.2)"});
  r.push_back({"supports_per_metre", "1/m", std::nullopt, "",
               "rack supports (hinges) per metre of rack, 1/rack.span: a cost proxy", ModelSet{}, 0, "",
               true, {}, "definition"});
  r.push_back({"wear_life", "s", QuantityKind::kTime, "yr",
               "deterministic Archard wear life of the nominal drive", ModelSet{Model::kWearLife},
               static_cast<std::uint8_t>(kWearBits | kDutyBits), kWearEffects, false, {},
               "WearModel(drive).life(WearSample{}) (physics.md 10, docs/models/wear.md)"});
  r.push_back({"wear_life_cycles", "-", QuantityKind::kDimensionless, "",
               "deterministic wear life in rack passes (no duty needed)", ModelSet{Model::kWearLife},
               kWearBits, kWearEffects, false, {}, "WearLifeResult::life_cycles"});
  r.push_back({"wear_life_at_R", "s", QuantityKind::kTime, "yr",
               "wear life reached with probability R under the problem's reliability inputs "
               "(fixed seed: common random numbers across designs)",
               ModelSet{Model::kWearReliability}, static_cast<std::uint8_t>(kWearBits | kDutyBits),
               kWearEffects, false,
               {ParameterSpec::Use::kRequired, "R", 0.0, 0.0, 1.0, "reliability, strictly inside (0, 1)"},
               "exact input quantile (one monotone input) or run_wear_reliability (physics.md 12)"});
  r.push_back({"root_bending_stress", "Pa", QuantityKind::kModulus, "MPa",
               "pinion tooth-root bending stress, load at the tip, 30 deg tangent critical section "
               "of the generated fillet",
               stress, 0, "interference_limit", true, {},
               "ISO 6336-3:1996 method C (Y_F, Y_S, Y_eps at the tip) on the real tooth"});
  r.push_back({"rack_root_bending_stress", "Pa", QuantityKind::kModulus, "MPa",
               "rack tooth-root bending stress, load at the highest rack contact, 30 deg tangent on "
               "the rack root round",
               stress, 0, "interference_limit", true, {}, "ISO 6336-3 form, trapezoid rack tooth"});
  r.push_back({"root_bending_safety", "-", QuantityKind::kDimensionless, "",
               "min(S_F pinion, S_F rack), S_F = allowable bending / root stress", stress, kBendBits,
               "interference_limit", true, {}, "ISO 6336-3 S_F = sigma_FP / sigma_F"});
  r.push_back({"contact_stress", "Pa", QuantityKind::kModulus, "MPa",
               "nominal flank contact stress Z_E Z_H Z_eps sqrt(F_t/(b d)) (rack: u -> infinity)",
               stress, 0, "interference_limit", true, {}, "ISO 6336-2 (Z_B, Z_beta = 1)"});
  r.push_back({"contact_safety", "-", QuantityKind::kDimensionless, "",
               "S_H = allowable contact stress (weaker member) / contact stress", stress, kContactBits,
               "interference_limit", true, {}, "ISO 6336-2 S_H = sigma_HP / sigma_H"});
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
  }
  return "?";
}

std::vector<std::string> ModelSet::names() const {
  std::vector<std::string> out;
  for (Model m : {Model::kGeometry, Model::kStiffnessCurve, Model::kWearLife, Model::kWearReliability,
                  Model::kStress}) {
    if (contains(m)) out.emplace_back(model_name(m));
  }
  return out;
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
  const MetricDefinition* best = nullptr;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const MetricDefinition& d : reg) {
    const std::size_t e = edit_distance(name, d.name);
    if (e < best_d) {
      best_d = e;
      best = &d;
    }
  }
  const std::size_t allowed = std::max<std::size_t>(2, name.size() / 3);
  if (best && best_d <= allowed) msg += " (did you mean '" + std::string(best->name) + "'?)";
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
