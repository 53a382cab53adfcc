// A study whose problem is held in memory (an inline `problem:` map, or a
// problem a program hands load_study_text) is the same study as one that
// reads the same problem from its file, and its errors point into the text
// the problem came from.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "rackopt/study/study_runner.hpp"
#include "rackopt/study/study_spec.hpp"
#include "rackopt/studyfile/study_loader.hpp"
#include "studyfile_test_support.hpp"
#include "support/file_text.hpp"
#include "support/input_error_expectations.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt::study {
namespace {

const std::string kRailwayFile = std::string(RACKOPT_SOURCE_DIR) + "/problems/rack_railway.yaml";

// The railway problem's text with every line indented by two spaces: the
// body of an inline `problem:` map.
std::string indented_railway() {
  std::istringstream in(test_support::read_text(kRailwayFile));
  std::string out, line;
  while (std::getline(in, line)) out += "  " + line + "\n";
  return out;
}

// An evaluate study of two metrics; `problem` is its `problem:` entry (or
// "" for none).
std::string evaluate_study(const std::string& problem) {
  return "study: {kind: evaluate}\n" + problem +
         "problem_set: {numerics.positions_per_period: 24}\n"
         "objectives: [{metric: stiffness_fluctuation}]\n"
         "report: [contact_ratio]\n";
}

TEST(InMemoryProblem, InlineProblemMapIsTheSameStudyAsItsFile) {
  const StudySpec from_file = test::load(evaluate_study("problem: ../problems/rack_railway.yaml\n"));
  const StudySpec inline_map = test::load(evaluate_study("problem:\n" + indented_railway()));
  ASSERT_TRUE(inline_map.problem_root);
  EXPECT_FALSE(from_file.problem_root);
  EXPECT_EQ(inline_map.problem_path, "t.yaml (problem:)");
  // The fingerprint hashes the problem's content: the same study either way.
  EXPECT_EQ(study_fingerprint(inline_map), study_fingerprint(from_file));
  EXPECT_EQ(study_problem_tree(inline_map).root.entries.size(), study_problem_tree(from_file).root.entries.size());
}

TEST(InMemoryProblem, ErrorsInAnInlineProblemPointIntoTheStudyFile) {
  // Line 2 is "problem:", line 3 its first key; the module is given in an
  // unit of the wrong kind.
  const std::string text = evaluate_study("problem:\n  pinion: {module: 3 kN, teeth: 20}\n");
  test_support::expect_input_error([&] { (void)test::load(text); },
                                   {.file = "t.yaml", .line = 3, .key = "pinion.module", .in_message = {"kN"}});
}

TEST(InMemoryProblem, AProgramsProblemReplacesTheFileAndRunsTheSame) {
  const studyfile::InMemoryProblem given{test_support::read_text(kRailwayFile), "<memory>"};
  // No `problem:` key at all: the program's problem is the study's.
  const StudySpec held = studyfile::load_study_text(evaluate_study(""), "t.yaml", test::kStudies, {}, &given);
  // A `problem:` the study names is replaced by the program's.
  const StudySpec replaced = studyfile::load_study_text(
      evaluate_study("problem: ../problems/gantry_axis.yaml\n"), "t.yaml", test::kStudies, {}, &given);
  const StudySpec from_file = test::load(evaluate_study("problem: ../problems/rack_railway.yaml\n"));
  EXPECT_EQ(held.problem_path, "<memory>");
  EXPECT_EQ(study_fingerprint(held), study_fingerprint(from_file));
  EXPECT_EQ(study_fingerprint(replaced), study_fingerprint(from_file));

  // The runner reads the held problem too: the same design, the same values.
  RunOptions run_held, run_file;
  run_held.out_dir = test_support::scratch_path("held");
  run_file.out_dir = test_support::scratch_path("file");
  run_held.threads = run_file.threads = 1;
  const StudyResult a = run_study(held, run_held);
  const StudyResult b = run_study(from_file, run_file);
  ASSERT_TRUE(a.best && b.best);
  ASSERT_TRUE(a.best->ok);
  EXPECT_EQ(a.best->metric_values, b.best->metric_values);
}

TEST(InMemoryProblem, ErrorsInAProgramsProblemPointIntoItsOwnText) {
  const studyfile::InMemoryProblem given{"pinion:\n  teeth: 20\n  module: 3 kN\n", "<memory>"};
  test_support::expect_input_error(
      [&] { (void)studyfile::load_study_text(evaluate_study(""), "t.yaml", test::kStudies, {}, &given); },
      {.file = "<memory>", .line = 3, .key = "pinion.module", .in_message = {"kN"}});
}

}  // namespace
}  // namespace rackopt::study
