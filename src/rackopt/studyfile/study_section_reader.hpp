// How the study file reads its sections: the shared SectionReader
// (marked_yaml/section_reader.hpp) in the study file's style, which also
// proposes a key or a choice that a mistyped word abbreviates, and prints
// values to 10 significant digits.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/marked_yaml/section_reader.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt::studyfile {

// The file of marks for values given with --set.
inline constexpr const char* kCommandLine = "<command line>";

// The candidate closest to `word` when it is a near miss (closest_name, the
// rule of every loader), or else one it abbreviates ("max_evals").
std::optional<std::string> near_miss(std::string_view word, const std::vector<std::string>& candidates);

ReaderStyle study_reader_style();

// One map of the study file; see SectionReader. `example` completes
// "expected a map of keys (...), e.g. <example>".
SectionReader study_section(const MarkedNode* node, std::string path, const SourceMark& fallback,
                            std::vector<std::string> allowed, const std::string& example = {});

// "objectives[2]".
std::string item_path(const std::string& list, std::size_t i);

// A value as study messages print it (10 significant digits, in `unit` or
// the kind's default unit).
std::string format_in(double si, QuantityKind kind, std::string_view unit = {});

// "a time": how the study file names a quantity it expects.
std::string expected_kind_text(QuantityKind kind);

// A single value of a list or a variable, with where it was written.
struct ValueSite {
  double value;
  std::string text;
  SourceMark mark;
  std::string path;
};

// `node` must be a scalar of `kind` ("expected a single value, found ...").
ValueSite read_value(const MarkedNode& node, const std::string& path, QuantityKind kind);

}  // namespace rackopt::studyfile
