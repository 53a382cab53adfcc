#include "rackopt/core/error.hpp"

namespace rackopt {

std::string to_string(const SourceMark& mark) {
  std::string out = mark.file.empty() ? std::string("<input>") : mark.file;
  if (mark.line > 0) {
    out += ":" + std::to_string(mark.line);
    if (mark.column > 0) out += ":" + std::to_string(mark.column);
  }
  return out;
}

static std::string format_input_error(const SourceMark& mark, const std::string& key,
                                      const std::string& message) {
  std::string out = to_string(mark) + ": ";
  if (!key.empty()) out += key + ": ";
  return out + message;
}

InputError::InputError(SourceMark mark, std::string key_path, std::string message)
    : std::runtime_error(format_input_error(mark, key_path, message)),
      mark_(std::move(mark)),
      key_path_(std::move(key_path)),
      message_(std::move(message)) {}

DesignError::DesignError(std::string code, const std::string& message)
    : std::runtime_error(message), code_(std::move(code)) {}

}  // namespace rackopt
