// The few cmark-gfm tree operations report.md's quoting (markdown_text.cpp)
// and report.html (report_html.cpp) share: one parser setup, so both read
// Markdown exactly alike, and one way to turn raw HTML into shown text.
// Internal to study_report.
#pragma once

#include <cmark-gfm.h>

#include <memory>
#include <string>
#include <vector>

namespace rackopt::study_report::cmark_tree {

struct NodeFree {
  void operator()(cmark_node* n) const { cmark_node_free(n); }
};
struct ParserFree {
  void operator()(cmark_parser* p) const { cmark_parser_free(p); }
};
using Document = std::unique_ptr<cmark_node, NodeFree>;

// A parser with the extensions GitHub reads report.md with (table,
// strikethrough, autolink). `file` names the file in the runtime_error
// thrown when cmark-gfm cannot make it ("report.md", "report.html").
std::unique_ptr<cmark_parser, ParserFree> gfm_parser(const std::string& file);

// The literal text of `n` ("" when it has none).
std::string literal_of(cmark_node* n);

// What a reader sees of `n`'s content: its text, code and line breaks.
std::string plain_text(cmark_node* n);

// A new node of `type` holding `text` as its literal.
cmark_node* literal_node(cmark_node_type type, const std::string& text);

// Replaces `old_node` with `new_node` in the tree and frees `old_node`.
void replace(cmark_node* old_node, cmark_node* new_node);

// The nodes of the tree under `root` whose type satisfies `wanted`, collected
// first: the tree must not change under the iterator.
template <class Wanted>
std::vector<cmark_node*> nodes_where(cmark_node* root, Wanted wanted) {
  std::vector<cmark_node*> found;
  cmark_iter* it = cmark_iter_new(root);
  for (cmark_event_type ev = cmark_iter_next(it); ev != CMARK_EVENT_DONE; ev = cmark_iter_next(it)) {
    if (ev == CMARK_EVENT_ENTER && wanted(cmark_node_get_type(cmark_iter_get_node(it)))) {
      found.push_back(cmark_iter_get_node(it));
    }
  }
  cmark_iter_free(it);
  return found;
}

// Every raw HTML node under `root` becomes text that shows it (a block as a
// code block): rendered, it is seen, never interpreted.
void raw_html_as_text(cmark_node* root);

}  // namespace rackopt::study_report::cmark_tree
