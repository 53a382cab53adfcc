// User text in report.md: escaped text renders as itself (parsed back with
// cmark-gfm, the parser report.html uses), keeps its line and its table
// cell, and a description keeps its Markdown but no raw HTML and no link
// whose scheme could run anything.
#include "rackopt/study_report/markdown_text.hpp"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace rackopt::study_report {
namespace {

// Texts that mean something to Markdown, HTML or a table.
const std::vector<std::string> kNastyTexts = {
    "plain",
    "the paper's drive",
    "a\nsystem(\"touch owned\")",
    "# heading\n## another",
    "- item\n+ item\n1. first\n2) second",
    "> quote",
    "| a | b |\n|---|---|",
    "a | b \\| c \\\\| d",
    "<!-- comment",
    "<script>alert(1)</script>",
    "<b>bold</b> &amp; &lt; &#x61;",
    "[link](javascript:alert(1))",
    "![img](data:text/html,x)",
    "<javascript:alert(1)>",
    "*em* _em_ __strong__ ~~gone~~ `code` ``two``",
    "snake_case_name_ _lead trail_ “_unicode_”",
    "\\ backslash at the end \\",
    "    indented code",
    " leading space",
    "===",
    "---",
    "***",
    "```\nfence",
    "~~~",
    "1986. a year",
    "trailing #",
    "tab\there\rCR\x01\x1b\x7f",
    "www.example.com http://x.org a@b.org",
    "`` ` ``",
    "`",
    "[ref]\n\n[ref]: javascript:alert(1)",
};

struct NodeFree {
  void operator()(cmark_node* n) const { cmark_node_free(n); }
};
using Doc = std::unique_ptr<cmark_node, NodeFree>;

Doc parse_gfm(const std::string& md) {
  cmark_gfm_core_extensions_ensure_registered();
  cmark_parser* parser = cmark_parser_new(CMARK_OPT_DEFAULT);
  for (const char* name : {"table", "strikethrough", "autolink"}) {
    cmark_parser_attach_syntax_extension(parser, cmark_find_syntax_extension(name));
  }
  cmark_parser_feed(parser, md.data(), md.size());
  Doc doc(cmark_parser_finish(parser));
  cmark_parser_free(parser);
  return doc;
}

// The text a reader sees in `n` (links' text included).
std::string seen_text(cmark_node* n) {
  std::string out;
  for (cmark_node* c = cmark_node_first_child(n); c != nullptr; c = cmark_node_next(c)) {
    const cmark_node_type t = cmark_node_get_type(c);
    if (t == CMARK_NODE_TEXT || t == CMARK_NODE_CODE || t == CMARK_NODE_HTML_INLINE || t == CMARK_NODE_CODE_BLOCK) {
      out += cmark_node_get_literal(c);
    } else if (t == CMARK_NODE_SOFTBREAK || t == CMARK_NODE_LINEBREAK) {
      out += '\n';
    } else {
      out += seen_text(c);
    }
  }
  return out;
}

// Every node of the tree, in document order.
std::vector<cmark_node*> all_nodes(cmark_node* root) {
  std::vector<cmark_node*> out;
  cmark_iter* it = cmark_iter_new(root);
  for (cmark_event_type ev = cmark_iter_next(it); ev != CMARK_EVENT_DONE; ev = cmark_iter_next(it)) {
    if (ev == CMARK_EVENT_ENTER) out.push_back(cmark_iter_get_node(it));
  }
  cmark_iter_free(it);
  return out;
}

std::size_t count_type(cmark_node* root, cmark_node_type type) {
  const auto nodes = all_nodes(root);
  return static_cast<std::size_t>(
      std::count_if(nodes.begin(), nodes.end(), [&](cmark_node* n) { return cmark_node_get_type(n) == type; }));
}

std::string controls_as_spaces(std::string s) {
  for (char& c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  return s;
}

TEST(MarkdownText, AHeadingShowsTheNameAndStaysOneHeading) {
  for (const std::string& name : kNastyTexts) {
    const Doc doc = parse_gfm("# Study: " + markdown_text(name) + "\n\n## Next\n");
    cmark_node* first = cmark_node_first_child(doc.get());
    ASSERT_EQ(cmark_node_get_type(first), CMARK_NODE_HEADING) << name;
    EXPECT_EQ(cmark_node_get_heading_level(first), 1) << name;
    // a heading drops its trailing spaces
    std::string expected = "Study: " + controls_as_spaces(name);
    while (expected.back() == ' ') expected.pop_back();
    EXPECT_EQ(seen_text(first), expected) << markdown_text(name);
    EXPECT_EQ(cmark_node_get_type(cmark_node_next(first)), CMARK_NODE_HEADING) << name;
    EXPECT_EQ(cmark_node_next(cmark_node_next(first)), nullptr) << name;
    EXPECT_EQ(count_type(doc.get(), CMARK_NODE_HTML_INLINE), 0u) << name;
    EXPECT_EQ(count_type(doc.get(), CMARK_NODE_IMAGE), 0u) << name;
  }
}

TEST(MarkdownText, AListItemShowsTheTextAndStaysOneItem) {
  for (const std::string& text : kNastyTexts) {
    const Doc doc = parse_gfm("- " + markdown_text(text) + "\n- next\n");
    cmark_node* list = cmark_node_first_child(doc.get());
    ASSERT_EQ(cmark_node_get_type(list), CMARK_NODE_LIST) << text;
    EXPECT_EQ(cmark_node_next(list), nullptr) << text;
    cmark_node* item = cmark_node_first_child(list);
    cmark_node* paragraph = cmark_node_first_child(item);
    ASSERT_EQ(cmark_node_get_type(paragraph), CMARK_NODE_PARAGRAPH) << markdown_text(text);
    EXPECT_EQ(cmark_node_next(paragraph), nullptr) << text;  // no nested list, quote or code
    std::string expected = controls_as_spaces(text);
    while (expected.back() == ' ') expected.pop_back();
    EXPECT_EQ(seen_text(paragraph), expected) << markdown_text(text);
    EXPECT_EQ(count_type(doc.get(), CMARK_NODE_ITEM), 2u) << text;
  }
}

TEST(MarkdownText, TableCellsKeepTheirColumns) {
  for (const std::string& text : kNastyTexts) {
    const Doc doc = parse_gfm("| a | b | c |\n|---|---|---|\n| " + markdown_text(text) + " | " +
                              markdown_code_cell(text) + " | end |\n\nafter\n");
    cmark_node* table = cmark_node_first_child(doc.get());
    ASSERT_STREQ(cmark_node_get_type_string(table), "table") << text;
    cmark_node* row = cmark_node_next(cmark_node_first_child(table));
    ASSERT_NE(row, nullptr) << text;
    std::vector<std::string> cells;
    for (cmark_node* c = cmark_node_first_child(row); c != nullptr; c = cmark_node_next(c)) cells.push_back(seen_text(c));
    std::string expected = controls_as_spaces(text);
    while (expected.back() == ' ') expected.pop_back();
    ASSERT_EQ(cells.size(), 3u) << markdown_text(text);
    EXPECT_EQ(cells[0], expected) << markdown_text(text);
    EXPECT_EQ(cells[1], controls_as_spaces(text)) << markdown_code_cell(text);
    EXPECT_EQ(cells[2], "end");
    EXPECT_EQ(cmark_node_next(row), nullptr) << text;  // one data row
  }
}

TEST(MarkdownText, ACodeSpanHoldsAnyText) {
  for (const std::string& text : kNastyTexts) {
    const Doc doc = parse_gfm("- file: " + markdown_code(text) + "\n");
    cmark_node* paragraph = cmark_node_first_child(cmark_node_first_child(cmark_node_first_child(doc.get())));
    ASSERT_NE(paragraph, nullptr);
    cmark_node* code = cmark_node_next(cmark_node_first_child(paragraph));
    ASSERT_NE(code, nullptr) << markdown_code(text);
    EXPECT_EQ(cmark_node_get_type(code), CMARK_NODE_CODE) << markdown_code(text);
    EXPECT_EQ(std::string(cmark_node_get_literal(code)), controls_as_spaces(text)) << markdown_code(text);
    EXPECT_EQ(cmark_node_next(code), nullptr) << markdown_code(text);
  }
}

TEST(MarkdownText, OnlyRelativeHttpAndMailtoDestinationsAreAllowed) {
  for (const char* ok : {"pareto.png", "plots/a%20b.png", "#top", "//host/x", "/abs/path", "http://x.org",
                         "HTTPS://x.org/a?b=c:d", "mailto:a@b.org", "a/b:c", "?q=javascript:x"}) {
    EXPECT_TRUE(allowed_link_destination(ok)) << ok;
  }
  for (const char* bad : {"javascript:alert(1)", "JaVaScRiPt:alert(1)", " javascript:x", "\x01javascript:x",
                          "java\tscript:x", "java\nscript:x", "vbscript:x", "data:text/html,x", "file:///etc/passwd",
                          "ftp://x", ":x", "jav&#x61;script:x"}) {
    EXPECT_FALSE(allowed_link_destination(bad)) << bad;
  }
}

TEST(MarkdownText, LinkDestinationsArePathsOnly) {
  EXPECT_EQ(markdown_link_destination("plots/a b.png"), "plots/a%20b.png");
  EXPECT_EQ(markdown_link_destination("javascript:alert(1)"), "javascript%3Aalert%281%29");
  EXPECT_EQ(markdown_link_destination("a)\n<b>"), "a%29%0A%3Cb%3E");
  EXPECT_EQ(markdown_link_destination("/tmp/run-1/x_y.~"), "/tmp/run-1/x_y.~");
}

// A description keeps its Markdown, loses raw HTML and forbidden links, and
// cannot swallow what report.md writes after it.
TEST(MarkdownDescription, KeepsMarkdownDropsHtmlAndForbiddenLinks) {
  const std::string description =
      "Intro with *emphasis*, `code` and [a link](https://example.org) and [mail](mailto:a@b.org) "
      "and [rel](notes/a.md).\n\n"
      "- one\n- two\n\n"
      "[js](javascript:alert(1)) [JS](JaVaScRiPt:alert(2)) [ent](jav&#x61;script:alert(3)) "
      "[vb](vbscript:x) ![data](data:image/png;base64,AAAA) <javascript:alert(4)> [ref][r]\n\n"
      "[r]: javascript:alert(5)\n\n"
      "<b onclick=\"x()\">inline html</b>\n\n"
      "<!-- an unclosed comment\n\n```\nan unclosed fence";
  const std::string md = markdown_description(description) + "\n\n## After\n\n| a |\n|---|\n| 1 |\n";
  const Doc doc = parse_gfm(md);
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_HTML_BLOCK), 0u) << md;
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_HTML_INLINE), 0u) << md;
  std::vector<std::string> urls;
  for (cmark_node* n : all_nodes(doc.get())) {
    const cmark_node_type t = cmark_node_get_type(n);
    if (t == CMARK_NODE_LINK || t == CMARK_NODE_IMAGE) urls.push_back(cmark_node_get_url(n));
  }
  EXPECT_EQ(urls, (std::vector<std::string>{"https://example.org", "mailto:a@b.org", "notes/a.md"})) << md;
  // the text of the dropped links and the HTML is still shown
  const std::string all = seen_text(doc.get());
  for (const char* shown : {"js", "vb", "data", "inline html", "<b onclick=\"x()\">", "<!-- an unclosed comment",
                            "an unclosed fence", "javascript:alert(4)", "ref"}) {
    EXPECT_NE(all.find(shown), std::string::npos) << shown << "\n" << md;
  }
  // what follows the description is still a heading and a table
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_HEADING), 1u) << md;
  std::size_t tables = 0;
  for (cmark_node* n : all_nodes(doc.get())) tables += std::string(cmark_node_get_type_string(n)) == "table";
  EXPECT_EQ(tables, 1u) << md;
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_LIST), 1u) << md;
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_EMPH), 1u) << md;
}

// The CommonMark renderer separates a list from a following list or code
// block with "<!-- end list -->": the description carries no such HTML, and
// the blocks stay apart.
TEST(MarkdownDescription, AdjacentListsAndCodeStayApartWithoutHtml) {
  const std::string md = markdown_description("- a\n- b\n\n\n* c\n\n1. d\n\n       indented code\n");
  EXPECT_EQ(md.find("<!--"), std::string::npos) << md;
  const Doc doc = parse_gfm(md);
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_HTML_BLOCK), 0u) << md;
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_LIST), 3u) << md;
  EXPECT_EQ(count_type(doc.get(), CMARK_NODE_CODE_BLOCK), 1u) << md;
  EXPECT_EQ(seen_text(doc.get()), "abcdindented code\n") << md;
}

TEST(MarkdownDescription, PlainTextComesBackAsWritten) {
  EXPECT_EQ(markdown_description("A synthetic study of two variables."), "A synthetic study of two variables.");
  EXPECT_EQ(markdown_description("First paragraph.\n\nSecond paragraph."), "First paragraph.\n\nSecond paragraph.");
}

}  // namespace
}  // namespace rackopt::study_report
