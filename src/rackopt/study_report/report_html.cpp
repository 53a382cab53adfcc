#include "rackopt/study_report/report_html.hpp"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "rackopt/study_report/cmark_tree.hpp"
#include "rackopt/study_report/markdown_text.hpp"

namespace rackopt::study_report {
namespace {

using namespace cmark_tree;

// Small enough to read in the source, enough for tables that line up, plots
// that scale with the window and a page that prints. A table whose header
// row is empty (report.md's two-column design tables) shows no header.
constexpr const char* kStyle = R"(
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
       line-height: 1.5; color: #1b1b1b; background: #fff; margin: 0; }
main { max-width: 72rem; margin: 0 auto; padding: 1rem 1.5rem 3rem; }
h1, h2, h3 { line-height: 1.25; }
h2 { border-bottom: 1px solid #d0d7de; padding-bottom: .2em; margin-top: 2em; }
table { border-collapse: collapse; margin: 1em 0; font-variant-numeric: tabular-nums;
        display: block; overflow-x: auto; max-width: 100%; }
th, td { border: 1px solid #d0d7de; padding: .3em .7em; text-align: left; vertical-align: top; }
thead th { background: #f3f5f7; }
thead:not(:has(th:not(:empty))) { display: none; }
tbody tr:nth-child(even) { background: #fafbfc; }
code { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; font-size: .9em;
       background: #f3f5f7; padding: .1em .3em; border-radius: 3px; }
pre { background: #f6f8fa; padding: .8em 1em; overflow-x: auto; border-radius: 4px; }
pre code { background: none; padding: 0; }
body { overflow-x: hidden; }
figure.plot { margin: 1.5em 0 .3em; width: calc(100vw - 3rem); position: relative; left: 50%;
              transform: translateX(-50%); }
figure.plot svg { display: block; width: 100%; height: auto; border: 1px solid #e1e4e8; }
figcaption { font-weight: 600; margin-top: .4em; }
figure.plot + p { margin-top: .2em; color: #444; }
@media print { main { max-width: none; }
               figure.plot { width: 100%; left: 0; transform: none; break-inside: avoid; } }
)";

bool starts_with(const std::string& s, std::size_t at, const char* prefix) {
  return s.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

// Within one tag `tag` of an SVG: ids and references to them prefixed.
std::string prefix_ids(const std::string& tag, const std::string& prefix) {
  static const char* const kPatterns[] = {" id='", " id=\"", "\nid='", "\nid=\"", "\tid='", "\tid=\"",
                                          "href='#", "href=\"#", "url(#"};
  std::string out;
  out.reserve(tag.size() + 16);
  for (std::size_t i = 0; i < tag.size();) {
    bool hit = false;
    for (const char* p : kPatterns) {
      if (starts_with(tag, i, p)) {
        out += p;
        out += prefix;
        i += std::char_traits<char>::length(p);
        hit = true;
        break;
      }
    }
    if (!hit) out += tag[i++];
  }
  return out;
}

// The root tag without its width and height attributes (the viewBox keeps
// the aspect ratio; CSS gives the width).
std::string without_fixed_size(const std::string& tag) {
  if (tag.find("viewBox=") == std::string::npos) return tag;
  std::string out = tag;
  for (const char* attribute : {"width=", "height="}) {
    for (std::size_t at = out.find(attribute); at != std::string::npos; at = out.find(attribute, at)) {
      const bool own = at > 0 && (out[at - 1] == ' ' || out[at - 1] == '\n' || out[at - 1] == '\t');
      const std::size_t q = at + std::char_traits<char>::length(attribute);
      if (!own || q >= out.size() || (out[q] != '"' && out[q] != '\'')) {
        ++at;
        continue;
      }
      const std::size_t end = out.find(out[q], q + 1);
      if (end == std::string::npos) break;
      out.erase(at, end + 1 - at);
    }
  }
  return out;
}

// The width of the SVG's viewBox ("" when it has none): the figure is shown
// at most that wide, its drawn size.
std::string view_box_width(const std::string& svg) {
  const std::size_t end = svg.find('>');
  const std::size_t at = svg.find("viewBox=\"");
  if (at == std::string::npos || at > end) return "";
  std::istringstream in(svg.substr(at + 9, svg.find('"', at + 9) - at - 9));
  double x = 0, y = 0, w = 0;
  if (!(in >> x >> y >> w) || !(w > 0) || w > 1e5) return "";
  return std::to_string(static_cast<long>(std::lround(w)));
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string inline_svg(const std::string& svg_text, const std::string& id_prefix) {
  std::size_t start = std::string::npos;
  for (std::size_t at = svg_text.find("<svg"); at != std::string::npos; at = svg_text.find("<svg", at + 1)) {
    const char next = at + 4 < svg_text.size() ? svg_text[at + 4] : '\0';
    if (next == ' ' || next == '\n' || next == '\r' || next == '\t' || next == '>') {
      start = at;
      break;
    }
  }
  if (start == std::string::npos) return "";
  std::string out;
  out.reserve(svg_text.size() - start + 64);
  bool root = true;
  for (std::size_t i = start; i < svg_text.size();) {
    if (svg_text[i] != '<') {
      const std::size_t lt = svg_text.find('<', i);
      const std::size_t end = lt == std::string::npos ? svg_text.size() : lt;
      out.append(svg_text, i, end - i);
      i = end;
      continue;
    }
    // One tag: up to the first '>' outside a quoted attribute value.
    std::size_t j = i + 1;
    char quote = '\0';
    for (; j < svg_text.size(); ++j) {
      const char c = svg_text[j];
      if (quote != '\0') {
        if (c == quote) quote = '\0';
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        break;
      }
    }
    const std::size_t end = j < svg_text.size() ? j + 1 : svg_text.size();
    std::string tag = prefix_ids(svg_text.substr(i, end - i), id_prefix);
    if (root) tag = without_fixed_size(tag);
    root = false;
    out += tag;
    i = end;
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' ')) out.pop_back();
  return out;
}

std::string report_html(const std::string& markdown, const std::string& title,
                        const std::map<std::string, std::string>& svg_by_target) {
  const auto parser = gfm_parser("report.html");
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  const Document doc(cmark_parser_finish(parser.get()));
  if (!doc) throw std::runtime_error("report.html: cmark-gfm could not parse report.md");

  // report.md writes user text escaped and a description filtered
  // (markdown_text.hpp); the page checks its links once more, so that
  // whatever Markdown it is given, it carries no javascript:, data: or other
  // link that is not relative, http(s) or mailto.
  unlink_forbidden_destinations(doc.get());

  // The page is rendered with raw HTML allowed (the figures are raw HTML), so
  // the markdown's own raw HTML becomes text first: shown, never interpreted.
  raw_html_as_text(doc.get());
  for (cmark_node* image : nodes_where(doc.get(), [](cmark_node_type t) { return t == CMARK_NODE_IMAGE; })) {
    const char* url_text = cmark_node_get_url(image);
    const std::string url = url_text != nullptr ? url_text : "";
    const std::string alt = plain_text(image);
    const auto svg = svg_by_target.find(url);
    if (svg == svg_by_target.end() || svg->second.empty()) {
      // No picture of our own: a link to the file keeps the page free of
      // anything it would have to load.
      cmark_node* link = cmark_node_new(CMARK_NODE_LINK);
      cmark_node_set_url(link, url.c_str());
      cmark_node_append_child(link, literal_node(CMARK_NODE_TEXT, alt.empty() ? url : alt));
      replace(image, link);
      continue;
    }
    // On a wide window a figure may grow past the text's column, up to its
    // drawn size: the multi-panel plots are wide.
    const std::string w = view_box_width(svg->second);
    const std::string figure = "<figure class=\"plot\"" +
                               (w.empty() ? std::string() : " style=\"max-width: " + w + "px\"") + ">\n" +
                               svg->second + "\n<figcaption>" + html_escape(alt) + "</figcaption>\n</figure>\n";
    cmark_node* parent = cmark_node_parent(image);
    const bool alone = parent != nullptr && cmark_node_get_type(parent) == CMARK_NODE_PARAGRAPH &&
                       cmark_node_first_child(parent) == image && cmark_node_next(image) == nullptr;
    if (alone) {
      replace(parent, literal_node(CMARK_NODE_HTML_BLOCK, figure));  // a figure cannot sit inside a <p>
    } else {
      replace(image, literal_node(CMARK_NODE_HTML_INLINE, "<span class=\"plot\">" + svg->second + "</span>"));
    }
  }

  char* body = cmark_render_html(doc.get(), CMARK_OPT_UNSAFE, cmark_parser_get_syntax_extensions(parser.get()));
  if (body == nullptr) throw std::runtime_error("report.html: cmark-gfm could not render report.md");
  const std::string body_text(body);
  cmark_get_default_mem_allocator()->free(body);

  std::string page;
  page.reserve(body_text.size() + 4096);
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  // Nothing to fetch: the policy makes that hold even for a link typed into
  // a study's description as an image.
  page += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<meta name=\"generator\" content=\"rackopt\">\n";
  page += "<title>" + html_escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<main>\n";
  page += body_text;
  page += "</main>\n</body>\n</html>\n";
  return page;
}

}  // namespace rackopt::study_report
