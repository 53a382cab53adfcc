#include "rackopt/studyfile/verify_section.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt::studyfile {

// The loaders fill the study layer's types throughout.
using namespace rackopt::study;
namespace {

constexpr const char* kForms = "fe, or a map {method: fe, positions: 4, level: 0, extended_contact: off, rack_supports: off}";


int whole_in(const MarkedMap& m, const std::string& key, int fallback, int lo, int hi) {
  const auto t = m.scalar(key, "a whole number");
  if (!t) return fallback;
  const double v = parse_whole_number(t->first, t->second, m.child_path(key));
  if (v < lo || v > hi) {
    throw InputError(t->second, m.child_path(key),
                     t->first + " is out of range; allowed: " + std::to_string(lo) + " <= " + key + " <= " +
                         std::to_string(hi));
  }
  return static_cast<int>(v);
}

}  // namespace

std::optional<FeVerifySpec> read_verify_section(const MarkedMap& top) {
  const MarkedNode* node = top.get("verify");
  if (node == nullptr) return std::nullopt;
  FeVerifySpec v;
  v.mark = node->mark;
  if (node->type == MarkedNode::Type::kScalar) {
    if (lower(node->scalar) != "fe") {
      throw InputError(node->mark, "verify", "'" + node->scalar + "' is not allowed; allowed: " + kForms);
    }
    return v;
  }
  if (!node->is_map()) throw InputError(node->mark, "verify", "expected " + std::string(kForms) + ", found " + node->type_name());
  const MarkedMap m(node, "verify", top.key_mark("verify"), {"method", "positions", "level", "extended_contact", "rack_supports"},
                    "{method: fe, positions: 4, level: 0}");
  if (const auto method = m.scalar("method", "fe"); method && lower(method->first) != "fe") {
    throw InputError(method->second, "verify.method", "'" + method->first + "' is not allowed; allowed: fe");
  }
  v.positions = whole_in(m, "positions", v.positions, 1, fe::kMaxFePositions);
  v.level = whole_in(m, "level", v.level, 0, 6);
  v.extended_contact = m.flag("extended_contact", v.extended_contact);
  v.rack_supports = m.flag("rack_supports", v.rack_supports);
  return v;
}

}  // namespace rackopt::studyfile
