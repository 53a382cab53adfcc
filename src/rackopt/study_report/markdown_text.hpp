// User text (a study's name and description, file paths, --set overrides,
// messages, warnings, labels) written into report.md: every such text goes
// through one of these functions, so that the page shows it as text and it
// can neither add Markdown structure (a heading, a table row, a list) nor
// carry raw HTML or a link that runs anything. report.html is rendered from
// report.md and checks its links again (report_html.cpp).
#pragma once

#include <string>
#include <string_view>

struct cmark_node;

namespace rackopt::study_report {

// `text` as inline Markdown that renders as the text itself, in running
// text, a heading, a list item or a GFM table cell. Backslash-escaped: what
// can start Markdown anywhere (\ ` * [ ] < & | ~ #), '_' at a word's edge,
// a leading - + > (a list, a quote), and a '.' or ')' after leading digits
// (an ordered list); a leading space becomes &#32; (no indented code); every
// control character (line breaks, tab, CR) becomes a space, so the text stays
// on its line. The rest means nothing once '[' and '<' are escaped and is
// kept, so report.md stays readable as plain text ("contact_ratio").
std::string markdown_text(std::string_view text);

// `text` as one code span (file paths, --set overrides): fenced by more
// backticks than the longest run inside, padded when it starts or ends with
// a backtick or a space, control characters as spaces. For a GFM table cell
// use markdown_code_cell: a '|' there must be escaped even inside code.
std::string markdown_code(std::string_view text);
std::string markdown_code_cell(std::string_view text);

// A file path as a Markdown link destination: every byte other than ASCII
// letters, digits and - . _ ~ / percent-encoded (RFC 3986), so a path with
// spaces, parentheses, '<', ':' or a line break stays one relative or
// absolute path and never reads as a scheme. "plots/a b.png" ->
// "plots/a%20b.png".
std::string markdown_link_destination(std::string_view path);

// A study's free-form description as Markdown of its own: paragraphs, lists,
// emphasis, code, tables and links are kept; raw HTML (tags, comments, an
// unclosed "<!--") becomes a code block or text that shows it; a link or
// image whose destination is not allowed (allowed_link_destination) becomes
// its text. The description is parsed with cmark-gfm and rendered back with
// its CommonMark renderer: the parser decides what the text means exactly as
// report.html's renderer will (no second guess by hand), and the renderer
// closes every block, so no unclosed code fence or HTML block in a
// description can swallow the report that follows it (where the renderer
// would end a list with "<!-- end list -->", an empty link reference
// definition "[//]: # (end of list)" does that without HTML).
std::string markdown_description(std::string_view markdown);

// True for a link destination a report may carry: relative ("plots/a.png",
// "#top", "//host/x"), http:, https: or mailto:, scheme in any case, after
// dropping leading spaces and control characters and every tab and line
// break (browsers ignore them). False for every other scheme (javascript:,
// vbscript:, data:, file:, ...), and for an '&' before the first of : / ? #
// (an entity left undecoded, "jav&#x61;script:"; cmark-gfm decodes them in
// the destinations it gives).
bool allowed_link_destination(std::string_view url);

// In the cmark-gfm tree under `root`: every LINK or IMAGE node whose
// destination is not allowed is replaced by its content as plain text
// (an image by its alt text). Returns how many were replaced.
int unlink_forbidden_destinations(cmark_node* root);

}  // namespace rackopt::study_report
