#include "rackopt/problem/drive_sections.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;

const char* const kHardnessKinds = "constant | polynomial | table | case_hardened";

// Evaluates sum c_i h^i (Horner).
double polynomial_value(const std::vector<double>& c, double h) {
  double v = 0;
  for (std::size_t i = c.size(); i-- > 0;) v = v * h + c[i];
  return v;
}

}  // namespace

// Every profile comes out complete: surface = H(0), core filled (measured
// data: the value at its deepest point unless given; constant: the surface),
// limit filled (case_hardened: 0.8 surface unless given).
HardnessProfile read_hardness(const MarkedNode& node, const std::string& path) {
  HardnessProfile h;
  const NumberRule& surface_rule = *find_problem_key_rule("wear.hardness.surface");
  if (node.type == MarkedNode::Type::kScalar) {
    h.kind = HardnessProfile::Kind::kConstant;
    h.surface = parse_quantity(node.scalar, QuantityKind::kHardness, node.mark, path);
    check_value_range(node.mark, path, "hardness", h.surface, QuantityKind::kHardness, surface_rule.range, "",
                      problem_reader_style());
    h.core = h.surface;
    return h;
  }
  if (!node.is_map()) {
    throw InputError(node.mark, path,
                     std::string("expected a hardness (e.g. 596 HB: a constant profile) or a profile map {kind: ") +
                         kHardnessKinds + ", ...}, found " + node.type_name());
  }
  const std::vector<std::string> all = {"kind",       "surface",  "core",         "limit",
                                        "case_depth", "exponent", "coefficients", "valid_depth",
                                        "depths",     "values",   "depth_unit",   "hardness_unit"};
  const SectionReader b = problem_section(&node, path, "wear.hardness", node.mark, all);
  if (!b.has("kind")) {
    b.missing("kind", std::string("the profile kind: ") + kHardnessKinds +
                          " (or write a single hardness such as 596 HB for a constant profile)");
  }
  const std::string kind = b.choice("kind", {"constant", "polynomial", "table", "case_hardened"}).value_or("constant");
  std::vector<std::string> own;
  if (kind == "constant") own = {"kind", "surface"};
  if (kind == "polynomial") own = {"kind", "coefficients", "depth_unit", "hardness_unit", "valid_depth", "core"};
  if (kind == "table") own = {"kind", "depths", "values", "depth_unit", "hardness_unit", "core"};
  if (kind == "case_hardened") own = {"kind", "surface", "core", "case_depth", "limit", "exponent"};
  for (const auto& e : node.entries) {
    if (std::find(own.begin(), own.end(), e.key) == own.end()) {
      throw InputError(
          e.key_mark, b.child_path(e.key),
          "key '" + e.key + "' does not belong to a '" + kind + "' hardness profile; its keys: " + join(own));
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
      b.missing("coefficients",
                "the fit's coefficients in ascending powers of depth, e.g. [596, 2, -1.6786, -0.25] "
                "(units from depth_unit and hardness_unit)");
    }
    if (list->type != MarkedNode::Type::kSequence || list->items.empty() || list->items.size() > 12) {
      throw InputError(list->mark, b.child_path("coefficients"),
                       "expected a list of 1 to 12 plain numbers c0, c1, ... (H = c0 + c1 h + c2 h^2 + ..., in " +
                           hardness_unit + " with h in " + depth_unit + "), found " +
                           (list->type == MarkedNode::Type::kSequence ? std::to_string(list->items.size()) + " items"
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
                         e.message() +
                             " (coefficients are plain numbers; their units are set once by depth_unit, "
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
        b.check_range("valid_depth", h.valid_depth, {0, depth, true, true},
                      " (the polynomial gives H = " + format_quantity(value, QuantityKind::kHardness) +
                          " at h = " + format_length_mm(depth) + "; a measured fit must stay positive over its range)");
      }
    }
    h.core = b.has("core") ? b.number("core", std::nullopt) : polynomial_value(h.coefficients, h.valid_depth);
  } else if (kind == "table") {
    h.kind = HardnessProfile::Kind::kTable;
    if (!b.has("depths")) b.missing("depths", "the measured depths, e.g. [0, 1, 2, 4] mm, ascending");
    if (!b.has("values")) b.missing("values", "the measured hardness at each depth, e.g. [596, 590, 560, 480] HB");
    const std::vector<ListValue> depths = schema_quantity_list(b, "depths", "wear.hardness.depths[]", depth_unit);
    const std::vector<ListValue> values = schema_quantity_list(b, "values", "wear.hardness.values[]", hardness_unit);
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
    b.check_range("core", h.core, {0, h.surface, true, true},
                  " (below the surface hardness " + format_quantity(h.surface, QuantityKind::kHardness) +
                      ": a case-hardened profile drops from surface to core)");
    h.limit = b.number("limit", 0.8 * h.surface);
    if (!(h.limit > h.core && h.limit < h.surface)) {
      const std::string why =
          " (the hardness at the case depth lies between core and surface" +
          std::string(b.has("limit") ? ")" : "; the default limit is 0.8 x surface, ISO 18203 SHD)");
      if (b.has("limit")) {
        b.check_range("limit", h.limit, {h.core, h.surface, true, true}, why);
      }
      b.check_range("core", h.core, {0, h.limit, true, true}, why);
    }
  }
  return h;
}

// wear: absent = not configured (coefficient 0); present = coefficient and a
// hardness for both members are required.
void read_wear(const SectionReader& top, Drive& drive) {
  const MarkedNode* node = top.get("wear");
  if (node == nullptr) return;
  const SectionReader w =
      problem_section(node, "wear", "wear", top.key_mark("wear"),
                      {"coefficient", "max_depth", "min_contact_ratio", "stop_at_case_depth", "update_profile",
                       "profile_points", "block_fraction", "hardness", "pinion_hardness", "rack_hardness"});
  WearSpec& wear = drive.wear;
  const WearSpec defaults;
  wear.coefficient = w.number("coefficient", std::nullopt);
  wear.max_depth = w.number("max_depth", defaults.max_depth);
  // Deeper than half the tooth thickness at the pitch line (pi m / 4) the
  // tooth is gone before the limit is reached.
  const double quarter_pitch = 0.25 * kPi * drive.pinion.module;
  w.check_range("max_depth", wear.max_depth, {0, quarter_pitch, true, false},
                " (half the tooth thickness at the pitch line, pi m / 4 = " + format_length_mm(quarter_pitch) + ")");
  wear.min_contact_ratio = w.number("min_contact_ratio", defaults.min_contact_ratio);
  wear.stop_at_case_depth = w.flag("stop_at_case_depth", defaults.stop_at_case_depth);
  wear.update_profile = w.flag("update_profile", defaults.update_profile);
  wear.profile_points = w.whole("profile_points", defaults.profile_points);
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

}  // namespace rackopt
