// The problem file's numeric keys: each key's quantity kind and the static
// part of its allowed range (docs/yaml.md states the same limits), and the
// section reader that reads a problem section by them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/marked_yaml/section_reader.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt {

// The rule of a schema path ("pinion.module", "materials.*.E",
// "faults[].depth", "wear.hardness.depths[]"); nullptr for a path that is
// not a numeric key.
const NumberRule* find_problem_key_rule(std::string_view schema_path);

// The quantity kind of a numeric problem key, so that other inputs (study
// bounds, sweeps) parse its values the same way. Accepts concrete paths
// ("materials.steel.E", "faults[0].depth", "reliability.times[2]",
// "wear.rack_hardness.case_depth"). nullopt for keys that are not numbers
// (names, on/off switches, choices), for unknown keys, and for the
// parameters of reliability.random[n] (their kind follows the `input`) and
// polynomial coefficients (their unit follows depth_unit/hardness_unit).
std::optional<QuantityKind> problem_key_kind(std::string_view key_path);

// The problem file's reader style: closest_name for near misses, values in
// range messages to 6 significant digits (whole numbers to 10).
ReaderStyle problem_reader_style(std::string schema_path = {});

// One map of the problem (a section such as `pinion`, one material, one
// fault) at `path`, its numeric keys ruled by the schema at `schema_path`.
// `node` may be nullptr or null (section absent or empty): then every key is
// absent and errors point at `fallback` (the parent's mark).
SectionReader problem_section(const MarkedNode* node, std::string path, std::string schema_path,
                              const SourceMark& fallback, std::vector<std::string> allowed);

// A list key of `section` whose items are ruled by the schema path
// `item_schema_path` ("reliability.times[]"); see SectionReader::quantity_list.
std::vector<ListValue> schema_quantity_list(const SectionReader& section, const std::string& key,
                                            const std::string& item_schema_path, std::string_view bare_unit = {});

}  // namespace rackopt
