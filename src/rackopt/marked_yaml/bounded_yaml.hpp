// The one way rackopt parses YAML text (problem files, study files, `--set`
// values): yaml-cpp 0.7 loads, but only after a streaming pass has checked
// that the text holds at most one document and stays inside the limits of
// marked_yaml/input_limits.hpp once aliases are expanded. YAML::LoadAll is never
// used: on a text that starts with ',' it returns empty documents forever.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

namespace rackopt {

// The single document of `text` as a yaml-cpp node (a Null node when the
// text holds no document). Marks in errors name `file`; with
// `from_command_line` they carry line 0 (the text is a `--set` value).
// Throws InputError, in time and memory bounded by the size of the text, for:
// text longer than kMaxInputBytes; a YAML syntax error (yaml-cpp's mark);
// nesting deeper than yaml-cpp's 500 levels; more than kMaxTreeNodes nodes or
// kMaxExpandedTextBytes of key and value text after alias expansion; an alias
// inside the value its anchor names (a cycle); a stray ',' outside a flow
// list or map (at the ','); a second document ('---').
YAML::Node load_one_yaml_document(const std::string& text, const std::string& file, bool from_command_line);

}  // namespace rackopt
