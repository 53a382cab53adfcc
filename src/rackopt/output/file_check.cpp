#include "rackopt/output/file_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

#include <sys/stat.h>

namespace rackopt {
namespace {

// "report.md.tmp.123" -> ".md", "pareto.png.tmp" -> ".png".
std::string extension_of(std::string name) {
  const std::size_t slash = name.find_last_of('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  for (;;) {
    const std::size_t dot = name.find_last_of('.');
    if (dot == std::string::npos) return "";
    const std::string ext = name.substr(dot);
    bool digits = ext.size() > 1;
    for (std::size_t i = 1; i < ext.size(); ++i) digits = digits && std::isdigit(static_cast<unsigned char>(ext[i]));
    if (ext == ".tmp" || digits) {
      name.resize(dot);
      continue;
    }
    std::string lower;
    for (char c : ext) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower;
  }
}

std::string read_range(std::ifstream& in, long long offset, long long n) {
  std::string out(static_cast<std::size_t>(n), '\0');
  in.seekg(offset);
  in.read(out.data(), n);
  out.resize(static_cast<std::size_t>(in.gcount()));
  return out;
}

}  // namespace

std::string check_json_complete(const std::string& text) {
  std::size_t i = 0;
  auto skip_ws = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  };
  skip_ws();
  if (i == text.size()) return "empty JSON";
  if (text[i] != '{' && text[i] != '[') return "does not start with { or [";
  std::string stack;
  bool in_string = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      stack.push_back(c);
    } else if (c == '}' || c == ']') {
      if (stack.empty() || stack.back() != (c == '}' ? '{' : '[')) return "unbalanced brackets";
      stack.pop_back();
      if (stack.empty()) {
        ++i;
        break;
      }
    }
  }
  if (in_string || !stack.empty()) return "incomplete JSON (truncated)";
  skip_ws();
  if (i != text.size()) return "text after the JSON value";
  return "";
}

std::string check_output_file(const std::string& path, const std::string& format_name, long long expected_size) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0) return "missing";
  if (!S_ISREG(st.st_mode)) return "not a regular file";
  const long long size = static_cast<long long>(st.st_size);
  if (size == 0) return "empty";
  if (expected_size >= 0 && size != expected_size) {
    return "size " + std::to_string(size) + " bytes instead of " + std::to_string(expected_size) + " (truncated)";
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot be read back";
  const std::string ext = extension_of(format_name);
  if (ext == ".png") {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static constexpr unsigned char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (read_range(in, 0, 8) != std::string_view(reinterpret_cast<const char*>(kSignature), 8)) {
      return "no PNG signature";
    }
    if (size < 20 || read_range(in, size - 12, 12) != std::string_view(reinterpret_cast<const char*>(kIend), 12)) {
      return "no IEND chunk at the end (truncated PNG)";
    }
  } else if (ext == ".svg") {
    const long long n = std::min<long long>(size, 64);
    if (read_range(in, size - n, n).find("</svg>") == std::string::npos) return "no </svg> at the end (truncated SVG)";
  } else if (ext == ".html") {
    const long long n = std::min<long long>(size, 64);
    if (read_range(in, size - n, n).find("</html>") == std::string::npos) {
      return "no </html> at the end (truncated HTML)";
    }
  } else if (ext == ".json") {
    std::ostringstream all;
    all << in.rdbuf();
    const std::string why = check_json_complete(all.str());
    if (!why.empty()) return why;
  } else if (ext == ".csv" || ext == ".md" || ext == ".gp") {
    if (read_range(in, size - 1, 1) != "\n") return "does not end with a newline (truncated)";
  } else {
    // A format nobody taught the check would be published unverified.
    return "no completeness check for the format '" + ext +
           "'; add one to check_output_file (docs/extending.md, \"A new output file or format\")";
  }
  return "";
}

}  // namespace rackopt
