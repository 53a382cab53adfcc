#include "rackopt/problem/random_input_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "rackopt/marked_yaml/section_reader.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct RandomInputKind {
  const char* name;   // as written in the file
  const char* key;    // RandomInput::key
  QuantityKind kind;  // unit kind of its values
};
constexpr RandomInputKind kRandomInputs[] = {
    {"contact_ratio", "contact_ratio", QuantityKind::kDimensionless},
    {"wear_coefficient", "wear.coefficient", QuantityKind::kDimensionless},
    {"load", "load", QuantityKind::kForce},
    {"surface_hardness", "surface_hardness", QuantityKind::kHardness},
};

// The parameters of one distribution in one form: `first` and `second` are
// required (second may be replaced by `alternative`), `optional` may be absent.
struct Form {
  std::vector<std::string> required;  // in order: a, b
  std::string alternative;            // replaces required[1] (normal around the design: cv for sd)
  std::string optional;               // shift / median_factor
};

class Item : public SectionReader {
 public:
  using SectionReader::SectionReader;

  std::optional<double> quantity(const std::string& key, QuantityKind kind) const {
    const auto text = scalar(key, expected(kind));
    if (!text) return std::nullopt;
    return parse_quantity(text->first, kind, text->second, child_path(key));
  }
  double required(const std::string& key, QuantityKind kind, const std::string& what) const {
    const auto v = quantity(key, kind);
    if (!v) missing(key, expected(kind) + " (" + what + ")");
    return *v;
  }
  // Same text as the problem loader's range errors.
  void check(const std::string& key, QuantityKind kind, double v, double lo, double hi, bool lo_open, bool hi_open,
             const std::string& why) const {
    const bool below = lo_open ? !(v > lo) : !(v >= lo);
    const bool above = hi_open ? !(v < hi) : !(v <= hi);
    if (!below && !above) return;
    std::string range;
    if (std::isfinite(lo)) range += format_quantity(lo, kind) + (lo_open ? " < " : " <= ");
    range += key;
    if (std::isfinite(hi)) range += std::string(hi_open ? " < " : " <= ") + format_quantity(hi, kind);
    const auto text = scalar(key, "");
    throw InputError(text ? text->second : key_mark(key), child_path(key),
                     format_quantity(v, kind) + " is out of range; allowed: " + range + why);
  }
  static std::string expected(QuantityKind kind) {
    switch (kind) {
      case QuantityKind::kDimensionless: return "a plain number";
      case QuantityKind::kForce: return "a force (e.g. 50 kN)";
      case QuantityKind::kHardness: return "a hardness (e.g. 596 HB)";
      default: return "a number";
    }
  }
};

}  // namespace

RandomInput read_random_input(const MarkedNode& item, const std::string& path) {
  if (!item.is_map()) {
    throw InputError(item.mark, path,
                     "expected a map {input: contact_ratio, distribution: normal, sd: ...} (around the design) or "
                     "{input: ..., distribution: normal, mean: ..., sd: ..., absolute: true}, found " +
                         item.type_name());
  }
  const Item b(&item, path, item.mark,
               {"input", "distribution", "absolute", "shift", "sd", "cv", "sigma", "median_factor", "half_width",
                "mean", "median", "lower", "upper", "scale", "shape"});
  std::vector<std::string> inputs;
  for (const auto& r : kRandomInputs) inputs.emplace_back(r.name);
  const auto choice = [&](const std::string& key, const std::vector<std::string>& options) {
    const auto value = b.choice(key, options);
    if (!value) b.missing(key, key == "input" ? "the uncertain input: " + join(options, " | ")
                                              : "one of " + join(options, " | "));
    return *value;
  };
  const std::string input = choice("input", inputs);
  const RandomInputKind* which = nullptr;
  for (const auto& r : kRandomInputs) {
    if (input == r.name) which = &r;
  }
  const std::string distribution = choice("distribution", {"normal", "lognormal", "uniform", "weibull"});
  RandomInput out;
  out.key = which->key;
  out.absolute = b.flag("absolute", false);
  const QuantityKind unit = which->kind;
  const QuantityKind plain = QuantityKind::kDimensionless;

  Form form;
  if (out.absolute) {
    if (distribution == "normal") form = {{"mean", "sd"}, "", ""};
    if (distribution == "lognormal") form = {{"median", "sigma"}, "", ""};
    if (distribution == "uniform") form = {{"lower", "upper"}, "", ""};
    if (distribution == "weibull") form = {{"scale", "shape"}, "", ""};
  } else {
    if (distribution == "normal") form = {{"sd"}, "cv", "shift"};
    if (distribution == "lognormal") form = {{"sigma"}, "", "median_factor"};
    if (distribution == "uniform") form = {{"half_width"}, "", "shift"};
    if (distribution == "weibull") {
      throw InputError(b.value_mark("distribution"), b.child_path("distribution"),
                       "a weibull " + input + " has no form around the design: write absolute: true with scale and "
                       "shape, or use lognormal (a factor with median 1: sigma) around the design");
    }
  }
  std::vector<std::string> params = form.required;
  if (!form.alternative.empty()) params.push_back(form.alternative);
  if (!form.optional.empty()) params.push_back(form.optional);
  for (const auto& e : item.entries) {
    if (e.key == "input" || e.key == "distribution" || e.key == "absolute") continue;
    if (std::find(params.begin(), params.end(), e.key) != params.end()) continue;
    const bool absolute_only = e.key == "mean" || e.key == "median" || e.key == "lower" || e.key == "upper" ||
                               e.key == "scale" || e.key == "shape";
    if (!out.absolute && absolute_only) {
      throw InputError(e.key_mark, b.child_path(e.key),
                       "'" + e.key + "' gives an absolute distribution, which ignores the design's own " + input +
                           ": around the design a " + distribution + " takes " + join(params) +
                           " (docs/yaml.md, reliability.random); to keep the absolute form write absolute: true");
    }
    throw InputError(e.key_mark, b.child_path(e.key),
                     "'" + e.key + "' is not a parameter of " + (out.absolute ? "an absolute " : "a ") + distribution +
                         " distribution" + (out.absolute ? "" : " around the design") + "; its parameters: " +
                         join(params));
  }

  if (out.absolute) {
    const bool second_plain = distribution == "lognormal" || distribution == "weibull";
    const QuantityKind second_kind = second_plain ? plain : unit;
    out.distribution = distribution == "normal"      ? RandomInput::Distribution::kNormal
                       : distribution == "lognormal" ? RandomInput::Distribution::kLognormal
                       : distribution == "uniform"   ? RandomInput::Distribution::kUniform
                                                     : RandomInput::Distribution::kWeibull;
    const std::string& first = form.required[0];
    const std::string& second = form.required[1];
    out.a = b.required(first, unit, distribution + " " + first);
    out.b = b.required(second, second_kind, distribution + " " + second);
    // Every random input is a positive physical quantity.
    b.check(first, unit, out.a, 0, kInf, true, true, " (" + input + " is positive)");
    if (distribution == "uniform") {
      b.check(second, second_kind, out.b, out.a, kInf, true, true, " (upper must exceed lower)");
    } else if (distribution == "lognormal") {
      // sigma of ln X above 5 spans e^10 = 2e4 between -1 and +1 sd: a typo, not a scatter.
      b.check(second, second_kind, out.b, 0, 5, true, false, " (standard deviation of ln " + input + ")");
    } else {
      b.check(second, second_kind, out.b, 0, kInf, true, true, "");
    }
    return out;
  }

  if (distribution == "normal") {
    out.distribution = RandomInput::Distribution::kNormal;
    const bool has_sd = b.has("sd"), has_cv = b.has("cv");
    if (has_sd && has_cv) {
      throw InputError(b.key_mark("cv"), b.child_path("cv"),
                       "give either sd (in the unit of " + input + ") or cv (sd / the design's value), not both");
    }
    if (has_cv) {
      out.cv = b.required("cv", plain, "coefficient of variation");
      // cv >= 1 puts a sixth of a normal load, coefficient or hardness below 0.
      b.check("cv", plain, out.cv, 0, 1, true, true, " (coefficient of variation: sd / the design's value)");
    } else {
      out.b = b.required("sd", unit, "standard deviation around the design's value, or cv");
      b.check("sd", unit, out.b, 0, kInf, true, true, "");
    }
    out.a = b.quantity("shift", unit).value_or(0.0);
  } else if (distribution == "lognormal") {
    out.distribution = RandomInput::Distribution::kLognormal;
    out.b = b.required("sigma", plain, "standard deviation of ln of the factor on the design's value");
    b.check("sigma", plain, out.b, 0, 5, true, false, " (standard deviation of ln of the factor)");
    out.a = b.quantity("median_factor", plain).value_or(1.0);
    b.check("median_factor", plain, out.a, 0, kInf, true, true, " (the factor on the design's value is positive)");
  } else {
    out.distribution = RandomInput::Distribution::kUniform;
    const double half = b.required("half_width", unit, "half the width around the design's value");
    b.check("half_width", unit, half, 0, kInf, true, true, "");
    const double shift = b.quantity("shift", unit).value_or(0.0);
    out.a = shift - half;
    out.b = shift + half;
  }
  return out;
}

}  // namespace rackopt
