#include "rackopt/study_report/markdown_text.hpp"

#include <cmark-gfm.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <vector>

#include "rackopt/core/text.hpp"
#include "rackopt/study_report/cmark_tree.hpp"

namespace rackopt::study_report {
namespace {

using namespace cmark_tree;

bool is_control(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 || byte == 0x7f;
}


// The CommonMark renderer ends a list that a list or a code block follows
// with the line "<!-- end list -->", raw HTML of its own. Each such line (as
// the parser reads it: never one inside a code block) becomes the link
// reference definition "[//]: # (end of list)", which ends the list as well
// and renders as nothing.
std::string without_list_end_comments(const std::string& markdown) {
  static constexpr std::string_view kComment = "<!-- end list -->";
  const auto parser = gfm_parser("report.md");
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  const cmark_tree::Document doc(cmark_parser_finish(parser.get()));
  std::set<int> lines;
  for (cmark_node* n : nodes_where(doc.get(), [](cmark_node_type t) { return t == CMARK_NODE_HTML_BLOCK; })) {
    if (literal_of(n).find(kComment) != std::string::npos) lines.insert(cmark_node_get_start_line(n));
  }
  if (lines.empty()) return markdown;
  std::string out;
  int line = 1;
  for (std::size_t start = 0; start < markdown.size();) {
    std::size_t end = markdown.find('\n', start);
    end = end == std::string::npos ? markdown.size() : end + 1;
    std::string text = markdown.substr(start, end - start);
    const std::size_t at = text.find(kComment);
    if (lines.count(line) != 0 && at != std::string::npos) text.replace(at, kComment.size(), "[//]: # (end of list)");
    out += text;
    start = end;
    ++line;
  }
  return out;
}

}  // namespace

std::string markdown_text(std::string_view text) {
  // Anywhere: what starts code, emphasis, a link or image ('!' and '(' only
  // after a '[', itself escaped), raw HTML, an entity, a table cell, a
  // strikethrough or (trailing) an ATX heading's closing '#'s.
  static constexpr std::string_view kAnywhere = "\\`*[]<&|~#";
  // At the start only: a list item, a quote.
  static constexpr std::string_view kAtStart = "-+>";
  auto word = [&](std::size_t i) {
    // ASCII only: a Unicode punctuation mark beside '_' lets it open emphasis
    return i < text.size() && static_cast<unsigned char>(text[i]) < 0x80 &&
           std::isalnum(static_cast<unsigned char>(text[i]));
  };
  std::string out;
  out.reserve(text.size() + text.size() / 4);
  bool leading_digits = true;  // every character so far a digit
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = is_control(text[i]) ? ' ' : text[i];
    // '_' inside a word ("contact_ratio") never starts emphasis.
    const bool emphasis = c == '_' && !(i > 0 && word(i - 1) && word(i + 1));
    const bool list_number = (c == '.' || c == ')') && leading_digits && i > 0;
    if (i == 0 && c == ' ') {
      out += "&#32;";
      continue;
    }
    if (kAnywhere.find(c) != std::string_view::npos || (i == 0 && kAtStart.find(c) != std::string_view::npos) ||
        emphasis || list_number) {
      out += '\\';
    }
    out += c;
    leading_digits = leading_digits && c >= '0' && c <= '9';
  }
  return out;
}

std::string markdown_code(std::string_view text) {
  const std::string body = one_line(text);
  if (body.empty()) return "";
  std::size_t longest = 0, run = 0;
  for (char c : body) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(longest + 1, '`');
  // CommonMark strips one space from each end of a code span that has one at
  // both: the padding, not the text's own (a span of spaces only is kept).
  const bool all_spaces = body.find_first_not_of(' ') == std::string::npos;
  const bool pad = !all_spaces && (body.front() == '`' || body.back() == '`' || body.front() == ' ' ||
                                   body.back() == ' ');
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}

std::string markdown_code_cell(std::string_view text) {
  // GFM splits a table row at every '|' not preceded by a backslash, code
  // spans included, and drops that backslash before reading the cell.
  std::string out;
  for (char c : markdown_code(text)) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string markdown_link_destination(std::string_view path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                       c == '.' || c == '_' || c == '~' || c == '/';
    if (plain) {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

bool allowed_link_destination(std::string_view url) {
  std::string u;
  for (char c : url) {
    if (c != '\t' && c != '\n' && c != '\r') u += c;
  }
  std::size_t start = 0;
  while (start < u.size() && static_cast<unsigned char>(u[start]) <= 0x20) ++start;
  u.erase(0, start);
  const std::size_t end = u.find_first_of(":/?#");
  // An entity where a scheme would be ("jav&#x61;script:") is one that was
  // not decoded: never a plain relative path.
  if (u.find('&') < end) return false;
  if (end == std::string::npos || u[end] != ':') return true;  // relative: no scheme
  const std::string scheme = lower(u.substr(0, end));
  return scheme == "http" || scheme == "https" || scheme == "mailto";
}

int unlink_forbidden_destinations(cmark_node* root) {
  const std::vector<cmark_node*> links =
      nodes_where(root, [](cmark_node_type t) { return t == CMARK_NODE_LINK || t == CMARK_NODE_IMAGE; });
  int replaced = 0;
  for (cmark_node* n : links) {
    const char* url = cmark_node_get_url(n);
    if (allowed_link_destination(url != nullptr ? url : "")) continue;
    ++replaced;
    if (cmark_node_get_type(n) == CMARK_NODE_IMAGE) {
      replace(n, literal_node(CMARK_NODE_TEXT, plain_text(n)));
      continue;
    }
    // A link's content (text, emphasis, code) stays where the link was.
    while (cmark_node* child = cmark_node_first_child(n)) cmark_node_insert_before(n, child);
    cmark_node_free(n);
  }
  return replaced;
}

std::string markdown_description(std::string_view markdown) {
  const auto parser = gfm_parser("report.md");
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  const cmark_tree::Document doc(cmark_parser_finish(parser.get()));
  if (!doc) throw std::runtime_error("report.md: cmark-gfm could not parse the study's description");
  raw_html_as_text(doc.get());
  unlink_forbidden_destinations(doc.get());
  char* rendered = cmark_render_commonmark(doc.get(), CMARK_OPT_DEFAULT, 0);
  if (rendered == nullptr) throw std::runtime_error("report.md: cmark-gfm could not render the study's description");
  std::string out(rendered);
  cmark_get_default_mem_allocator()->free(rendered);
  out = without_list_end_comments(out);
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

}  // namespace rackopt::study_report
