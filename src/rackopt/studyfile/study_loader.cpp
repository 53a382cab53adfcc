#include "rackopt/studyfile/study_loader.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <utility>

#include "rackopt/core/text.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/design_point.hpp"
#include "rackopt/study/study_kind_rules.hpp"
#include "rackopt/studyfile/study_section_reader.hpp"
#include "rackopt/studyfile/study_sections.hpp"
#include "rackopt/studyfile/verify_section.hpp"

namespace rackopt::studyfile {

// The loaders fill the study layer's types throughout.
using namespace rackopt::study;
namespace {

namespace fs = std::filesystem;

std::uint64_t read_seed(const SectionReader& s, const std::string& key, std::uint64_t fallback) {
  const auto t = s.scalar(key, "a whole number >= 0");
  if (!t) return fallback;
  const std::string text = trim(t->first);
  std::uint64_t v = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && text[0] == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (text.empty() || ec != std::errc() || ptr != last) {
    throw InputError(t->second, s.child_path(key),
                     "'" + t->first + "' is not a seed; expected a whole number >= 0 (at most 18446744073709551615)");
  }
  return v;
}

}  // namespace

StudySpec load_study_text(const std::string& yaml_text, const std::string& name_for_messages,
                          const std::string& base_dir, const std::vector<std::string>& overrides,
                          const InMemoryProblem* given_problem) {
  MarkedNode root = parse_marked_yaml(yaml_text, name_for_messages);
  if (root.is_null()) {
    root.type = MarkedNode::Type::kMap;
    root.mark = SourceMark{name_for_messages, 1, 1};
  }
  if (!root.is_map()) {
    throw InputError(
        root.mark, "",
        "a study file is a map of sections (study, problem, variables, objectives, ...), found " + root.type_name());
  }
  const std::vector<std::string> cli_problem_overrides = apply_study_overrides(root, overrides);

  StudySpec spec;
  spec.file = name_for_messages;
  const SectionReader top =
      study_section(&root, "", root.mark,
                    {"study", "problem", "problem_set", "variables", "objectives", "constraints", "report",
                     "metric_options", "solver", "pareto", "sweep", "output", "limits", "verify"});

  const std::vector<std::string> kinds = {"evaluate", "sweep", "optimize", "pareto", "reliability"};
  if (!top.has("study")) top.missing("study", "a map {name: ..., kind: " + join(kinds, " | ") + ", seed: 1}");
  const SectionReader study = study_section(top.get("study"), "study", top.key_mark("study"),
                                            {"name", "kind", "seed", "description"}, "{kind: optimize, seed: 1}");
  spec.name = study.text("name", fs::path(name_for_messages).stem().string());
  spec.name_mark = study.has("name") ? study.value_mark("name") : SourceMark{name_for_messages, 0, 0};
  spec.description = study.text("description", "");
  const auto kind_text = study.choice("kind", kinds);
  if (!kind_text) study.missing("kind", "one of " + join(kinds, " | "));
  const std::size_t kind_index =
      static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), *kind_text) - kinds.begin());
  const StudyKind kind_values[] = {StudyKind::kEvaluate, StudyKind::kSweep, StudyKind::kOptimize, StudyKind::kPareto,
                                   StudyKind::kReliability};
  spec.kind = kind_values[kind_index];
  spec.seed = read_seed(study, "seed", 1);
  const SourceMark kind_mark = study.value_mark("kind");

  const LoadedProblem problem = read_problem_section(top, base_dir, cli_problem_overrides, given_problem, spec);
  const Drive& drive = problem.drive;
  read_variables(top, problem, spec);
  const std::vector<MetricSite> metric_sites = read_metric_sections(top, spec);
  const SectionReader mo = read_metric_options(top, spec);
  const SettingsSections settings = read_settings_sections(top, spec);
  const SectionReader& sv = settings.solver;
  const SectionReader& pa = settings.pareto;
  const SectionReader& sw = settings.sweep;
  spec.verify_fe = read_verify_section(top);

  const SourceMark variables_mark = top.key_mark("variables");
  const SourceMark objectives_mark = top.key_mark("objectives");
  // Where a broken kind rule points: the key to change, or study.kind when
  // the section the kind needs is missing altogether.
  auto rule_site = [&](const StudyRuleViolation& v) -> std::pair<SourceMark, std::string> {
    auto value_or_section = [](const SectionReader& sec, const char* key, const std::string& path) {
      return std::pair<SourceMark, std::string>{sec.has(key) ? sec.value_mark(key) : sec.mark(), path};
    };
    switch (v.part) {
      case StudyRulePart::kObjectives:
        if (top.has("objectives")) return {objectives_mark, "objectives"};
        return {kind_mark, "study.kind"};
      case StudyRulePart::kVariables:
        if (top.has("variables")) return {variables_mark, "variables"};
        return {kind_mark, "study.kind"};
      case StudyRulePart::kVariable:
        return {spec.variables[v.variable].mark, "variables." + spec.variables[v.variable].key};
      case StudyRulePart::kSweepGrid:
        if (sw.has("levels")) return {sw.value_mark("levels"), "sweep.levels"};
        return {sw.present() ? sw.mark() : variables_mark, "sweep"};
      case StudyRulePart::kSweepPoints: return {sw.value_mark("points"), "sweep.points"};
      case StudyRulePart::kSolverLibrary: return value_or_section(sv, "library", "solver.library");
      case StudyRulePart::kSolverLocalAlgorithm:
        if (sv.has("local_algorithm")) return {sv.value_mark("local_algorithm"), "solver.local_algorithm"};
        return value_or_section(sv, "algorithm", "solver.algorithm");
      case StudyRulePart::kSolverAlgorithm: return value_or_section(sv, "algorithm", "solver.algorithm");
      case StudyRulePart::kSolverOption:
        if (sv.has(v.option)) return {sv.value_mark(v.option), "solver." + v.option};
        return value_or_section(sv, "algorithm", "solver.algorithm");
      case StudyRulePart::kParetoMethod:
        if (pa.has("method")) return {pa.value_mark("method"), "pareto.method"};
        if (sv.has("algorithm")) return {sv.value_mark("algorithm"), "solver.algorithm"};
        return {kind_mark, "solver.algorithm"};
    }
    return {kind_mark, "study.kind"};
  };
  // One design for evaluate/reliability: a single listed value is its start.
  if (spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability) {
    for (auto& v : spec.variables)
      if (!v.start && v.values.size() == 1) v.start = v.values.front();
  }
  if (const auto broken = check_study_kind_rules(spec)) {
    const auto [where, key] = rule_site(*broken);
    throw InputError(where, key, broken->message);
  }
  if ((spec.kind == StudyKind::kEvaluate || spec.kind == StudyKind::kReliability) && !spec.variables.empty()) {
    std::vector<std::pair<std::string, double>> design;
    for (const auto& v : spec.variables) design.emplace_back(v.key, *v.start);
    try {
      (void)drive_with_values(problem.tree, design);
    } catch (const InputError& e) {
      throw InputError(variables_mark, "variables",
                       "the design of the starts is refused by the problem: " +
                           (e.key_path().empty() ? "" : e.key_path() + ": ") + e.message());
    }
  }
  if (spec.kind == StudyKind::kReliability) {
    if (!(drive.wear.coefficient > 0)) {
      throw InputError(kind_mark, "study.kind",
                       "a reliability study needs the problem's wear section (wear.coefficient, hardness); '" +
                           spec.problem_path + "' has none (docs/yaml.md, wear)");
    }
    if (drive.reliability.inputs.empty()) {
      throw InputError(kind_mark, "study.kind",
                       "a reliability study needs random inputs in the problem's reliability section "
                       "(reliability.random, e.g. - {input: contact_ratio, distribution: normal, shift: -0.096, sd: "
                       "0.038}); '" +
                           spec.problem_path + "' has none");
    }
  }

  check_metrics_against_problem(metric_sites, mo, drive, spec);

  spec.pareto.solver = spec.solver;
  return spec;
}

StudySpec load_study_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_input_file(path, "study file");
  return load_study_text(text, path, fs::path(path).parent_path().string(), overrides);
}

}  // namespace rackopt::studyfile
