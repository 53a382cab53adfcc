// Error types shared by every module.
//
// Two kinds of failure are kept apart on purpose:
//  * InputError: the user wrote something we cannot accept (bad unit, unknown
//    key, out-of-range value). Carries where it was written. CLI exit code 2.
//  * DesignError: the input is well-formed but describes a drive that cannot
//    exist or that the models cannot represent (pointed tooth, contact ratio
//    below 1, spall deeper than the tooth). An optimizer sees it as an
//    infeasible point with this message; the CLI also exits 2.
// Anything else that escapes (std::runtime_error, ...) is a failed run (exit 1).
#pragma once

#include <stdexcept>
#include <string>

namespace rackopt {

// Where in an input file a value came from. line/column are 1-based; 0 means
// unknown (for example a value given with --set on the command line).
struct SourceMark {
  std::string file;  // "<command line>" for --set overrides
  int line = 0;
  int column = 0;
};

// "file:line:column" (or just "file" when line is unknown).
std::string to_string(const SourceMark& mark);

class InputError : public std::runtime_error {
 public:
  // key_path is the dotted path (e.g. "pinion.module"), may be empty.
  // what() is "file:line:column: key: message".
  InputError(SourceMark mark, std::string key_path, std::string message);
  const SourceMark& mark() const { return mark_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& message() const { return message_; }

 private:
  SourceMark mark_;
  std::string key_path_;
  std::string message_;
};

class DesignError : public std::runtime_error {
 public:
  // code is a short stable identifier an optimizer or a test can match
  // ("pointed_tooth", "contact_ratio_below_one", "spall_too_deep", ...);
  // message is for people and says what limit was broken and by how much.
  DesignError(std::string code, const std::string& message);
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

}  // namespace rackopt
