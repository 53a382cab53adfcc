// The typed reader of one map of a marked YAML tree, shared by the problem
// loader and the study loader: numbers and quantities with their units and
// ranges, whole numbers, choices, lists. Every error names file:line:column
// and the key path, and says what is allowed (docs/yaml.md, docs/studies.md).
// A value that is absent comes back as nullopt, so "not given" is never
// confused with a value.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/marked_yaml/marked_map.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt {

// lo <= v <= hi, either end open (strict) or infinite (no limit).
struct ValueRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const;
};

// What a numeric key is: its unit kind and the static part of its range.
// `zero_is_default`: exactly 0 is accepted too ("0 = derived from other keys").
struct NumberRule {
  QuantityKind kind = QuantityKind::kDimensionless;
  ValueRange range;
  bool zero_is_default = false;
};

// The rule of a numeric key by its schema path ("pinion.module"); nullptr
// when the schema has none.
using NumberSchema = const NumberRule* (*)(std::string_view schema_path);

// How a file's sections name near misses and print values: the problem file
// and the study file each keep their own spelling of the same messages.
struct ReaderStyle {
  NameSuggester suggest = nullptr;  // keys and choices; closest_name when null
  int digits = 6;                   // significant digits of a value in a range message
  int count_digits = 10;            // same for whole numbers
  NumberSchema schema = nullptr;    // for number(key) and whole(key)
  std::string schema_path;          // the section's path in the schema ("pinion", "faults[]")
};

// "a length (e.g. 60 mm)": the kind as "expected ..." messages name it.
std::string expected_quantity_text(QuantityKind kind);

// "5 deg <= pressure_angle <= 45 deg": `name` between the finite ends.
std::string range_text(const std::string& name, QuantityKind kind, const ValueRange& range, const ReaderStyle& style);

// Throws "<v> is out of range; allowed: <range_text><why>" at `where` when
// `range` does not contain v.
void check_value_range(const SourceMark& where, const std::string& path, const std::string& name, double v,
                       QuantityKind kind, const ValueRange& range, const std::string& why, const ReaderStyle& style);

// One value of a list key, with where it was written.
struct ListValue {
  double si = 0;
  SourceMark mark;
  std::string path;  // "reliability.times[2]"
};

class SectionReader : public MarkedMap {
 public:
  // See MarkedMap: unknown keys are refused here, with style.suggest's
  // "did you mean".
  SectionReader(const MarkedNode* node, std::string path, const SourceMark& fallback, std::vector<std::string> allowed,
                ReaderStyle style = {}, const std::string& example = {});

  const ReaderStyle& style() const { return style_; }

  // A number of `kind` in SI (a bare number is in `bare_unit`, else the
  // kind's default unit); nullopt when absent. `expected` names the kind in
  // "expected ..., found a map" (default: expected_quantity_text).
  std::optional<double> quantity(const std::string& key, QuantityKind kind, std::string_view bare_unit = {},
                                 const std::string& expected = {}) const;
  // Same, checked against `range`; `why` is appended to a range error.
  std::optional<double> quantity_in(const std::string& key, QuantityKind kind, const ValueRange& range,
                                    const std::string& why = {}, std::string_view bare_unit = {},
                                    const std::string& expected = {}) const;
  // quantity_in of a plain number (no unit).
  std::optional<double> plain_number(const std::string& key, const ValueRange& range) const {
    return quantity_in(key, QuantityKind::kDimensionless, range);
  }
  // A whole number in `range` ("2147483648" is out of range, not an overflow).
  std::optional<long long> integer(const std::string& key, const ValueRange& range) const;

  // The schema's rule of `key` (style.schema at schema_path.key); a
  // programming error when the schema has none.
  const NumberRule& rule(const std::string& key) const;
  // A number by the schema: `fallback` when absent, a missing-key error when
  // there is no fallback. Exactly 0 passes for a zero_is_default key.
  double number(const std::string& key, std::optional<double> fallback, const std::string& why = {}) const;
  int whole(const std::string& key, std::optional<int> fallback) const;

  // One of `options`, compared without case, returned as `options` spells
  // it; nullopt when absent. A value that is none of them: "'x' is not
  // allowed; allowed: a | b" with "did you mean" for a near miss.
  std::optional<std::string> choice(const std::string& key, const std::vector<std::string>& options) const;

  // A list of `kind` quantities, written either as a YAML list ([40 yr,
  // 55 yr] or [40, 55]) or, because YAML cannot put a unit after a flow list,
  // as one text "[40, 55, 60] yr" whose trailing unit applies to every bare
  // number. A bare item means `bare_unit` (empty: the kind's default). A
  // single value is a list of one. Each item is checked against `range`, the
  // range message naming `key`. Empty when absent.
  std::vector<ListValue> quantity_list(const std::string& key, QuantityKind kind, const ValueRange& range,
                                       std::string_view bare_unit = {}) const;

  // Throws when v is outside `range`, at the value (or the key, or the map);
  // `why` explains a derived limit. Without `kind`: the schema's kind.
  void check_range(const std::string& key, QuantityKind kind, double v, const ValueRange& range,
                   const std::string& why = {}) const;
  void check_range(const std::string& key, double v, const ValueRange& range, const std::string& why = {}) const;

 private:
  ReaderStyle style_;
};

}  // namespace rackopt
