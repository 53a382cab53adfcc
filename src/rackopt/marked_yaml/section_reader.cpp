#include "rackopt/marked_yaml/section_reader.hpp"

#include <cmath>
#include <stdexcept>

#include "rackopt/core/suggest.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

std::string format_in(double si, QuantityKind kind, const ReaderStyle& style) {
  if (kind == QuantityKind::kCount) return format_number(si, style.count_digits);
  return format_quantity(si, kind, {}, style.digits);
}

}  // namespace

bool ValueRange::contains(double v) const {
  const bool below = lo_open ? !(v > lo) : !(v >= lo);
  const bool above = hi_open ? !(v < hi) : !(v <= hi);
  return !below && !above;
}

std::string expected_quantity_text(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kCount: return "a whole number";
    case QuantityKind::kDimensionless: return "a plain number";
    case QuantityKind::kLength: return "a length (e.g. 60 mm)";
    case QuantityKind::kAngle: return "an angle (e.g. 20 deg)";
    case QuantityKind::kModulus: return "a modulus (e.g. 210 GPa)";
    case QuantityKind::kForce: return "a force (e.g. 50 kN)";
    case QuantityKind::kTorque: return "a torque (e.g. 453 kN*m)";
    case QuantityKind::kStiffness: return "a stiffness (e.g. 200 MN/m)";
    case QuantityKind::kArea: return "an area (e.g. 3600 mm^2)";
    case QuantityKind::kSecondMoment: return "a second moment of area (e.g. 2.15e6 mm^4)";
    case QuantityKind::kTime: return "a time (e.g. 60 yr)";
    case QuantityKind::kHardness: return "a hardness (e.g. 596 HB)";
    case QuantityKind::kRate: return "a rate (e.g. 3000 1/yr)";
    case QuantityKind::kMass: return "a mass (e.g. 120 kg)";
    case QuantityKind::kDensity: return "a density (e.g. 7850 kg/m^3)";
    case QuantityKind::kSpeed: return "a speed (e.g. 0.5 m/s, 2000 km/yr)";
    case QuantityKind::kPower: return "a power (e.g. 15 kW)";
    case QuantityKind::kInertia: return "a moment of inertia (e.g. 2.4 kg*m^2)";
    case QuantityKind::kTorsionalStiffness: return "a torsional stiffness (e.g. 5 MN*m/rad)";
  }
  return "a number";
}

std::string range_text(const std::string& name, QuantityKind kind, const ValueRange& range, const ReaderStyle& style) {
  std::string out;
  if (std::isfinite(range.lo)) out += format_in(range.lo, kind, style) + (range.lo_open ? " < " : " <= ");
  out += name;
  if (std::isfinite(range.hi)) out += std::string(range.hi_open ? " < " : " <= ") + format_in(range.hi, kind, style);
  return out;
}

void check_value_range(const SourceMark& where, const std::string& path, const std::string& name, double v,
                       QuantityKind kind, const ValueRange& range, const std::string& why, const ReaderStyle& style) {
  if (range.contains(v)) return;
  throw InputError(
      where, path,
      format_in(v, kind, style) + " is out of range; allowed: " + range_text(name, kind, range, style) + why);
}

SectionReader::SectionReader(const MarkedNode* node, std::string path, const SourceMark& fallback,
                             std::vector<std::string> allowed, ReaderStyle style, const std::string& example)
    : MarkedMap(node, std::move(path), fallback, std::move(allowed), example, style.suggest),
      style_(std::move(style)) {}

std::optional<double> SectionReader::quantity(const std::string& key, QuantityKind kind, std::string_view bare_unit,
                                              const std::string& expected) const {
  const auto text = scalar(key, expected.empty() ? expected_quantity_text(kind) : expected);
  if (!text) return std::nullopt;
  return parse_quantity(text->first, kind, text->second, child_path(key), bare_unit);
}

std::optional<double> SectionReader::quantity_in(const std::string& key, QuantityKind kind, const ValueRange& range,
                                                 const std::string& why, std::string_view bare_unit,
                                                 const std::string& expected) const {
  const auto v = quantity(key, kind, bare_unit, expected);
  if (v) check_range(key, kind, *v, range, why);
  return v;
}

std::optional<long long> SectionReader::integer(const std::string& key, const ValueRange& range) const {
  const auto text = scalar(key, expected_quantity_text(QuantityKind::kCount));
  if (!text) return std::nullopt;
  // Range-checked as a double first: 2147483648 is "out of range", not an overflow.
  const double v = parse_whole_number(text->first, text->second, child_path(key));
  check_value_range(text->second, child_path(key), key, v, QuantityKind::kCount, range, "", style_);
  return static_cast<long long>(v);
}

const NumberRule& SectionReader::rule(const std::string& key) const {
  const std::string schema_key = style_.schema_path.empty() ? key : style_.schema_path + "." + key;
  const NumberRule* r = style_.schema != nullptr ? style_.schema(schema_key) : nullptr;
  if (r == nullptr) throw std::logic_error("section reader: no rule for " + schema_key);
  return *r;
}

double SectionReader::number(const std::string& key, std::optional<double> fallback, const std::string& why) const {
  const NumberRule& r = rule(key);
  const auto v = quantity(key, r.kind);
  if (!v) {
    if (!fallback) missing(key, expected_quantity_text(r.kind));
    return *fallback;
  }
  if (r.zero_is_default && *v == 0) return *v;
  check_range(key, r.kind, *v, r.range, why.empty() && r.zero_is_default ? " (or 0 for the default)" : why);
  return *v;
}

int SectionReader::whole(const std::string& key, std::optional<int> fallback) const {
  const NumberRule& r = rule(key);
  const auto v = integer(key, r.range);
  if (!v) {
    if (!fallback) missing(key, expected_quantity_text(r.kind));
    return *fallback;
  }
  return static_cast<int>(*v);
}

std::optional<std::string> SectionReader::choice(const std::string& key,
                                                 const std::vector<std::string>& options) const {
  const auto text = scalar(key, "one of " + join(options, " | "));
  if (!text) return std::nullopt;
  const std::string wanted = lower(text->first);
  for (const auto& o : options) {
    if (wanted == lower(o)) return o;
  }
  std::string message = "'" + text->first + "' is not allowed; allowed: " + join(options, " | ");
  const NameSuggester suggest = style_.suggest != nullptr ? style_.suggest : closest_name;
  if (const auto best = suggest(text->first, options)) message += " (did you mean '" + *best + "'?)";
  throw InputError(text->second, child_path(key), message);
}

std::vector<ListValue> SectionReader::quantity_list(const std::string& key, QuantityKind kind, const ValueRange& range,
                                                    std::string_view bare_unit) const {
  std::vector<ListValue> out;
  const MarkedNode* node = get(key);
  if (node == nullptr) return out;
  const std::string path = child_path(key);
  auto add = [&](std::string_view text, const SourceMark& mark, std::string_view unit) {
    ListValue v;
    v.path = path + "[" + std::to_string(out.size()) + "]";
    v.mark = mark;
    v.si = parse_quantity(text, kind, mark, v.path, unit);
    check_value_range(mark, v.path, key, v.si, kind, range, "", style_);
    out.push_back(v);
  };
  if (node->type == MarkedNode::Type::kSequence) {
    for (const auto& item : node->items) {
      if (item.type != MarkedNode::Type::kScalar) {
        throw InputError(item.mark, path + "[" + std::to_string(out.size()) + "]",
                         "expected " + expected_quantity_text(kind) + ", found " + item.type_name());
      }
      add(item.scalar, item.mark, bare_unit);
    }
    return out;
  }
  if (node->type != MarkedNode::Type::kScalar) {
    throw InputError(node->mark, path,
                     "expected a list of values (e.g. [40 yr, 55 yr], or \"[40, 55] yr\"), found " + node->type_name());
  }
  const std::string& text = node->scalar;
  const std::size_t open = text.find('[');
  if (open == std::string::npos) {
    add(text, node->mark, bare_unit);
    return out;
  }
  const std::size_t close = text.find(']', open);
  if (close == std::string::npos || text.find_first_not_of(" \t", 0) != open) {
    throw InputError(node->mark, path, "'" + text + "' is not a list; write [40 yr, 55 yr] or \"[40, 55] yr\"");
  }
  const std::string trailing = text.substr(close + 1);
  const std::string unit = trailing.find_first_not_of(" \t") == std::string::npos ? std::string(bare_unit) : trailing;
  if (!unit.empty()) unit_factor(unit, kind, node->mark, path);  // an unknown trailing unit fails here
  const std::string inner = text.substr(open + 1, close - open - 1);
  if (inner.find_first_not_of(" \t") == std::string::npos) return out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = inner.find(',', start);
    add(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start), node->mark, unit);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

void SectionReader::check_range(const std::string& key, QuantityKind kind, double v, const ValueRange& range,
                                const std::string& why) const {
  const auto text = scalar(key, "");
  const SourceMark where = text ? text->second : key_mark(key);
  check_value_range(where, child_path(key), key, v, kind, range, why, style_);
}

void SectionReader::check_range(const std::string& key, double v, const ValueRange& range,
                                const std::string& why) const {
  check_range(key, rule(key).kind, v, range, why);
}

}  // namespace rackopt
