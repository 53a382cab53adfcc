#include "rackopt/study_report/cmark_tree.hpp"

#include <cmark-gfm-core-extensions.h>

#include <mutex>
#include <stdexcept>

namespace rackopt::study_report::cmark_tree {

std::unique_ptr<cmark_parser, ParserFree> gfm_parser(const std::string& file) {
  static std::once_flag registered;
  std::call_once(registered, [] { cmark_gfm_core_extensions_ensure_registered(); });
  std::unique_ptr<cmark_parser, ParserFree> parser(cmark_parser_new(CMARK_OPT_DEFAULT));
  if (!parser) throw std::runtime_error(file + ": cmark-gfm could not make a parser");
  for (const char* name : {"table", "strikethrough", "autolink"}) {
    cmark_syntax_extension* ext = cmark_find_syntax_extension(name);
    if (ext == nullptr) throw std::runtime_error(file + ": cmark-gfm has no '" + name + "' extension");
    cmark_parser_attach_syntax_extension(parser.get(), ext);
  }
  return parser;
}

std::string literal_of(cmark_node* n) {
  const char* s = cmark_node_get_literal(n);
  return s != nullptr ? s : "";
}

std::string plain_text(cmark_node* n) {
  std::string out;
  for (cmark_node* c = cmark_node_first_child(n); c != nullptr; c = cmark_node_next(c)) {
    const cmark_node_type t = cmark_node_get_type(c);
    if (t == CMARK_NODE_TEXT || t == CMARK_NODE_CODE || t == CMARK_NODE_HTML_INLINE) {
      out += literal_of(c);
    } else if (t == CMARK_NODE_SOFTBREAK || t == CMARK_NODE_LINEBREAK) {
      out += ' ';
    } else {
      out += plain_text(c);
    }
  }
  return out;
}

cmark_node* literal_node(cmark_node_type type, const std::string& text) {
  cmark_node* n = cmark_node_new(type);
  cmark_node_set_literal(n, text.c_str());
  return n;
}

void replace(cmark_node* old_node, cmark_node* new_node) {
  cmark_node_replace(old_node, new_node);
  cmark_node_free(old_node);
}

void raw_html_as_text(cmark_node* root) {
  const std::vector<cmark_node*> raw_html =
      nodes_where(root, [](cmark_node_type t) { return t == CMARK_NODE_HTML_INLINE || t == CMARK_NODE_HTML_BLOCK; });
  for (cmark_node* n : raw_html) {
    const bool block = cmark_node_get_type(n) == CMARK_NODE_HTML_BLOCK;
    replace(n, literal_node(block ? CMARK_NODE_CODE_BLOCK : CMARK_NODE_TEXT, literal_of(n)));
  }
}

}  // namespace rackopt::study_report::cmark_tree
