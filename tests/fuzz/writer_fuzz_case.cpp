#include "writer_fuzz_case.hpp"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>

#include "rackopt/metrics/metric_registry.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/output/wear_report.hpp"
#include "rackopt/study/study_result.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/study_report/design_tables.hpp"
#include "rackopt/study_report/markdown_text.hpp"
#include "rackopt/study_report/report_html.hpp"
#include "rackopt/study_report/report_markdown.hpp"
#include "rackopt/study_report/study_plots.hpp"
#include "rackopt/study_report/study_report.hpp"

namespace rackopt::fuzz {
namespace {

using namespace rackopt::study;
using namespace rackopt::study_report;

// --- the study the texts go into ---------------------------------------------

DesignVariable length_variable(const std::string& key, double lo, double hi) {
  DesignVariable v;
  v.key = key;
  v.kind = QuantityKind::kLength;
  v.unit = "mm";
  v.lower = lo;
  v.upper = hi;
  return v;
}

// A pareto study of two objectives (the fuzzed label and a second one made
// from it, so the two never meet), one constraint, two variables.
StudySpec spec_of(const WriterTexts& t, StudyKind kind) {
  StudySpec s;
  s.name = t.name;
  s.description = t.description;
  s.file = t.path;
  s.problem_path = t.path;
  s.problem_overrides = {t.path};
  s.kind = kind;
  s.variables = {length_variable(t.variable_key, 0.02, 0.032), length_variable("rack.span", 1.2, 3.0)};
  const metrics::MetricRequest request = metrics::resolve_request(metrics::parse_metric_request("min_stiffness"));
  for (const std::string& label : {t.metric_label, t.metric_label + " #2"}) {
    ObjectiveSpec o;
    o.metric = request;
    o.label = label;
    s.objectives.push_back(o);
  }
  ConstraintSpec c;
  c.metric = request;
  c.label = t.metric_label;
  c.min = 1.3;
  s.constraints.push_back(c);
  return s;
}

DesignResult design_of(const StudySpec& spec, const WriterTexts& t, double a) {
  DesignResult d;
  d.x = {0.02 + 0.01 * a, 3.0 - a};
  d.metric_labels = {spec.objectives[0].label, spec.objectives[1].label};
  d.metric_values = {a, 1 - a};
  d.metric_ok = {true, true};
  d.objectives = {a, 1 - a};
  d.ok = true;
  d.feasible = true;
  d.label = t.message;
  d.message = t.message;
  d.warnings = {t.message};
  return d;
}

StudyResult result_of(const StudySpec& spec, const WriterTexts& t) {
  StudyResult r;
  r.status = StudyStatus::kOk;
  for (int k = 0; k < 3; ++k) r.front.push_back(design_of(spec, t, 0.5 * k));
  r.chosen = 1;
  r.sweep_points = r.front;
  r.best = r.front[0];
  r.evaluations = 5;
  r.best_history = {3, 2, 2, 1, 1};
  r.solver_message = t.message;
  r.warnings = {t.message};
  return r;
}

// Every plot script a study or a run writes, by name.
std::map<std::string, std::string> scripts_of(const WriterTexts& t) {
  std::map<std::string, std::string> out;
  const StudySpec pareto = spec_of(t, StudyKind::kPareto);
  const StudyResult r = result_of(pareto, t);
  const std::vector<std::string> labels = metric_labels(pareto, r);
  if (const auto front = front_table(pareto, labels, r)) out["pareto.gp"] = pareto_gnuplot(pareto, *front, "");
  out["history.gp"] = history_gnuplot(pareto, t.metric_label, r.best_history.size());
  out["hypervolume.gp"] = hypervolume_gnuplot(pareto, r.best_history.size());
  const StudySpec sweep = spec_of(t, StudyKind::kSweep);
  if (const auto table = sweep_table(sweep, labels, r)) out["sweep.gp"] = sweep_gnuplot(sweep, *table, labels);
  out["stiffness.gp"] = stiffness_gnuplot(StiffnessCurve{}, t.name, "stiffness.csv", "stiffness.png.tmp");
  out["wear_profile.gp"] = wear_profile_gnuplot(t.name, WearLifeResult{});
  out["life_histogram.gp"] = life_histogram_gnuplot(t.name);
  out["reliability.gp"] = reliability_gnuplot(t.name);
  return out;
}

// --- gnuplot ---------------------------------------------------------------------

std::size_t line_count(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

// The rules for one script line: strings close, and what is outside them
// starts no command of its own.
void check_gnuplot_line(const std::string& script, const std::string& line, std::vector<std::string>& broken) {
  if (line.empty() || line[0] == '#') return;
  std::string outside;
  char quote = '\0';
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote == '\'') {
      if (c == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
        ++i;  // a doubled quote inside the string
      } else if (c == '\'') {
        quote = '\0';
      }
    } else if (quote == '"') {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        quote = '\0';
      }
    } else if (c == '\'' || c == '"') {
      quote = c;
      outside += ' ';
    } else {
      outside += c;
    }
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t') broken.push_back(script + ": a control character: " + line);
  }
  if (quote != '\0') broken.push_back(script + ": a string left open at the end of the line: " + line);
  if (outside.find_first_of("`@") != std::string::npos) broken.push_back(script + ": ` or @ outside a string: " + line);
  for (const char* word : {"system", "load", "call", "eval", "shell", "cd "}) {
    if (outside.find(word) != std::string::npos) broken.push_back(script + ": '" + word + "' outside a string: " + line);
  }
  const std::size_t first = outside.find_first_not_of(' ');
  if (first != std::string::npos && outside[first] == '!') broken.push_back(script + ": a shell command: " + line);
}

void check_gnuplot(const WriterTexts& t, std::vector<std::string>& broken) {
  // The reference keeps the key and the label: they pick the tables' columns
  // (a label may name a real metric), so only the free texts are made plain.
  const std::map<std::string, std::string> plain =
      scripts_of(WriterTexts{"x", "x", t.variable_key, t.metric_label, "x", "x"});
  const std::map<std::string, std::string> scripts = scripts_of(t);
  for (const auto& [name, script] : scripts) {
    const auto reference = plain.find(name);
    if (reference == plain.end()) {
      broken.push_back(name + ": written only for this input");
      continue;
    }
    if (line_count(script) != line_count(reference->second)) {
      broken.push_back(name + ": " + std::to_string(line_count(script)) + " lines, " +
                       std::to_string(line_count(reference->second)) + " from plain text");
    }
    for (auto& b : gnuplot_script_problems(name, script)) broken.push_back(std::move(b));
  }
}

// --- report.md -------------------------------------------------------------------

struct NodeFree {
  void operator()(cmark_node* n) const { cmark_node_free(n); }
};

std::unique_ptr<cmark_node, NodeFree> parse_gfm(const std::string& md) {
  static std::once_flag registered;
  std::call_once(registered, [] { cmark_gfm_core_extensions_ensure_registered(); });
  cmark_parser* parser = cmark_parser_new(CMARK_OPT_DEFAULT);
  for (const char* name : {"table", "strikethrough", "autolink"}) {
    cmark_parser_attach_syntax_extension(parser, cmark_find_syntax_extension(name));
  }
  cmark_parser_feed(parser, md.data(), md.size());
  std::unique_ptr<cmark_node, NodeFree> doc(cmark_parser_finish(parser));
  cmark_parser_free(parser);
  return doc;
}

std::string text_of(cmark_node* n) {
  std::string out;
  for (cmark_node* c = cmark_node_first_child(n); c != nullptr; c = cmark_node_next(c)) {
    const char* literal = cmark_node_get_literal(c);
    out += literal != nullptr ? literal : text_of(c);
  }
  return out;
}

}  // namespace

std::vector<std::string> markdown_problems(const std::string& md) {
  std::vector<std::string> broken;
  const auto doc = parse_gfm(md);
  cmark_node* first = cmark_node_first_child(doc.get());
  if (first == nullptr || cmark_node_get_type(first) != CMARK_NODE_HEADING || cmark_node_get_heading_level(first) != 1) {
    broken.push_back("report.md: the first block is not the level-1 heading");
  }
  std::size_t level_one = 0;
  bool outcome = false;
  cmark_iter* it = cmark_iter_new(doc.get());
  for (cmark_event_type ev = cmark_iter_next(it); ev != CMARK_EVENT_DONE; ev = cmark_iter_next(it)) {
    if (ev != CMARK_EVENT_ENTER) continue;
    cmark_node* n = cmark_iter_get_node(it);
    const cmark_node_type type = cmark_node_get_type(n);
    if (type == CMARK_NODE_HTML_BLOCK || type == CMARK_NODE_HTML_INLINE) {
      broken.push_back("report.md: raw HTML: " + std::string(cmark_node_get_literal(n)));
    }
    if (type == CMARK_NODE_LINK || type == CMARK_NODE_IMAGE) {
      const std::string url = cmark_node_get_url(n);
      if (!allowed_link_destination(url)) broken.push_back("report.md: a link to " + url);
    }
    if (type == CMARK_NODE_HEADING && cmark_node_get_heading_level(n) == 1) ++level_one;
    if (type == CMARK_NODE_HEADING && cmark_node_get_heading_level(n) == 2 && text_of(n) == "Outcome") outcome = true;
  }
  cmark_iter_free(it);
  if (!outcome) broken.push_back("report.md: the report's \"## Outcome\" heading is gone");
  (void)level_one;  // a description may hold headings of its own
  return broken;
}

namespace {

// --- report.html -----------------------------------------------------------------

const std::set<std::string> kTags = {"p",  "h1", "h2", "h3",    "h4",    "h5",    "h6", "ul",  "ol",
                                     "li", "a",  "em", "strong", "code",  "pre",   "del", "br", "hr",
                                     "blockquote", "table", "thead", "tbody", "tr", "th", "td"};
const std::set<std::string> kAttributes = {"href", "title", "class", "align", "start"};

// `value` of an attribute as the browser reads it: cmark writes &amp; and
// &#x27; in an href; any other entity there is not its own.
bool decode_href(const std::string& value, std::string& decoded) {
  decoded.clear();
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (value[i] != '&') {
      decoded += value[i];
    } else if (value.compare(i, 5, "&amp;") == 0) {
      decoded += '&';
      i += 4;
    } else if (value.compare(i, 6, "&#x27;") == 0) {
      decoded += '\'';
      i += 5;
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::string> html_problems(const std::string& html) {
  std::vector<std::string> broken;
  const std::size_t main_start = html.find("<main>\n");
  const std::size_t main_end = html.rfind("</main>");
  if (main_start == std::string::npos || main_end == std::string::npos || main_end < main_start) {
    broken.push_back("report.html: no <main>");
    return broken;
  }
  if (html.find("<!--") != std::string::npos) broken.push_back("report.html: an HTML comment");
  const std::string body = html.substr(main_start + 7, main_end - main_start - 7);
  for (std::size_t at = body.find('<'); at != std::string::npos; at = body.find('<', at + 1)) {
    std::size_t i = at + 1;
    if (i < body.size() && body[i] == '/') ++i;
    std::string tag;
    while (i < body.size() && std::isalnum(static_cast<unsigned char>(body[i]))) tag += body[i++];
    if (kTags.count(tag) == 0) {
      broken.push_back("report.html: a <" + tag + "> tag: " + body.substr(at, 60));
      continue;
    }
    // attributes: name="value" ... up to '>' or '/>'
    while (i < body.size() && body[i] != '>') {
      if (body[i] == ' ' || body[i] == '/') {
        ++i;
        continue;
      }
      std::string name;
      while (i < body.size() && std::isalpha(static_cast<unsigned char>(body[i]))) name += body[i++];
      if (name.empty() || i + 1 >= body.size() || body[i] != '=' || body[i + 1] != '"') {
        broken.push_back("report.html: a malformed tag: " + body.substr(at, 80));
        break;
      }
      const std::size_t close = body.find('"', i + 2);
      if (close == std::string::npos) {
        broken.push_back("report.html: an attribute left open");
        break;
      }
      const std::string value = body.substr(i + 2, close - i - 2);
      i = close + 1;
      if (kAttributes.count(name) == 0) broken.push_back("report.html: a " + name + "= attribute");
      std::string url;
      if (name == "href" && (!decode_href(value, url) || !allowed_link_destination(url))) {
        broken.push_back("report.html: a link to " + value);
      }
    }
  }
  return broken;
}

std::vector<std::string> gnuplot_script_problems(const std::string& name, const std::string& script) {
  std::vector<std::string> broken;
  std::size_t start = 0;
  while (start < script.size()) {
    std::size_t end = script.find('\n', start);
    if (end == std::string::npos) end = script.size();
    check_gnuplot_line(name, script.substr(start, end - start), broken);
    start = end + 1;
  }
  return broken;
}

WriterTexts writer_texts(std::string_view data) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (fields.size() < 6) {
    const std::size_t end = data.find('\0', start);
    fields.emplace_back(data.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  fields.resize(6, "x");
  return WriterTexts{fields[0], fields[1], fields[2], fields[3], fields[4], fields[5]};
}

std::vector<std::string> check_writers(const WriterTexts& texts) {
  std::vector<std::string> broken;
  check_gnuplot(texts, broken);
  const StudySpec spec = spec_of(texts, StudyKind::kPareto);
  const std::string md =
      report_markdown(spec, result_of(spec, texts), ReportFiles{}, {texts.message}, std::filesystem::path("."));
  for (auto& b : markdown_problems(md)) broken.push_back(std::move(b));
  for (auto& b : html_problems(report_html(md, "Study: " + spec.name, {}))) broken.push_back(std::move(b));
  return broken;
}

void run_writer_fuzz_case(std::string_view data) {
  const std::vector<std::string> broken = check_writers(writer_texts(data));
  if (broken.empty()) return;
  std::string all;
  for (const auto& b : broken) all += b + "\n";
  throw std::logic_error(all);
}

}  // namespace rackopt::fuzz
