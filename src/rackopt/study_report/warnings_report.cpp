#include "rackopt/study_report/warnings_report.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "rackopt/core/text.hpp"
#include "rackopt/study_report/markdown_text.hpp"

namespace rackopt::study_report {

using study::WarningGroup;
using study::WarningTally;
using study::warning_kind;

namespace {

bool best_gave(const ReportWarnings& w, const WarningGroup& g) {
  return std::any_of(w.best.begin(), w.best.end(), [&](const std::string& b) { return warning_kind(b) == g.kind; });
}

// "448 designs (evaluations 3, 7, 12, …)", "evaluation 12", "3 messages", "".
std::string origin_text(const WarningGroup& g, std::size_t max_ids) {
  std::ostringstream o;
  if (!g.evaluations.empty()) {
    if (g.designs == 1) return "evaluation " + std::to_string(g.evaluations.front());
    o << g.designs << " designs (evaluations ";
    const std::size_t shown = std::min(max_ids, g.evaluations.size());
    for (std::size_t i = 0; i < shown; ++i) o << (i ? ", " : "") << g.evaluations[i];
    if (g.designs > shown) o << ", …";
    o << ")";
  } else if (g.designs > 1) {
    o << g.designs << " designs";
  } else if (g.messages > 1) {
    o << g.messages << " messages";
  }
  return o.str();
}

// Whether any group stands for more than one message or names its designs
// (the heading then says "by kind").
bool any_grouped(const std::vector<WarningGroup>& groups) {
  return std::any_of(groups.begin(), groups.end(), [](const WarningGroup& g) {
    return g.messages > 1 || g.designs > 1 || !g.evaluations.empty();
  });
}

// The message, or the kind when the group holds several messages.
std::string headline(const WarningGroup& g) { return g.messages > 1 ? g.kind : g.example; }

}  // namespace

ReportWarnings report_warnings(const study::StudySpec& spec, const study::StudyResult& r,
                               const std::vector<std::string>& run_warnings) {
  ReportWarnings w;
  if (spec.kind == study::StudyKind::kPareto) w.design = "chosen design";
  if (spec.kind == study::StudyKind::kEvaluate || spec.kind == study::StudyKind::kReliability) w.design = "design";
  if (r.best) {
    w.best = r.best->warnings;
    w.best_evaluation = r.best->evaluation_id;
  }
  w.groups = r.warning_groups;
  w.kinds_dropped = r.warning_kinds_dropped;
  if (w.groups.empty()) {
    WarningTally from_text;
    for (const std::string& m : r.warnings) from_text.add({m}, 0);
    w.groups = from_text.groups();
    w.kinds_dropped += from_text.dropped();
  }
  // The report's own warnings (plots, the stiffness curve): those of
  // run_warnings that are not the designs'.
  const std::set<std::string> of_designs(r.warnings.begin(), r.warnings.end());
  WarningTally own;
  for (const std::string& m : run_warnings)
    if (!of_designs.count(m)) own.add({m}, 0);
  for (WarningGroup g : own.groups()) {
    g.designs = 0;
    w.groups.push_back(std::move(g));
  }
  w.kinds_dropped += own.dropped();
  return w;
}

std::vector<WarningGroup> other_warning_groups(const ReportWarnings& w) {
  std::vector<WarningGroup> out;
  for (const WarningGroup& g : w.groups) {
    const bool only_best = g.designs == 1 && best_gave(w, g) &&
                           (g.evaluations.empty() ? std::find(w.best.begin(), w.best.end(), g.example) != w.best.end()
                                                  : g.evaluations.front() == w.best_evaluation);
    if (!only_best) out.push_back(g);
  }
  return out;
}

std::string warning_group_text(const WarningGroup& g, std::size_t max_ids, bool with_example) {
  std::string out = headline(g);
  const std::string origin = origin_text(g, max_ids);
  if (!origin.empty()) out += " — " + origin;
  if (with_example && g.messages > 1) out += "; for example: " + g.example;
  return out;
}

std::string warnings_markdown(const ReportWarnings& w) {
  const std::vector<WarningGroup> others = other_warning_groups(w);
  std::ostringstream o;
  if (!w.best.empty()) {
    o << "## Warnings of the " << w.design;
    if (w.best_evaluation > 0) o << " (evaluation " << w.best_evaluation << ")";
    o << "\n\n";
    for (const std::string& m : w.best) o << "- " << markdown_text(m) << "\n";
    o << "\n";
  }
  if (!others.empty()) {
    const bool grouped = any_grouped(others);
    o << (w.best.empty() ? "## Warnings" : "## Other warnings of the run") << (grouped ? ", by kind" : "") << "\n\n";
    if (grouped)
      o << "Each kind once, its numbers shown as …, with the designs that gave it (their `id` in "
           "evaluations.csv) and one of its messages.\n\n";
    for (const WarningGroup& g : others) {
      o << "- " << (g.messages > 1 ? "**" + markdown_text(g.kind) + "**" : markdown_text(g.example));
      const std::string origin = origin_text(g, 10);
      if (!origin.empty()) o << " — " << markdown_text(origin);
      o << "\n";
      if (g.messages > 1) o << "  - for example: " << markdown_text(g.example) << "\n";
    }
    o << "\n";
  }
  if (w.kinds_dropped > 0)
    o << "Another " << w.kinds_dropped << " warnings of further kinds are not listed.\n\n";
  return o.str();
}

std::string warnings_text(const ReportWarnings& w, std::size_t max_groups) {
  const std::vector<WarningGroup> others = other_warning_groups(w);
  std::ostringstream o;
  if (!w.best.empty()) {
    o << "  warnings of the " << w.design;
    if (w.best_evaluation > 0) o << " (evaluation " << w.best_evaluation << ")";
    o << ":\n";
    for (const std::string& m : w.best) o << "    " << one_line(m) << "\n";
  }
  if (!others.empty()) {
    o << (w.best.empty() ? "  warnings" : "  other warnings of the run") << (any_grouped(others) ? ", by kind" : "")
      << ":\n";
    const std::size_t shown = std::min(max_groups, others.size());
    for (std::size_t i = 0; i < shown; ++i) o << "    " << one_line(warning_group_text(others[i], 5, false)) << "\n";
    if (others.size() > shown)
      o << "    ... and " << others.size() - shown << " more kinds (report.md, summary.json)\n";
  }
  if (w.kinds_dropped > 0) o << "    ... and " << w.kinds_dropped << " warnings of further kinds\n";
  return o.str();
}

void warning_groups_json(JsonWriter& j, const ReportWarnings& w) {
  j.key("warning_groups").begin_array();
  for (const WarningGroup& g : w.groups) {
    j.begin_object();
    j.key("kind").value(g.kind);
    j.key("example").value(g.example);
    j.key("designs").value(static_cast<long>(g.designs));
    j.key("messages").value(static_cast<long>(g.messages));
    j.key("evaluations").begin_array();
    for (std::int64_t id : g.evaluations) j.value(static_cast<long>(id));
    j.end_array();
    j.key("best_design").value(best_gave(w, g));
    j.end_object();
  }
  j.end_array();
  j.key("warning_kinds_dropped").value(static_cast<long>(w.kinds_dropped));
}

}  // namespace rackopt::study_report
