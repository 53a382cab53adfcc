#include "rackopt/problem/problem_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "rackopt/problem/marked_tree.hpp"

namespace rackopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
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
};

constexpr KeySpec kKeySpecs[] = {
    {"pinion.teeth", QuantityKind::kCount, 5, 1000, false, false},
    {"pinion.module", QuantityKind::kLength, 0.05e-3, 1.0, false, false},
    {"pinion.pressure_angle", QuantityKind::kAngle, 5 * kDeg, 45 * kDeg, false, false},
    {"pinion.face_width", QuantityKind::kLength, 0, 10.0, true, false},
    {"pinion.profile_shift", QuantityKind::kDimensionless, -2, 2, false, false},
    {"pinion.addendum", QuantityKind::kDimensionless, 0, 3, true, false},
    {"pinion.dedendum", QuantityKind::kDimensionless, 0, 3, true, false},
    {"pinion.tip_radius", QuantityKind::kDimensionless, 0, 1, false, false},
    {"pinion.bore_radius", QuantityKind::kLength, 0, 10.0, true, false},
    {"rack.addendum", QuantityKind::kDimensionless, 0, 3, true, false},
    {"rack.dedendum", QuantityKind::kDimensionless, 0, 3, true, false},
    {"rack.face_width", QuantityKind::kLength, 0, 10.0, true, false},
    {"rack.body_height", QuantityKind::kLength, 0, 10.0, true, false},
    {"rack.body_width", QuantityKind::kLength, 0, 10.0, true, false},
    {"rack.section.area", QuantityKind::kArea, 0, kInf, true, true},
    {"rack.section.second_moment", QuantityKind::kSecondMoment, 0, kInf, true, true},
    {"rack.section.shear_area", QuantityKind::kArea, 0, kInf, true, true},
    {"rack.section.neutral_axis_depth", QuantityKind::kLength, 0, 10.0, true, false},
    {"rack.span", QuantityKind::kLength, 0, 100.0, true, false},
    {"rack.tooth_offset", QuantityKind::kLength, 0, kInf, false, true},
    {"mounting.clearance", QuantityKind::kLength, -kInf, kInf, true, true},
    {"materials.*.E", QuantityKind::kModulus, 0, 2000e9, true, false},
    {"materials.*.nu", QuantityKind::kDimensionless, 0, 0.5, false, true},
    {"load.force", QuantityKind::kForce, 0, kInf, true, true},
    {"load.torque", QuantityKind::kTorque, 0, kInf, true, true},
    {"faults[].tooth", QuantityKind::kCount, 0, 1e9, false, false},
    {"faults[].start", QuantityKind::kLength, 0, kInf, false, true},
    {"faults[].length", QuantityKind::kLength, 0, kInf, true, true},
    {"faults[].width", QuantityKind::kLength, 0, kInf, true, true},
    {"faults[].depth", QuantityKind::kLength, 0, kInf, true, true},
    {"numerics.quadrature_order", QuantityKind::kCount, 2, 64, false, false},
    {"numerics.positions_per_period", QuantityKind::kCount, 4, 10000, false, false},
};

const KeySpec* find_spec(std::string_view pattern) {
  for (const auto& s : kKeySpecs) {
    if (pattern == s.pattern) return &s;
  }
  return nullptr;
}

// Edit distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string join(const std::vector<std::string>& names, const std::string& separator = ", ") {
  std::string out;
  for (const auto& n : names) {
    if (!out.empty()) out += separator;
    out += n;
  }
  return out;
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
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

// One map of the problem (a section such as `pinion`, one material, one
// fault). Rejects unknown keys on construction; reads typed values with
// defaults and ranges; reports missing keys at the map's own mark.
class Block {
 public:
  // `node` may be nullptr or null (section absent or empty): then every key
  // is absent and errors point at `fallback` (the parent's mark).
  Block(const MarkedNode* node, std::string path, std::string pattern, const SourceMark& fallback,
        std::vector<std::string> allowed)
      : node_(node), path_(std::move(path)), pattern_(std::move(pattern)), mark_(fallback),
        allowed_(std::move(allowed)) {
    if (node_ != nullptr && node_->is_null()) node_ = nullptr;
    if (node_ == nullptr) return;
    mark_ = node_->mark;
    if (!node_->is_map()) {
      throw InputError(node_->mark, path_,
                       "expected a map of keys (" + join(allowed_) + "), found " + node_->type_name());
    }
    if (allowed_.empty()) return;  // free-form names (materials, variants)
    for (const auto& e : node_->entries) {
      if (std::find(allowed_.begin(), allowed_.end(), e.key) != allowed_.end()) continue;
      std::string message = "unknown key '" + e.key + "'";
      message += path_.empty() ? " at the top level" : " in " + path_;
      const std::string* best = nullptr;
      std::size_t best_distance = 0;
      for (const auto& candidate : allowed_) {
        const std::size_t d = edit_distance(lower(e.key), lower(candidate));
        if (best == nullptr || d < best_distance) {
          best = &candidate;
          best_distance = d;
        }
      }
      if (best != nullptr && best_distance <= std::max<std::size_t>(2, e.key.size() / 3)) {
        message += "; did you mean '" + *best + "'?";
      }
      message += " Allowed keys: " + join(allowed_);
      throw InputError(e.key_mark, child_path(e.key), message);
    }
  }

  const MarkedNode* node() const { return node_; }
  const SourceMark& mark() const { return mark_; }
  const std::string& path() const { return path_; }
  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  // Present and not null.
  const MarkedNode* get(const std::string& key) const {
    if (node_ == nullptr) return nullptr;
    const MarkedNode* v = node_->find(key);
    return (v == nullptr || v->is_null()) ? nullptr : v;
  }
  bool has(const std::string& key) const { return get(key) != nullptr; }

  SourceMark key_mark(const std::string& key) const {
    if (node_ != nullptr) {
      for (const auto& e : node_->entries) {
        if (e.key == key) return e.key_mark;
      }
    }
    return mark_;
  }

  [[noreturn]] void missing(const std::string& key, const std::string& expected) const {
    throw InputError(mark_, child_path(key), "required key '" + key + "' is missing; expected " + expected);
  }

  // The scalar text of `key`; nullopt when absent. `expected` names the kind for messages.
  std::optional<std::pair<std::string, SourceMark>> scalar(const std::string& key, const std::string& expected) const {
    const MarkedNode* v = get(key);
    if (v == nullptr) {
      // A key written with an empty value is absent (`key:` or `key: ~`),
      // except that a required key then gets the "missing" message.
      return std::nullopt;
    }
    if (v->type != MarkedNode::Type::kScalar) {
      throw InputError(v->mark, child_path(key), "expected " + expected + ", found " + v->type_name());
    }
    return std::make_pair(v->scalar, v->mark);
  }

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
    }
    return "a number";
  }

  // A number of the key's kind, in SI, checked against the KeySpec range.
  double number(const std::string& key, std::optional<double> fallback) const {
    const KeySpec& s = spec(key);
    const auto text = scalar(key, expected_text(s.kind));
    if (!text) {
      if (!fallback) missing(key, expected_text(s.kind));
      return *fallback;
    }
    const double v = parse_quantity(text->first, s.kind, text->second, child_path(key));
    check_range(key, v, s.lo, s.hi, s.lo_open, s.hi_open, "");
    return v;
  }

  int count(const std::string& key, std::optional<int> fallback) const {
    const KeySpec& s = spec(key);
    const auto text = scalar(key, expected_text(s.kind));
    if (!text) {
      if (!fallback) missing(key, expected_text(s.kind));
      return *fallback;
    }
    const int v = parse_count(text->first, text->second, child_path(key));
    check_range(key, v, s.lo, s.hi, s.lo_open, s.hi_open, "");
    return v;
  }

  // Throws when v is outside the range; `why` explains a derived limit.
  void check_range(const std::string& key, double v, double lo, double hi, bool lo_open, bool hi_open,
                   const std::string& why) const {
    const bool below = lo_open ? !(v > lo) : !(v >= lo);
    const bool above = hi_open ? !(v < hi) : !(v <= hi);
    if (!below && !above) return;
    const QuantityKind kind = spec(key).kind;
    const auto text = scalar(key, "");
    const SourceMark where = text ? text->second : mark_;
    throw InputError(where, child_path(key),
                     format_in_kind(v, kind) + " is out of range; allowed: " +
                         range_text(key, kind, lo, hi, lo_open, hi_open) + why);
  }

  bool flag(const std::string& key, bool fallback) const {
    const auto text = scalar(key, "on or off");
    if (!text) return fallback;
    const std::string t = lower(text->first);
    if (t == "on" || t == "true" || t == "yes") return true;
    if (t == "off" || t == "false" || t == "no") return false;
    throw InputError(text->second, child_path(key), "'" + text->first + "' is not a switch; allowed: on, off (or true, false)");
  }

  std::string choice(const std::string& key, const std::vector<std::string>& options, const std::string& fallback) const {
    const auto text = scalar(key, "one of " + join(options, " | "));
    if (!text) return fallback;
    for (const auto& o : options) {
      if (text->first == o) return o;
    }
    throw InputError(text->second, child_path(key), "'" + text->first + "' is not allowed; allowed: " + join(options, " | "));
  }

  std::string text(const std::string& key, const std::string& fallback) const {
    const auto t = scalar(key, "a text");
    return t ? t->first : fallback;
  }

 private:
  const MarkedNode* node_;
  std::string path_;
  std::string pattern_;
  SourceMark mark_;
  std::vector<std::string> allowed_;
};

const std::vector<std::string> kTopKeys = {"name", "description", "variant", "variants", "pinion", "rack",
                                           "mounting", "materials", "load", "effects", "faults", "numerics"};

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
        const Block m(&e.value, "materials." + e.key, "materials.*", e.key_mark, {"E", "nu"});
        if (m.node() == nullptr) {
          throw InputError(e.key_mark, m.path(), "a material needs E (modulus) and nu (Poisson's ratio)");
        }
        materials[e.key] = Material{e.key, m.number("E", std::nullopt), m.number("nu", std::nullopt)};
      }
    }
  }

  // --- pinion
  const Block p(top.get("pinion"), "pinion", "pinion", top.mark(),
                {"teeth", "module", "pressure_angle", "face_width", "profile_shift", "addendum", "dedendum",
                 "tip_radius", "bore_radius", "material"});
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
    // fillet-foundation fit was made for (about 1.4..7, physics.md 3.2).
    pin.bore_radius = root_radius > 0 ? 0.5 * root_radius : 0.0;
  }
  pin.material = find_material(materials, p, "material");

  // --- rack
  const Block r(top.get("rack"), "rack", "rack", top.mark(),
                {"addendum", "dedendum", "face_width", "body_height", "body_width", "section", "span", "supports",
                 "tooth_offset", "material"});
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
  rack.material = find_material(materials, r, "material");

  // --- mounting
  const Block mount(top.get("mounting"), "mounting", "mounting", top.mark(), {"clearance"});
  drive.mounting.clearance = mount.number("clearance", 0.0);
  // A quarter module closer is the bottom clearance of a standard tooth: any
  // closer and the rack tip digs into the pinion root. A module apart leaves
  // a contact ratio far below 1 for any practical tooth.
  mount.check_range("clearance", drive.mounting.clearance, -0.25 * pin.module, pin.module, false, false,
                    " (-0.25 x module .. +1 x module)");

  // --- load
  const Block load(top.get("load"), "load", "load", top.mark(), {"force", "torque"});
  const bool has_force = load.has("force");
  const bool has_torque = load.has("torque");
  if (has_force && has_torque) {
    throw InputError(load.key_mark("torque"), "load.torque",
                     "give either load.force (normal mesh force) or load.torque (pinion torque), not both");
  }
  if (!has_force && !has_torque) {
    load.missing("force", "load.force (normal mesh force along the line of action, e.g. 50 kN) or load.torque "
                          "(pinion torque, e.g. 453 kN*m)");
  }
  if (has_force) {
    drive.load.force = load.number("force", std::nullopt);
    drive.load.torque = 0.0;
  } else {
    drive.load.torque = load.number("torque", std::nullopt);
    // The normal force acts along the line of action, tangent to the base
    // circle: F = T / r_b with r_b = m z cos(a0) / 2 (profile shift does not
    // change r_b).
    const double base_radius = 0.5 * pin.module * pin.teeth * std::cos(pin.pressure_angle);
    drive.load.force = drive.load.torque / base_radius;
  }

  // --- effects
  const Block fx(top.get("effects"), "effects", "effects", top.mark(),
                 {"pinion_tooth", "root_segment", "fillet_foundation", "rack_tooth", "hertz", "rack_span",
                  "couple_term", "body_axial", "body_shear", "interference_limit", "spalling"});
  Effects& e = drive.effects;
  const Effects defaults;
  e.pinion_tooth = fx.flag("pinion_tooth", defaults.pinion_tooth);
  e.root_segment = fx.flag("root_segment", defaults.root_segment);
  e.fillet_foundation = fx.flag("fillet_foundation", defaults.fillet_foundation);
  e.rack_tooth = fx.flag("rack_tooth", defaults.rack_tooth);
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

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(SourceMark{path, 0, 0}, "", std::string("cannot open the problem file: ") + std::strerror(errno));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

RackSection rectangular_rack_section(double width, double height) {
  RackSection s;
  s.area = width * height;
  s.second_moment = width * height * height * height / 12.0;
  s.shear_area = s.area / 1.2;
  s.neutral_axis_depth = 0.5 * height;
  return s;
}

Drive load_problem_text(const std::string& yaml_text, const std::string& name_for_messages,
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
  if (!parsed.selected) {
    apply_value_overrides(parsed.base);
    return build_drive(parsed.base, name_for_messages);
  }

  const auto& [wanted, where] = *parsed.selected;
  for (const auto& v : parsed.variants) {
    if (v.key != wanted) continue;
    MarkedNode merged = parsed.base;
    merge_over(merged, v.value);
    apply_value_overrides(merged);  // ordinary overrides win over the variant's values
    Drive drive = build_drive(merged, name_for_messages);
    drive.name += " [" + wanted + "]";
    return drive;
  }
  std::vector<std::string> names;
  for (const auto& v : parsed.variants) names.push_back(v.key);
  throw InputError(where, "variant",
                   "unknown variant '" + wanted + "'; " +
                       (names.empty() ? std::string("this problem defines no variants")
                                      : "defined: " + join(names)));
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
  if (path.rfind("faults[", 0) == 0) {
    const std::size_t close = path.find(']');
    if (close == std::string::npos) return std::nullopt;
    path = "faults[]" + path.substr(close + 1);
  }
  const KeySpec* s = find_spec(path);
  if (s == nullptr) return std::nullopt;
  return s->kind;
}

}  // namespace rackopt
