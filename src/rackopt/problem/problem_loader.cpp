#include "rackopt/problem/problem_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/marked_yaml/marked_map.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/random_input_keys.hpp"
#include "rackopt/problem/random_input_reader.hpp"

namespace rackopt {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kPi = 3.14159265358979323846;

// Numeric keys: kind and the static part of the allowed range, in SI.
// Ranges that depend on other keys (bore radius < root radius, clearance
// relative to the module, tooth index, tooth offset <= span) are checked in
// the code below on top of these. docs/yaml.md states the same limits.
struct KeySpec {
  const char* pattern;  // "pinion.module", "materials.*.E", "faults[].depth"
  QuantityKind kind;
  double lo;
  double hi;
  bool lo_open;  // true: value must be > lo (else >= lo)
  bool hi_open;  // true: value must be < hi (else <= hi)
  bool zero_is_default = false;  // exactly 0 is accepted too: "0 = derived from other keys"
};

// Plausibility: every physical quantity has a lower bound as well as an upper
// one, generous enough for any real drive (a watch-size module 0.05 mm to a
// ship lift's 63 mm and beyond) but far above the tiny values that would
// underflow in the model (a 1e-300 mm body has I = 0) or that show a unit was
// forgotten (E: 5e-324 Pa). docs/yaml.md states each range next to its key.
constexpr double kMinLength = 0.1e-3;  // 0.1 mm: the smallest tooth, body or face dimension
constexpr double kMinSmallLength = 1e-6;  // 1 um: spall sizes, wear depths

constexpr KeySpec kKeySpecs[] = {
    {"pinion.teeth", QuantityKind::kCount, 5, 1000, false, false},
    {"pinion.module", QuantityKind::kLength, 0.05e-3, 1.0, false, false},
    {"pinion.pressure_angle", QuantityKind::kAngle, 5 * kDeg, 45 * kDeg, false, false},
    {"pinion.face_width", QuantityKind::kLength, kMinLength, 10.0, false, false},
    {"pinion.profile_shift", QuantityKind::kDimensionless, -2, 2, false, false},
    {"pinion.addendum", QuantityKind::kDimensionless, 0.1, 3, false, false},
    {"pinion.dedendum", QuantityKind::kDimensionless, 0.1, 3, false, false},
    {"pinion.tip_radius", QuantityKind::kDimensionless, 0, 1, false, false},
    {"pinion.bore_radius", QuantityKind::kLength, kMinLength, 10.0, false, false},
    // Profile relief (docs/yaml.md): amount along the flank normal; length a
    // multiple of the module (a length with its unit is accepted too, up to 5 m_n).
    {"pinion.tip_relief.amount", QuantityKind::kLength, 0, 10e-3, false, false},
    {"pinion.tip_relief.length", QuantityKind::kDimensionless, 0.01, 5, false, false},
    {"pinion.root_relief.amount", QuantityKind::kLength, 0, 10e-3, false, false},
    {"pinion.root_relief.length", QuantityKind::kDimensionless, 0.01, 5, false, false},
    {"rack.tip_relief.amount", QuantityKind::kLength, 0, 10e-3, false, false},
    {"rack.tip_relief.length", QuantityKind::kDimensionless, 0.01, 5, false, false},
    {"rack.root_relief.amount", QuantityKind::kLength, 0, 10e-3, false, false},
    {"rack.root_relief.length", QuantityKind::kDimensionless, 0.01, 5, false, false},
    {"rack.addendum", QuantityKind::kDimensionless, 0.1, 3, false, false},
    {"rack.dedendum", QuantityKind::kDimensionless, 0.1, 3, false, false},
    {"rack.face_width", QuantityKind::kLength, kMinLength, 10.0, false, false},
    {"rack.body_height", QuantityKind::kLength, kMinLength, 10.0, false, false},
    {"rack.body_width", QuantityKind::kLength, kMinLength, 10.0, false, false},
    {"rack.section.area", QuantityKind::kArea, 1e-8, 100, false, false},
    {"rack.section.second_moment", QuantityKind::kSecondMoment, 1e-18, 1000, false, false},
    {"rack.section.shear_area", QuantityKind::kArea, 1e-8, 100, false, false},
    {"rack.section.neutral_axis_depth", QuantityKind::kLength, 0.01e-3, 10.0, false, false},
    {"rack.span", QuantityKind::kLength, 1e-3, 100.0, false, false},
    {"rack.tooth_offset", QuantityKind::kLength, 0, 100.0, false, false},
    // 0 = the cutter tip radius; a round larger than the rack space is
    // clamped by the stress model (it depends on the geometry).
    {"rack.root_radius", QuantityKind::kLength, 1e-6, 1.0, false, false, true},
    {"mounting.clearance", QuantityKind::kLength, 0, 1.0, false, false},
    // 0.1 GPa: polyethylene; 1200 GPa: diamond.
    {"materials.*.E", QuantityKind::kModulus, 0.1e9, 1200e9, false, false},
    {"materials.*.nu", QuantityKind::kDimensionless, 0, 0.5, false, true},
    // Permissible stresses: 5 GPa is several times any gear steel's (a
    // case-hardened sigma_HP is ~1.5 GPa); above it a unit was forgotten.
    {"materials.*.allowable_bending", QuantityKind::kModulus, 1e6, 5e9, false, false},
    {"materials.*.allowable_contact", QuantityKind::kModulus, 1e6, 5e9, false, false},
    // Metals and polymers lie in 900..23000 kg/m^3 (POM ~1400, steel 7850).
    {"materials.*.density", QuantityKind::kDensity, 500, 25000, false, false},
    // 1 mN (an instrument drive) .. 10 GN (ten times the largest ship lift).
    {"load.force", QuantityKind::kForce, 1e-3, 1e10, false, false},
    {"load.torque", QuantityKind::kTorque, 1e-6, 1e10, false, false},
    {"load.thrust", QuantityKind::kForce, 1e-3, 1e10, false, false},
    // 50 m/s (180 km/h) is beyond any rack drive; above it a unit was forgotten.
    {"load.speed", QuantityKind::kSpeed, 1e-6, 50, false, false},
    {"load.efficiency", QuantityKind::kDimensionless, 0.05, 1, false, false},
    // ISO 6336 load factors are >= 1 by definition (1 = no extra load);
    // above 10 the simplified method is meaningless.
    {"load.application_factor", QuantityKind::kDimensionless, 1, 10, false, false},
    {"load.dynamic_factor", QuantityKind::kDimensionless, 1, 10, false, false},
    {"load.face_load_factor", QuantityKind::kDimensionless, 1, 10, false, false},
    {"load.face_load_factor_bending", QuantityKind::kDimensionless, 1, 10, false, false},
    {"load.transverse_load_factor", QuantityKind::kDimensionless, 1, 10, false, false},
    {"faults[].tooth", QuantityKind::kCount, 0, 1e9, false, false},
    {"faults[].start", QuantityKind::kLength, 0, 10.0, false, false},
    {"faults[].length", QuantityKind::kLength, kMinSmallLength, 10.0, false, false},
    {"faults[].width", QuantityKind::kLength, kMinSmallLength, 10.0, false, false},
    {"faults[].depth", QuantityKind::kLength, kMinSmallLength, 1.0, false, false},
    {"numerics.quadrature_order", QuantityKind::kCount, 2, 64, false, false},
    {"numerics.positions_per_period", QuantityKind::kCount, 4, 10000, false, false},
    // Wear (docs/models/wear.md). Archard K spans mild wear ~1e-8 to severe
    // ~1e-2 (10.4); 1e-20..1 leaves room for any reading of a paper's k.
    {"wear.coefficient", QuantityKind::kDimensionless, 1e-20, 1, false, false},
    {"wear.max_depth", QuantityKind::kLength, kMinSmallLength, 1.0, false, false},
    // Below 1 the drive loses continuous contact whatever the wear: the
    // allowable contact ratio of the wear paper's criterion is at least 1.
    {"wear.min_contact_ratio", QuantityKind::kDimensionless, 1, 5, false, false},
    {"wear.profile_points", QuantityKind::kCount, 5, 2000, false, false},
    {"wear.block_fraction", QuantityKind::kDimensionless, 1e-6, 0.5, false, false},
    // One schema for wear.hardness, wear.pinion_hardness, wear.rack_hardness.
    // 2000 HB is far above any steel (a file-hard surface is ~ 700 HB).
    // 1 HB is far below any engineering polymer's indentation hardness.
    {"wear.hardness.surface", QuantityKind::kHardness, 1 * kPaPerHB, 2000 * kPaPerHB, false, false},
    {"wear.hardness.core", QuantityKind::kHardness, 1 * kPaPerHB, 2000 * kPaPerHB, false, false},
    {"wear.hardness.limit", QuantityKind::kHardness, 1 * kPaPerHB, 2000 * kPaPerHB, false, false},
    {"wear.hardness.case_depth", QuantityKind::kLength, 0.01e-3, 1.0, false, false},
    {"wear.hardness.exponent", QuantityKind::kDimensionless, 0.5, 20, false, false},
    {"wear.hardness.valid_depth", QuantityKind::kLength, 0.01e-3, 1.0, false, false},
    {"wear.hardness.depths[]", QuantityKind::kLength, 0, 1.0, false, false},
    {"wear.hardness.values[]", QuantityKind::kHardness, 1 * kPaPerHB, 2000 * kPaPerHB, false, false},
    // 1e-3/yr (once a millennium) .. 1e12/yr (30 kHz day and night).
    {"duty.rack_meshes_per_year", QuantityKind::kRate, 1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false},
    {"duty.pinion_meshes_per_year", QuantityKind::kRate, 1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false,
     true},
    // 1e9 m/yr is a drive running day and night at 30 m/s; a bare number is m/s.
    {"duty.travel_per_year", QuantityKind::kSpeed, 1.0 / kSecondsPerYear, 1e9 / kSecondsPerYear, false, false},
    {"duty.strokes_per_year", QuantityKind::kRate, 1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false},
    {"duty.stroke", QuantityKind::kLength, 1e-3, 1e5, false, false},
    {"reliability.samples", QuantityKind::kCount, 1, kMaxReliabilitySamples, false, false},
    {"reliability.seed", QuantityKind::kCount, 0, 2e9, false, false},
    {"reliability.ks_level", QuantityKind::kDimensionless, 0.001, 0.5, false, false},
    {"reliability.bootstrap_replicates", QuantityKind::kCount, 20, 100000, false, false},
    {"reliability.life_table_tolerance", QuantityKind::kDimensionless, 1e-6, 0.05, false, false},
    {"reliability.R[]", QuantityKind::kDimensionless, 0, 1, true, true},
    // 1e-6 yr (32 s) .. a million years.
    {"reliability.times[]", QuantityKind::kTime, 1e-6 * kSecondsPerYear, 1e6 * kSecondsPerYear, false, false},
};

const KeySpec* find_spec(std::string_view pattern) {
  for (const auto& s : kKeySpecs) {
    if (pattern == s.pattern) return &s;
  }
  return nullptr;
}

std::string format_in_kind(double si, QuantityKind kind) {
  if (kind == QuantityKind::kCount) return format_number(si, 10);
  return format_quantity(si, kind);
}

// "5 deg <= pressure_angle <= 45 deg", "pinion.face_width > 0 mm".
std::string range_text(const std::string& name, QuantityKind kind, double lo, double hi, bool lo_open,
                       bool hi_open) {
  std::string out;
  if (std::isfinite(lo)) out += format_in_kind(lo, kind) + (lo_open ? " < " : " <= ");
  out += name;
  if (std::isfinite(hi)) out += std::string(hi_open ? " < " : " <= ") + format_in_kind(hi, kind);
  return out;
}

// Throws when v is outside the range; `name` is the key as the range text
// shows it, `why` explains a derived limit.
void check_value_range(const SourceMark& where, const std::string& path, const std::string& name, double v,
                       QuantityKind kind, double lo, double hi, bool lo_open, bool hi_open, const std::string& why) {
  const bool below = lo_open ? !(v > lo) : !(v >= lo);
  const bool above = hi_open ? !(v < hi) : !(v <= hi);
  if (!below && !above) return;
  throw InputError(where, path,
                   format_in_kind(v, kind) + " is out of range; allowed: " +
                       range_text(name, kind, lo, hi, lo_open, hi_open) + why);
}

// One map of the problem (a section such as `pinion`, one material, one
// fault). Rejects unknown keys on construction; reads typed values with
// defaults and ranges; reports missing keys at the map's own mark.
class Block : public MarkedMap {
 public:
  // `node` may be nullptr or null (section absent or empty): then every key
  // is absent and errors point at `fallback` (the parent's mark).
  Block(const MarkedNode* node, std::string path, std::string pattern, const SourceMark& fallback,
        std::vector<std::string> allowed)
      : MarkedMap(node, std::move(path), fallback, std::move(allowed)), pattern_(std::move(pattern)) {}

  const KeySpec& spec(const std::string& key) const {
    const KeySpec* s = find_spec(pattern_.empty() ? key : pattern_ + "." + key);
    if (s == nullptr) throw std::logic_error("problem loader: no KeySpec for " + pattern_ + "." + key);
    return *s;
  }

  static std::string expected_text(QuantityKind kind) {
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
    }
    return "a number";
  }

  // A number of the key's kind, in SI, checked against the KeySpec range;
  // `why` is appended to a range error.
  double number(const std::string& key, std::optional<double> fallback, const std::string& why = "") const {
    const KeySpec& s = spec(key);
    const auto text = scalar(key, expected_text(s.kind));
    if (!text) {
      if (!fallback) missing(key, expected_text(s.kind));
      return *fallback;
    }
    const double v = parse_quantity(text->first, s.kind, text->second, child_path(key));
    if (s.zero_is_default && v == 0) return v;
    check_range(key, v, s.lo, s.hi, s.lo_open, s.hi_open,
                why.empty() && s.zero_is_default ? " (or 0 for the default)" : why);
    return v;
  }

  int count(const std::string& key, std::optional<int> fallback) const {
    const KeySpec& s = spec(key);
    const auto text = scalar(key, expected_text(s.kind));
    if (!text) {
      if (!fallback) missing(key, expected_text(s.kind));
      return *fallback;
    }
    // Range-checked as a double first: 2147483648 is "out of range", not an overflow.
    const double v = parse_whole_number(text->first, text->second, child_path(key));
    check_range(key, v, s.lo, s.hi, s.lo_open, s.hi_open, "");
    return static_cast<int>(v);
  }

  // Throws when v is outside the range; `why` explains a derived limit.
  void check_range(const std::string& key, double v, double lo, double hi, bool lo_open, bool hi_open,
                   const std::string& why) const {
    check_range_as(key, spec(key).kind, v, lo, hi, lo_open, hi_open, why);
  }

  // Same for a key without KeySpec (its kind decided by another key).
  void check_range_as(const std::string& key, QuantityKind kind, double v, double lo, double hi, bool lo_open,
                      bool hi_open, const std::string& why) const {
    const auto text = scalar(key, "");
    const SourceMark where = text ? text->second : key_mark(key);
    check_value_range(where, child_path(key), key, v, kind, lo, hi, lo_open, hi_open, why);
  }

  // A number of `kind` in SI without KeySpec or range; nullopt when absent.
  std::optional<double> quantity(const std::string& key, QuantityKind kind, std::string_view bare_unit = {}) const {
    const auto text = scalar(key, expected_text(kind));
    if (!text) return std::nullopt;
    return parse_quantity(text->first, kind, text->second, child_path(key), bare_unit);
  }

  std::string choice(const std::string& key, const std::vector<std::string>& options, const std::string& fallback) const {
    const auto text = scalar(key, "one of " + join(options, " | "));
    if (!text) return fallback;
    for (const auto& o : options) {
      if (text->first == o) return o;
    }
    throw InputError(text->second, child_path(key), "'" + text->first + "' is not allowed; allowed: " + join(options, " | "));
  }

 private:
  std::string pattern_;
};

const std::vector<std::string> kTopKeys = {"name",      "description", "variant", "variants",  "pinion",
                                           "rack",      "mounting",    "materials", "load",    "effects",
                                           "faults",    "numerics",    "wear",      "duty",    "reliability"};

Material find_material(const std::map<std::string, Material>& materials, const Block& block, const std::string& key) {
  const auto name = block.scalar(key, "a material name");
  const std::string wanted = name ? name->first : "steel";
  const auto it = materials.find(wanted);
  if (it != materials.end()) return it->second;
  std::vector<std::string> names;
  for (const auto& [n, m] : materials) names.push_back(n);
  throw InputError(name ? name->second : block.mark(), block.child_path(key),
                   "unknown material '" + wanted + "'; defined: " + join(names) +
                       " (add it under materials: {" + wanted + ": {E: ..., nu: ...}})");
}

// A tip or root relief of one member; `pattern` is the KeySpec path of the
// relief map ("pinion.tip_relief"). Absent: no relief.
ProfileRelief read_relief(const Block& member, const std::string& key, const std::string& pattern, double module) {
  ProfileRelief out;
  if (!member.has(key)) return out;
  const Block b(member.get(key), member.child_path(key), pattern, member.key_mark(key), {"amount", "length", "shape"});
  out.amount = b.number("amount", std::nullopt);
  b.check_range("amount", out.amount, 0, 0.1 * module, false, false,
                " (a tenth of the module; reliefs are tens of micrometres: write e.g. 20 um)");
  if (const auto text = b.scalar("length", "a multiple of the module (e.g. 0.3) or a length (e.g. 8 mm)")) {
    // A bare number is a multiple of the module, a number with a unit a length.
    double coef = 0;
    try {
      coef = parse_quantity(text->first, QuantityKind::kDimensionless, text->second, b.child_path("length"));
    } catch (const InputError&) {
      coef = parse_quantity(text->first, QuantityKind::kLength, text->second, b.child_path("length")) / module;
    }
    b.check_range("length", coef, 0, 5, true, false, " (multiples of the module, 5 m = " +
                                                         format_length_mm(5 * module) + ")");
    out.length = coef * module;
  } else if (out.amount > 0) {
    b.missing("length", "the relief length along the line of action: a multiple of the module (e.g. 0.3) or a "
                        "length (e.g. 8 mm)");
  }
  out.shape = b.choice("shape", {"linear", "parabolic"}, "linear") == "parabolic" ? ProfileRelief::Shape::kParabolic
                                                                                  : ProfileRelief::Shape::kLinear;
  return out;
}

// ------------------------------------------------------------ wear, duty, reliability

// One value of a list key, with where it was written.
struct ListValue {
  double si = 0;
  SourceMark mark;
  std::string path;  // "reliability.times[2]"
};

// Reads `key` of `block` as a list of `kind` quantities, written either as a
// YAML list ([40 yr, 55 yr] or [40, 55]) or, because YAML cannot put a unit
// after a flow list, as one text "[40, 55, 60] yr" whose trailing unit applies
// to every bare number. A bare item means `bare_unit` (empty: the kind's
// default). A single value is a list of one. Each item is range-checked
// against the KeySpec `pattern` ("reliability.times[]"). Empty when absent.
std::vector<ListValue> quantity_list(const Block& block, const std::string& key, const std::string& pattern,
                                     std::string_view bare_unit = {}) {
  std::vector<ListValue> out;
  const MarkedNode* node = block.get(key);
  if (node == nullptr) return out;
  const KeySpec* spec = find_spec(pattern);
  if (spec == nullptr) throw std::logic_error("problem loader: no KeySpec for " + pattern);
  const std::string path = block.child_path(key);
  auto add = [&](std::string_view text, const SourceMark& mark, std::string_view unit) {
    ListValue v;
    v.path = path + "[" + std::to_string(out.size()) + "]";
    v.mark = mark;
    v.si = parse_quantity(text, spec->kind, mark, v.path, unit);
    check_value_range(mark, v.path, key, v.si, spec->kind, spec->lo, spec->hi, spec->lo_open, spec->hi_open, "");
    out.push_back(v);
  };
  if (node->type == MarkedNode::Type::kSequence) {
    for (const auto& item : node->items) {
      if (item.type != MarkedNode::Type::kScalar) {
        throw InputError(item.mark, path + "[" + std::to_string(out.size()) + "]",
                         "expected " + Block::expected_text(spec->kind) + ", found " + item.type_name());
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
  if (!unit.empty()) unit_factor(unit, spec->kind, node->mark, path);  // an unknown trailing unit fails here
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

const char* const kHardnessKinds = "constant | polynomial | table | case_hardened";

// Evaluates sum c_i h^i (Horner).
double polynomial_value(const std::vector<double>& c, double h) {
  double v = 0;
  for (std::size_t i = c.size(); i-- > 0;) v = v * h + c[i];
  return v;
}

// A hardness profile map (or a single hardness: constant profile) at `path`.
// Every profile comes out complete: surface = H(0), core filled (measured
// data: the value at its deepest point unless given; constant: the surface),
// limit filled (case_hardened: 0.8 surface unless given).
HardnessProfile read_hardness(const MarkedNode& node, const std::string& path) {
  HardnessProfile h;
  const KeySpec& surface_spec = *find_spec("wear.hardness.surface");
  if (node.type == MarkedNode::Type::kScalar) {
    h.kind = HardnessProfile::Kind::kConstant;
    h.surface = parse_quantity(node.scalar, QuantityKind::kHardness, node.mark, path);
    check_value_range(node.mark, path, "hardness", h.surface, QuantityKind::kHardness, surface_spec.lo,
                      surface_spec.hi, surface_spec.lo_open, surface_spec.hi_open, "");
    h.core = h.surface;
    return h;
  }
  if (!node.is_map()) {
    throw InputError(node.mark, path,
                     std::string("expected a hardness (e.g. 596 HB: a constant profile) or a profile map {kind: ") +
                         kHardnessKinds + ", ...}, found " + node.type_name());
  }
  const std::vector<std::string> all = {"kind",        "surface", "core",     "limit",     "case_depth",
                                        "exponent",    "coefficients", "valid_depth", "depths", "values",
                                        "depth_unit",  "hardness_unit"};
  const Block b(&node, path, "wear.hardness", node.mark, all);
  if (!b.has("kind")) {
    b.missing("kind", std::string("the profile kind: ") + kHardnessKinds +
                          " (or write a single hardness such as 596 HB for a constant profile)");
  }
  const std::string kind = b.choice("kind", {"constant", "polynomial", "table", "case_hardened"}, "constant");
  std::vector<std::string> own;
  if (kind == "constant") own = {"kind", "surface"};
  if (kind == "polynomial") own = {"kind", "coefficients", "depth_unit", "hardness_unit", "valid_depth", "core"};
  if (kind == "table") own = {"kind", "depths", "values", "depth_unit", "hardness_unit", "core"};
  if (kind == "case_hardened") own = {"kind", "surface", "core", "case_depth", "limit", "exponent"};
  for (const auto& e : node.entries) {
    if (std::find(own.begin(), own.end(), e.key) == own.end()) {
      throw InputError(e.key_mark, b.child_path(e.key),
                       "key '" + e.key + "' does not belong to a '" + kind + "' hardness profile; its keys: " +
                           join(own));
    }
  }
  // Units of bare numbers in measured data (lists and polynomial coefficients).
  std::string depth_unit = std::string(default_unit(QuantityKind::kLength));
  std::string hardness_unit = std::string(default_unit(QuantityKind::kHardness));
  double depth_factor = 1e-3;
  double hardness_factor = kPaPerHB;
  if (const auto t = b.scalar("depth_unit", "a length unit (e.g. mm)")) {
    depth_factor = unit_factor(t->first, QuantityKind::kLength, t->second, b.child_path("depth_unit"));
    depth_unit = t->first;
  }
  if (const auto t = b.scalar("hardness_unit", "a hardness unit (e.g. HB)")) {
    hardness_factor = unit_factor(t->first, QuantityKind::kHardness, t->second, b.child_path("hardness_unit"));
    hardness_unit = t->first;
  }

  if (kind == "constant") {
    h.kind = HardnessProfile::Kind::kConstant;
    h.surface = b.number("surface", std::nullopt);
    h.core = h.surface;
  } else if (kind == "polynomial") {
    h.kind = HardnessProfile::Kind::kPolynomial;
    const MarkedNode* list = b.get("coefficients");
    if (list == nullptr) {
      b.missing("coefficients", "the fit's coefficients in ascending powers of depth, e.g. [596, 2, -1.6786, -0.25] "
                                "(units from depth_unit and hardness_unit)");
    }
    if (list->type != MarkedNode::Type::kSequence || list->items.empty() || list->items.size() > 12) {
      throw InputError(list->mark, b.child_path("coefficients"),
                       "expected a list of 1 to 12 plain numbers c0, c1, ... (H = c0 + c1 h + c2 h^2 + ..., in " +
                           hardness_unit + " with h in " + depth_unit + "), found " +
                           (list->type == MarkedNode::Type::kSequence
                                ? std::to_string(list->items.size()) + " items"
                                : list->type_name()));
    }
    // c_i [Pa / m^i] = c_i [unit_H / unit_h^i] * unit_H[Pa] / unit_h[m]^i.
    double per_depth_power = 1.0;
    for (std::size_t i = 0; i < list->items.size(); ++i) {
      const MarkedNode& item = list->items[i];
      const std::string item_path = b.child_path("coefficients") + "[" + std::to_string(i) + "]";
      if (item.type != MarkedNode::Type::kScalar) {
        throw InputError(item.mark, item_path, "expected a plain number, found " + item.type_name());
      }
      double c = 0;
      try {
        c = parse_quantity(item.scalar, QuantityKind::kDimensionless, item.mark, item_path);
      } catch (const InputError& e) {
        throw InputError(e.mark(), e.key_path(),
                         e.message() + " (coefficients are plain numbers; their units are set once by depth_unit, "
                                       "default mm, and hardness_unit, default HB)");
      }
      h.coefficients.push_back(c * hardness_factor / per_depth_power);
      per_depth_power *= depth_factor;
    }
    h.valid_depth = b.number("valid_depth", std::nullopt);
    h.surface = h.coefficients.front();
    if (!(h.surface > 0)) {
      throw InputError(list->items.front().mark, b.child_path("coefficients") + "[0]",
                       "c0 is the surface hardness H(0) and must be > 0");
    }
    // A measured fit must stay positive where it is used: look for H <= 0 on
    // a fine grid of [0, valid_depth] (a cubic has at most 2 extrema, so a
    // dip between 1000 samples would be narrower than 0.1 % of the range).
    constexpr int kChecks = 1000;
    for (int k = 0; k <= kChecks; ++k) {
      const double depth = h.valid_depth * k / kChecks;
      const double value = polynomial_value(h.coefficients, depth);
      if (!(value > 0)) {
        b.check_range("valid_depth", h.valid_depth, 0, depth, true, true,
                      " (the polynomial gives H = " + format_quantity(value, QuantityKind::kHardness) +
                          " at h = " + format_length_mm(depth) + "; a measured fit must stay positive over its range)");
      }
    }
    h.core = b.has("core") ? b.number("core", std::nullopt) : polynomial_value(h.coefficients, h.valid_depth);
  } else if (kind == "table") {
    h.kind = HardnessProfile::Kind::kTable;
    if (!b.has("depths")) b.missing("depths", "the measured depths, e.g. [0, 1, 2, 4] mm, ascending");
    if (!b.has("values")) b.missing("values", "the measured hardness at each depth, e.g. [596, 590, 560, 480] HB");
    const std::vector<ListValue> depths = quantity_list(b, "depths", "wear.hardness.depths[]", depth_unit);
    const std::vector<ListValue> values = quantity_list(b, "values", "wear.hardness.values[]", hardness_unit);
    if (depths.size() < 2) {
      throw InputError(b.get("depths")->mark, b.child_path("depths"),
                       "a table needs at least 2 points (one value is a constant profile: kind: constant)");
    }
    if (values.size() != depths.size()) {
      throw InputError(b.get("values")->mark, b.child_path("values"),
                       "values has " + std::to_string(values.size()) + " items but depths has " +
                           std::to_string(depths.size()) + "; give one hardness per depth");
    }
    for (std::size_t i = 0; i < depths.size(); ++i) {
      if (i > 0 && !(depths[i].si > depths[i - 1].si)) {
        throw InputError(depths[i].mark, depths[i].path,
                         "depths must be strictly ascending; " + format_length_mm(depths[i].si) + " follows " +
                             format_length_mm(depths[i - 1].si));
      }
      h.depths.push_back(depths[i].si);
      h.values.push_back(values[i].si);
    }
    h.surface = h.values.front();
    h.core = b.has("core") ? b.number("core", std::nullopt) : h.values.back();
  } else {
    h.kind = HardnessProfile::Kind::kCaseHardened;
    h.surface = b.number("surface", std::nullopt);
    h.core = b.number("core", std::nullopt);
    h.case_depth = b.number("case_depth", std::nullopt);
    h.exponent = b.number("exponent", 3.0);
    // docs/models/wear.md: delta = D / ln((Hs - Hc)/(Hlim - Hc))^(1/n) needs Hc < Hlim < Hs.
    b.check_range("core", h.core, 0, h.surface, true, true,
                  " (below the surface hardness " + format_quantity(h.surface, QuantityKind::kHardness) +
                      ": a case-hardened profile drops from surface to core)");
    h.limit = b.number("limit", 0.8 * h.surface);
    if (!(h.limit > h.core && h.limit < h.surface)) {
      const std::string why = " (the hardness at the case depth lies between core and surface" +
                              std::string(b.has("limit") ? ")" : "; the default limit is 0.8 x surface, ISO 18203 SHD)");
      if (b.has("limit")) {
        b.check_range("limit", h.limit, h.core, h.surface, true, true, why);
      }
      b.check_range("core", h.core, 0, h.limit, true, true, why);
    }
  }
  return h;
}

// wear: absent = not configured (coefficient 0); present = coefficient and a
// hardness for both members are required.
void read_wear(const Block& top, Drive& drive) {
  const MarkedNode* node = top.get("wear");
  if (node == nullptr) return;
  const Block w(node, "wear", "wear", top.key_mark("wear"),
                {"coefficient", "max_depth", "min_contact_ratio", "stop_at_case_depth", "update_profile",
                 "profile_points", "block_fraction", "hardness", "pinion_hardness", "rack_hardness"});
  WearSpec& wear = drive.wear;
  const WearSpec defaults;
  wear.coefficient = w.number("coefficient", std::nullopt);
  wear.max_depth = w.number("max_depth", defaults.max_depth);
  // Deeper than half the tooth thickness at the pitch line (pi m / 4) the
  // tooth is gone before the limit is reached.
  const double quarter_pitch = 0.25 * kPi * drive.pinion.module;
  w.check_range("max_depth", wear.max_depth, 0, quarter_pitch, true, false,
                " (half the tooth thickness at the pitch line, pi m / 4 = " + format_length_mm(quarter_pitch) + ")");
  wear.min_contact_ratio = w.number("min_contact_ratio", defaults.min_contact_ratio);
  wear.stop_at_case_depth = w.flag("stop_at_case_depth", defaults.stop_at_case_depth);
  wear.update_profile = w.flag("update_profile", defaults.update_profile);
  wear.profile_points = w.count("profile_points", defaults.profile_points);
  wear.block_fraction = w.number("block_fraction", defaults.block_fraction);

  const MarkedNode* both = w.get("hardness");
  const MarkedNode* pinion = w.get("pinion_hardness");
  const MarkedNode* rack = w.get("rack_hardness");
  if (both == nullptr && (pinion == nullptr || rack == nullptr)) {
    w.missing(pinion == nullptr ? (rack == nullptr ? "hardness" : "pinion_hardness") : "rack_hardness",
              "a hardness profile for both members: wear.hardness (both), or wear.pinion_hardness and "
              "wear.rack_hardness, e.g. {kind: constant, surface: 596 HB}");
  }
  if (both != nullptr) {
    wear.pinion_hardness = read_hardness(*both, "wear.hardness");
    wear.rack_hardness = wear.pinion_hardness;
  }
  if (pinion != nullptr) wear.pinion_hardness = read_hardness(*pinion, "wear.pinion_hardness");
  if (rack != nullptr) wear.rack_hardness = read_hardness(*rack, "wear.rack_hardness");
  if (wear.stop_at_case_depth && wear.pinion_hardness.kind != HardnessProfile::Kind::kCaseHardened &&
      wear.rack_hardness.kind != HardnessProfile::Kind::kCaseHardened) {
    const auto t = w.scalar("stop_at_case_depth", "");
    throw InputError(t ? t->second : w.mark(), "wear.stop_at_case_depth",
                     "needs a case_hardened hardness profile (kind: case_hardened, with case_depth) on the pinion "
                     "or the rack; measured profiles have no case depth");
  }
}

void read_duty(const Block& top, Drive& drive) {
  const Block d(top.get("duty"), "duty", "duty", top.key_mark("duty"),
                {"rack_meshes_per_year", "pinion_meshes_per_year", "travel_per_year", "strokes_per_year", "stroke"});
  if (d.node() == nullptr) return;  // no duty: lives in cycles only
  Duty& duty = drive.duty;
  const bool as_counts = d.has("rack_meshes_per_year");
  const bool as_travel = d.has("travel_per_year") || d.has("strokes_per_year") || d.has("stroke");
  if (as_counts && as_travel) {
    const std::string other = d.has("stroke") ? "stroke" : d.has("travel_per_year") ? "travel_per_year" : "strokes_per_year";
    throw InputError(d.key_mark(other), "duty." + other,
                     "give the duty either as mesh counts (duty.rack_meshes_per_year) or as travel (duty.stroke with "
                     "duty.travel_per_year or duty.strokes_per_year), not both: duty.rack_meshes_per_year is also given");
  }
  // The rate kind is SI (1/s) like every value; the Drive keeps per year.
  if (!as_travel) {
    duty.rack_meshes_per_year = d.number("rack_meshes_per_year", std::nullopt) * kSecondsPerYear;
    const double pinion = d.number("pinion_meshes_per_year", 0.0) * kSecondsPerYear;
    duty.pinion_meshes_per_year = pinion > 0 ? pinion : duty.rack_meshes_per_year;
    return;
  }
  if (d.has("pinion_meshes_per_year")) {
    throw InputError(d.key_mark("pinion_meshes_per_year"), "duty.pinion_meshes_per_year",
                     "with the duty given as travel the pinion's mesh count follows from it (travel / (pi m z)); "
                     "remove duty.pinion_meshes_per_year");
  }
  if (d.has("travel_per_year") && d.has("strokes_per_year")) {
    throw InputError(d.key_mark("strokes_per_year"), "duty.strokes_per_year",
                     "give duty.travel_per_year or duty.strokes_per_year, not both (travel = strokes x stroke)");
  }
  if (!d.has("travel_per_year") && !d.has("strokes_per_year")) {
    d.missing("travel_per_year", "duty.travel_per_year (e.g. 2000 km/yr) or duty.strokes_per_year (e.g. 5000 1/yr)");
  }
  duty.stroke = d.number("stroke", std::nullopt);
  duty.travel_per_year = d.has("travel_per_year")
                             ? d.number("travel_per_year", std::nullopt) * kSecondsPerYear
                             : d.number("strokes_per_year", std::nullopt) * kSecondsPerYear * duty.stroke;
  duty.rack_meshes_per_year = duty.travel_per_year / duty.stroke;
  duty.pinion_meshes_per_year = duty.travel_per_year / (kPi * drive.pinion.module * drive.pinion.teeth);
}

void read_reliability(const Block& top, Drive& drive) {
  const Block r(top.get("reliability"), "reliability", "reliability", top.key_mark("reliability"),
                {"samples", "seed", "sampling", "R", "times", "ks_level", "bootstrap_replicates", "life_table",
                 "life_table_tolerance", "random"});
  ReliabilitySpec& rel = drive.reliability;
  const ReliabilitySpec defaults;
  rel.samples = r.count("samples", defaults.samples);
  rel.seed = static_cast<unsigned long>(r.count("seed", static_cast<int>(defaults.seed)));
  rel.sobol = r.choice("sampling", {"pseudo", "sobol"}, defaults.sobol ? "sobol" : "pseudo") == "sobol";
  for (const auto& v : quantity_list(r, "R", "reliability.R[]")) rel.reliabilities.push_back(v.si);
  for (const auto& v : quantity_list(r, "times", "reliability.times[]")) rel.times.push_back(v.si);
  rel.ks_level = r.number("ks_level", defaults.ks_level);
  rel.bootstrap_replicates = r.count("bootstrap_replicates", defaults.bootstrap_replicates);
  rel.life_table = r.flag("life_table", defaults.life_table);
  rel.life_table_tolerance = r.number("life_table_tolerance", defaults.life_table_tolerance);
  const MarkedNode* random = r.get("random");
  if (random == nullptr) return;
  if (random->type != MarkedNode::Type::kSequence) {
    throw InputError(random->mark, "reliability.random",
                     "expected a list of random inputs (- {input: contact_ratio, distribution: normal, sd: 0.02}), "
                     "found " + random->type_name());
  }
  for (std::size_t i = 0; i < random->items.size(); ++i) {
    const std::string path = "reliability.random[" + std::to_string(i) + "]";
    RandomInput input = read_random_input(random->items[i], path);
    for (std::size_t j = 0; j < rel.inputs.size(); ++j) {
      if (rel.inputs[j].key == input.key) {
        const MarkedNode* written = random->items[i].find("input");
        throw InputError(written->mark, path + ".input",
                         "'" + written->scalar + "' is already random in reliability.random[" + std::to_string(j) +
                             "]; each input may appear once");
      }
    }
    rel.inputs.push_back(input);
  }
}

// The whole schema: a validated tree (overrides and variant already merged)
// to a Drive.
Drive build_drive(const MarkedNode& root, const std::string& file) {
  if (!root.is_null() && !root.is_map()) {
    throw InputError(root.mark, "",
                     "a problem file is a map of sections (pinion, rack, load, ...), found " + root.type_name());
  }
  const SourceMark top_mark = root.is_null() ? SourceMark{file, 1, 1} : root.mark;
  const Block top(&root, "", "", top_mark, kTopKeys);
  Drive drive;
  drive.source_file = file;
  {
    std::string stem = file;
    const std::size_t slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    const std::size_t dot = stem.rfind('.');
    if (dot != std::string::npos && dot > 0) stem = stem.substr(0, dot);
    drive.name = top.text("name", stem);
  }
  top.text("description", "");  // checked to be text; the Drive has no field for it

  // --- materials: built-in steel, then the file's (which may redefine steel)
  std::map<std::string, Material> materials;
  materials["steel"] = Material{"steel", 210e9, 0.3};
  {
    const Block block(top.get("materials"), "materials", "materials", top.key_mark("materials"), {});
    if (block.node() != nullptr) {
      for (const auto& e : block.node()->entries) {
        const Block m(&e.value, "materials." + e.key, "materials.*", e.key_mark,
                      {"E", "nu", "allowable_bending", "allowable_contact", "density"});
        if (m.node() == nullptr) {
          throw InputError(e.key_mark, m.path(), "a material needs E (modulus) and nu (Poisson's ratio)");
        }
        Material material;
        material.name = e.key;
        material.youngs_modulus = m.number("E", std::nullopt);
        material.poisson_ratio = m.number("nu", std::nullopt);
        // A bare number is GPa (the modulus kind): "430" would be 430 GPa.
        const std::string hint = " (a permissible stress; a bare number means GPa: write e.g. 430 MPa)";
        material.allowable_bending = m.number("allowable_bending", 0.0, hint);
        material.allowable_contact = m.number("allowable_contact", 0.0, hint);
        material.density = m.number("density", material.density);
        materials[e.key] = material;
      }
    }
  }

  // --- pinion
  const Block p(top.get("pinion"), "pinion", "pinion", top.mark(),
                {"teeth", "module", "pressure_angle", "face_width", "profile_shift", "addendum", "dedendum",
                 "tip_radius", "bore_radius", "material", "tip_relief", "root_relief"});
  PinionSpec& pin = drive.pinion;
  pin.teeth = p.count("teeth", std::nullopt);
  pin.module = p.number("module", std::nullopt);
  pin.pressure_angle = p.number("pressure_angle", 20 * kDeg);
  pin.face_width = p.number("face_width", std::nullopt);
  pin.profile_shift = p.number("profile_shift", 0.0);
  pin.addendum_coef = p.number("addendum", 1.0);
  pin.dedendum_coef = p.number("dedendum", 1.25);
  pin.tip_radius_coef = p.number("tip_radius", 0.38);
  const double root_radius = pin.module * (0.5 * pin.teeth - pin.dedendum_coef + pin.profile_shift);
  if (p.has("bore_radius")) {
    pin.bore_radius = p.number("bore_radius", std::nullopt);
    if (root_radius > 0) {
      p.check_range("bore_radius", pin.bore_radius, 0, root_radius, true, true,
                    " (the root radius r_f = m (z/2 - dedendum + profile_shift) = " + format_length_mm(root_radius) +
                        ")");
    }
  } else {
    // Half the root radius: h_f = r_f/r_int = 2, inside the range Sainsot's
    // fillet-foundation fit was made for (about 1.4..7, docs/models/tooth.md).
    pin.bore_radius = root_radius > 0 ? 0.5 * root_radius : 0.0;
  }
  pin.material = find_material(materials, p, "material");
  pin.tip_relief = read_relief(p, "tip_relief", "pinion.tip_relief", pin.module);
  pin.root_relief = read_relief(p, "root_relief", "pinion.root_relief", pin.module);

  // --- rack
  const Block r(top.get("rack"), "rack", "rack", top.mark(),
                {"addendum", "dedendum", "face_width", "body_height", "body_width", "section", "span", "supports",
                 "tooth_offset", "root_radius", "material", "tip_relief", "root_relief"});
  RackSpec& rack = drive.rack;
  rack.addendum_coef = r.number("addendum", 1.0);
  rack.dedendum_coef = r.number("dedendum", 1.25);
  rack.face_width = r.number("face_width", pin.face_width);
  const bool has_height = r.has("body_height");
  const bool has_section = r.has("section");
  if (has_height && has_section) {
    throw InputError(r.key_mark("section"), "rack.section",
                     "give either rack.body_height (rectangular body) or rack.section (explicit properties), not both");
  }
  if (!has_height && !has_section) {
    r.missing("body_height", "the rack body: rack.body_height (rectangular body, e.g. 75 mm) or rack.section "
                             "{area, second_moment, shear_area, neutral_axis_depth}");
  }
  if (has_height) {
    rack.body_height = r.number("body_height", std::nullopt);
    rack.body_width = r.number("body_width", rack.face_width);
    rack.section = rectangular_rack_section(rack.body_width, rack.body_height);
  } else {
    if (r.has("body_width")) {
      throw InputError(r.key_mark("body_width"), "rack.body_width",
                       "rack.body_width belongs to a rectangular body (rack.body_height); with rack.section give "
                       "the section properties only");
    }
    const Block s(r.get("section"), "rack.section", "rack.section", r.key_mark("section"),
                  {"area", "second_moment", "shear_area", "neutral_axis_depth"});
    rack.body_height = 0.0;
    rack.body_width = 0.0;
    rack.section.area = s.number("area", std::nullopt);
    rack.section.second_moment = s.number("second_moment", std::nullopt);
    rack.section.shear_area = s.number("shear_area", rack.section.area / 1.2);
    s.check_range("shear_area", rack.section.shear_area, 0, rack.section.area, true, false,
                  " (the shear area kappa*A cannot exceed the area A = " +
                      format_quantity(rack.section.area, QuantityKind::kArea) + ")");
    rack.section.neutral_axis_depth = s.number("neutral_axis_depth", std::nullopt);
  }
  rack.span = r.number("span", std::nullopt);
  rack.supports = r.choice("supports", {"pin-pin", "pin-roller"}, "pin-pin") == "pin-roller" ? Supports::kPinRoller
                                                                                             : Supports::kPinPin;
  const double pitch = kPi * pin.module;
  rack.tooth_offset = r.number("tooth_offset", 0.5 * pitch);
  r.check_range("tooth_offset", rack.tooth_offset, 0, rack.span, false, false, " (within the span rack.span)");
  rack.root_radius = r.number("root_radius", 0.0, " (0 = the pinion cutter tip radius)");
  rack.material = find_material(materials, r, "material");
  rack.tip_relief = read_relief(r, "tip_relief", "rack.tip_relief", pin.module);
  rack.root_relief = read_relief(r, "root_relief", "rack.root_relief", pin.module);

  // --- mounting
  const Block mount(top.get("mounting"), "mounting", "mounting", top.mark(), {"clearance"});
  const std::string clearance_why = " (0 = zero backlash, the teeth touch on both flanks; up to 1 x module)";
  drive.mounting.clearance = mount.number("clearance", 0.0, clearance_why);
  // 0 is the zero-backlash mesh: the pinion was generated by the rack's own
  // profile, so the teeth touch on both flanks (backlash 2 clearance tan a0).
  // Closer, the flanks would overlap: a negative clearance is impossible
  // (build_mesh_geometry refuses it too), not a deeper mesh. A module apart
  // leaves a contact ratio far below 1 for any practical tooth.
  mount.check_range("clearance", drive.mounting.clearance, 0, pin.module, false, false, clearance_why);

  // --- load
  const Block load(top.get("load"), "load", "load", top.mark(),
                   {"force", "torque", "thrust", "speed", "efficiency", "application_factor", "dynamic_factor",
                    "face_load_factor", "face_load_factor_bending", "transverse_load_factor"});
  {
    std::vector<std::string> given;
    for (const char* k : {"force", "torque", "thrust"}) {
      if (load.has(k)) given.emplace_back(k);
    }
    if (given.size() > 1) {
      throw InputError(load.key_mark(given[1]), "load." + given[1],
                       "give one of load.force (normal mesh force), load.torque (pinion torque) or load.thrust "
                       "(rack thrust), not load." + given[0] + " and load." + given[1]);
    }
    if (given.empty()) {
      load.missing("force", "load.force (normal mesh force along the line of action, e.g. 50 kN), load.torque "
                            "(pinion torque, e.g. 453 kN*m) or load.thrust (tangential force on the rack, e.g. 12 kN)");
    }
  }
  // The normal force acts along the line of action, tangent to the base
  // circle: F = T / r_b with r_b = m z cos(a0) / 2 (profile shift does not
  // change r_b); the rack's operating pressure angle is a0, so F = F_t / cos a0.
  if (load.has("force")) {
    drive.load.force = load.number("force", std::nullopt);
  } else if (load.has("torque")) {
    drive.load.torque = load.number("torque", std::nullopt);
    const double base_radius = 0.5 * pin.module * pin.teeth * std::cos(pin.pressure_angle);
    drive.load.force = drive.load.torque / base_radius;
  } else {
    drive.load.thrust = load.number("thrust", std::nullopt);
    drive.load.force = drive.load.thrust / std::cos(pin.pressure_angle);
  }
  drive.load.speed = load.number("speed", 0.0);
  drive.load.efficiency = load.number("efficiency", 1.0);
  {
    const std::string why = " (ISO 6336 load factors are >= 1; 1 = no extra load)";
    const Load ld;
    drive.load.application_factor = load.number("application_factor", ld.application_factor, why);
    drive.load.dynamic_factor = load.number("dynamic_factor", ld.dynamic_factor, why);
    drive.load.face_load_factor = load.number("face_load_factor", ld.face_load_factor, why);
    // Absent: 0, derived from K_Hbeta and the tooth proportions where the
    // stresses are computed (so it follows a varied module or face width).
    drive.load.face_load_factor_bending = load.number("face_load_factor_bending", 0.0, why);
    drive.load.transverse_load_factor = load.number("transverse_load_factor", ld.transverse_load_factor, why);
  }

  // --- effects
  const Block fx(top.get("effects"), "effects", "effects", top.mark(),
                 {"pinion_tooth", "root_segment", "fillet_foundation", "fillet_calibration", "rack_tooth",
                  "rack_foundation", "hertz", "pair_coupling", "rack_span", "supported_rack",
                  "couple_term", "body_axial", "body_shear", "interference_limit", "spalling"});
  Effects& e = drive.effects;
  const Effects defaults;
  e.pinion_tooth = fx.flag("pinion_tooth", defaults.pinion_tooth);
  e.root_segment = fx.flag("root_segment", defaults.root_segment);
  e.fillet_foundation = fx.flag("fillet_foundation", defaults.fillet_foundation);
  e.fillet_calibration = fx.flag("fillet_calibration", defaults.fillet_calibration);
  e.rack_tooth = fx.flag("rack_tooth", defaults.rack_tooth);
  e.rack_foundation = fx.flag("rack_foundation", defaults.rack_foundation);
  e.pair_coupling = fx.flag("pair_coupling", defaults.pair_coupling);
  e.supported_rack = fx.flag("supported_rack", defaults.supported_rack);
  {
    const std::string h = fx.choice("hertz", {"off", "linear", "weber_banaschek"},
                                    defaults.hertz == HertzModel::kOff      ? "off"
                                    : defaults.hertz == HertzModel::kLinear ? "linear"
                                                                            : "weber_banaschek");
    e.hertz = h == "off" ? HertzModel::kOff : h == "linear" ? HertzModel::kLinear : HertzModel::kWeberBanaschek;
  }
  {
    const std::string s = fx.choice("rack_span", {"off", "rigid", "coupled", "per_pair"},
                                    defaults.rack_span == RackSpanModel::kRigid     ? "rigid"
                                    : defaults.rack_span == RackSpanModel::kCoupled ? "coupled"
                                                                                    : "per_pair");
    e.rack_span = (s == "off" || s == "rigid") ? RackSpanModel::kRigid
                  : s == "coupled"             ? RackSpanModel::kCoupled
                                               : RackSpanModel::kPerPair;
  }
  e.couple_term = fx.flag("couple_term", defaults.couple_term);
  e.body_axial = fx.flag("body_axial", defaults.body_axial);
  e.body_shear = fx.flag("body_shear", defaults.body_shear);
  e.interference_limit = fx.flag("interference_limit", defaults.interference_limit);
  e.spalling = fx.flag("spalling", defaults.spalling);
  if (!e.any_compliance()) {
    throw InputError(top.key_mark("effects"), "effects",
                     "every compliance is switched off (pinion_tooth, fillet_foundation, rack_tooth, hertz: off, "
                     "rack_span: rigid): the mesh would be rigid, with infinite stiffness and no load sharing; "
                     "keep at least one on");
  }

  // --- faults
  if (const MarkedNode* faults = top.get("faults")) {
    if (faults->type != MarkedNode::Type::kSequence) {
      throw InputError(faults->mark, "faults",
                       "expected a list of faults (- {type: spall, member: pinion, tooth: 0, ...}), found " +
                           faults->type_name());
    }
    const int rack_teeth =
        rack.tooth_offset <= rack.span ? static_cast<int>(std::floor((rack.span - rack.tooth_offset) / pitch)) + 1 : 0;
    for (std::size_t i = 0; i < faults->items.size(); ++i) {
      const MarkedNode& item = faults->items[i];
      const std::string path = "faults[" + std::to_string(i) + "]";
      if (!item.is_map()) {
        throw InputError(item.mark, path, "expected a map {type: spall, member, tooth, start, length, width, depth}, found " +
                                              item.type_name());
      }
      const Block f(&item, path, "faults[]", item.mark,
                    {"type", "name", "member", "tooth", "start", "length", "width", "depth"});
      if (!f.has("type")) f.missing("type", "the fault type: spall");
      f.choice("type", {"spall"}, "spall");
      Spall s;
      s.name = f.text("name", "spall " + std::to_string(i + 1));
      s.member = f.choice("member", {"pinion", "rack"}, "pinion") == "rack" ? Member::kRack : Member::kPinion;
      s.tooth = f.count("tooth", std::nullopt);
      if (s.member == Member::kPinion) {
        f.check_range("tooth", s.tooth, 0, pin.teeth - 1, false, false, " (pinion teeth are numbered 0..z-1)");
      } else {
        f.check_range("tooth", s.tooth, 0, rack_teeth - 1, false, false,
                      " (rack teeth of one span are numbered 0.." + std::to_string(rack_teeth - 1) + ")");
      }
      s.start = f.number("start", std::nullopt);
      s.length = f.number("length", std::nullopt);
      s.width = f.number("width", std::nullopt);
      s.depth = f.number("depth", std::nullopt);
      drive.spalls.push_back(s);
    }
  }

  // --- numerics
  const Block num(top.get("numerics"), "numerics", "numerics", top.mark(),
                  {"quadrature_order", "adaptive_quadrature", "positions_per_period"});
  const Numerics nd;
  drive.numerics.quadrature_order = num.count("quadrature_order", nd.quadrature_order);
  drive.numerics.adaptive_quadrature = num.flag("adaptive_quadrature", nd.adaptive_quadrature);
  drive.numerics.positions_per_period = num.count("positions_per_period", nd.positions_per_period);

  read_wear(top, drive);
  read_duty(top, drive);
  read_reliability(top, drive);
  return drive;
}

bool is_variant_assignment(const std::string& assignment) {
  const std::string key = override_key(assignment);
  return key == "variant" || key.rfind("variants.", 0) == 0 || key == "variants";
}

// The file's tree with overrides applied, split into base / variants.
struct ParsedProblem {
  MarkedNode base;  // without `variant` / `variants`
  std::vector<MarkedEntry> variants;
  std::optional<std::pair<std::string, SourceMark>> selected;
  SourceMark variants_mark;
};

ParsedProblem parse_problem(const std::string& text, const std::string& file, const std::vector<std::string>& overrides) {
  ParsedProblem out;
  out.base = parse_marked_yaml(text, file);
  if (out.base.is_null()) {
    out.base.type = MarkedNode::Type::kMap;
    out.base.mark = SourceMark{file, 1, 1};
  }
  if (!out.base.is_map()) {
    throw InputError(out.base.mark, "",
                     "a problem file is a map of sections (pinion, rack, load, ...), found " + out.base.type_name());
  }
  // Only the assignments that pick or edit variants go in now; the others are
  // applied after the variant is merged, so that they win over it.
  for (const auto& o : overrides) {
    if (is_variant_assignment(o)) apply_override(out.base, o);
  }

  auto& entries = out.base.entries;
  for (auto it = entries.begin(); it != entries.end();) {
    if (it->key == "variants") {
      out.variants_mark = it->key_mark;
      if (!it->value.is_null()) {
        if (!it->value.is_map()) {
          throw InputError(it->value.mark, "variants",
                           "expected a map of variant name -> partial problem, found " + it->value.type_name());
        }
        out.variants = it->value.entries;
      }
      it = entries.erase(it);
    } else if (it->key == "variant") {
      if (!it->value.is_null()) {
        if (it->value.type != MarkedNode::Type::kScalar) {
          throw InputError(it->value.mark, "variant", "expected a variant name, found " + it->value.type_name());
        }
        out.selected = std::make_pair(it->value.scalar, it->value.mark);
      }
      it = entries.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& v : out.variants) {
    if (!v.value.is_null() && !v.value.is_map()) {
      throw InputError(v.value.mark, "variants." + v.key,
                       "expected a partial problem (a map such as {faults: [...]}), found " + v.value.type_name());
    }
    for (const auto& inner : v.value.entries) {
      if (inner.key == "variant" || inner.key == "variants") {
        throw InputError(inner.key_mark, "variants." + v.key + "." + inner.key, "variants cannot be nested");
      }
    }
  }
  return out;
}

std::string read_file(const std::string& path) { return read_input_file(path, "problem file"); }

}  // namespace

RackSection rectangular_rack_section(double width, double height) {
  RackSection s;
  s.area = width * height;
  s.second_moment = width * height * height * height / 12.0;
  s.shear_area = s.area / 1.2;
  s.neutral_axis_depth = 0.5 * height;
  return s;
}

ProblemTree load_problem_tree(const std::string& yaml_text, const std::string& name_for_messages,
                              const std::vector<std::string>& overrides) {
  ParsedProblem parsed = parse_problem(yaml_text, name_for_messages, overrides);

  // Every variant must be valid, selected or not: a broken variant is a
  // broken file. They are checked with the file's values only.
  for (const auto& v : parsed.variants) {
    MarkedNode merged = parsed.base;
    merge_over(merged, v.value);
    build_drive(merged, name_for_messages);
  }
  auto apply_value_overrides = [&](MarkedNode& tree) {
    for (const auto& o : overrides) {
      if (!is_variant_assignment(o)) apply_override(tree, o);
    }
  };
  ProblemTree out;
  out.file = name_for_messages;
  if (!parsed.selected) {
    apply_value_overrides(parsed.base);
    out.root = std::move(parsed.base);
    return out;
  }

  const auto& [wanted, where] = *parsed.selected;
  for (const auto& v : parsed.variants) {
    if (v.key != wanted) continue;
    out.root = parsed.base;
    merge_over(out.root, v.value);
    apply_value_overrides(out.root);  // ordinary overrides win over the variant's values
    out.variant = wanted;
    return out;
  }
  std::vector<std::string> names;
  for (const auto& v : parsed.variants) names.push_back(v.key);
  throw InputError(where, "variant",
                   "unknown variant '" + wanted + "'; " +
                       (names.empty() ? std::string("this problem defines no variants")
                                      : "defined: " + join(names)));
}

Drive drive_from_tree(const ProblemTree& tree) {
  Drive drive = build_drive(tree.root, tree.file);
  if (!tree.variant.empty()) drive.name += " [" + tree.variant + "]";
  return drive;
}

Drive load_problem_text(const std::string& yaml_text, const std::string& name_for_messages,
                        const std::vector<std::string>& overrides) {
  Drive drive = drive_from_tree(load_problem_tree(yaml_text, name_for_messages, overrides));
  check_overrides_against_absolute_inputs(drive, overrides);
  return drive;
}

ProblemTree load_problem_tree_file(const std::string& path, const std::vector<std::string>& overrides) {
  return load_problem_tree(read_file(path), path, overrides);
}

Drive load_problem(const std::string& path, const std::vector<std::string>& overrides) {
  return load_problem_text(read_file(path), path, overrides);
}

std::vector<std::string> problem_variants(const std::string& path) {
  const ParsedProblem parsed = parse_problem(read_file(path), path, {});
  std::vector<std::string> names;
  for (const auto& v : parsed.variants) names.push_back(v.key);
  return names;
}

std::optional<QuantityKind> problem_key_kind(std::string_view key_path) {
  std::string path(key_path);
  // Variant contents follow the same schema.
  if (path.rfind("variants.", 0) == 0) {
    const std::size_t dot = path.find('.', 9);
    if (dot == std::string::npos) return std::nullopt;
    path = path.substr(dot + 1);
  }
  if (path.rfind("materials.", 0) == 0) {
    const std::size_t dot = path.find('.', 10);
    if (dot == std::string::npos) return std::nullopt;
    path = "materials.*" + path.substr(dot);
  }
  // List indices: "faults[3].depth" -> "faults[]", "reliability.times[0]" -> "reliability.times[]".
  for (std::size_t open = path.find('['); open != std::string::npos; open = path.find('[', open + 1)) {
    const std::size_t close = path.find(']', open);
    if (close == std::string::npos) return std::nullopt;
    path.erase(open + 1, close - open - 1);
  }
  // The three hardness maps share one schema; a single value is a constant profile.
  for (const char* member : {"wear.pinion_hardness", "wear.rack_hardness"}) {
    const std::string prefix(member);
    if (path.rfind(prefix, 0) == 0 && (path.size() == prefix.size() || path[prefix.size()] == '.')) {
      path = "wear.hardness" + path.substr(prefix.size());
    }
  }
  if (path == "wear.hardness") return QuantityKind::kHardness;
  const KeySpec* s = find_spec(path);
  if (s == nullptr) return std::nullopt;
  return s->kind;
}

}  // namespace rackopt
