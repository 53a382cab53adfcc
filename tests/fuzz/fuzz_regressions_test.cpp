// Replays every input the fuzzer found (tests/fuzz/regressions/, one file
// each, named after what it broke) through the same function the fuzz target
// runs: each must now be refused with InputError/DesignError or load, never
// crash, hang, exhaust memory or throw anything else. Also replays the seed
// corpus (the shipped problems and studies), which must load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input_fuzz_case.hpp"
#include "writer_fuzz_case.hpp"

namespace rackopt::fuzz {
namespace {

namespace fs = std::filesystem;

const std::string kSource = RACKOPT_SOURCE_DIR;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> files_in(const fs::path& dir, const std::string& extension = "") {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(FuzzRegressions, EveryFoundInputIsHandled) {
  const auto files = files_in(kSource + "/tests/fuzz/regressions");
  ASSERT_FALSE(files.empty()) << "tests/fuzz/regressions/ holds the inputs the fuzzer found";
  for (const auto& f : files) {
    if (f.filename() == "README.md") continue;
    EXPECT_NO_THROW(run_input_fuzz_case(read_all(f), kSource + "/studies")) << f.filename();
  }
}

TEST(FuzzRegressions, SeedCorpusRunsClean) {
  for (const char* dir : {"/problems", "/studies"}) {
    for (const auto& f : files_in(kSource + dir, ".yaml")) {
      EXPECT_NO_THROW(run_input_fuzz_case(read_all(f), kSource + "/studies")) << f;
    }
  }
}

// The writer target's corpus (tests/fuzz/writer_corpus/: newlines, CR,
// backquotes, @macros, quotes, HTML comments, script tags, javascript:
// links in every spelling, Markdown structure, invalid UTF-8): every rule
// of check_writers holds for each.
TEST(FuzzRegressions, WriterCorpusKeepsEveryRule) {
  const auto files = files_in(kSource + "/tests/fuzz/writer_corpus");
  ASSERT_GT(files.size(), 10u);
  for (const auto& f : files) {
    if (f.filename() == "README.md") continue;
    const std::vector<std::string> broken = check_writers(writer_texts(read_all(f)));
    std::string all;
    for (const auto& b : broken) all += b + "\n";
    EXPECT_TRUE(broken.empty()) << f.filename() << ":\n" << all;
  }
}

// The checks themselves catch what the writers must never produce, so the
// corpus test above can fail.
TEST(FuzzRegressions, WriterChecksCatchEachBreakout) {
  EXPECT_FALSE(gnuplot_script_problems("t.gp", "set title 'rack\nsystem(\"id\")'\n").empty());
  EXPECT_FALSE(gnuplot_script_problems("t.gp", "set title 'a' . `id`\n").empty());
  EXPECT_FALSE(gnuplot_script_problems("t.gp", "set title @m\n").empty());
  EXPECT_FALSE(gnuplot_script_problems("t.gp", "set title 'it's'\n").empty());
  EXPECT_TRUE(gnuplot_script_problems("t.gp", "set title 'it''s `id` @m system(1)'\n").empty());
  EXPECT_FALSE(markdown_problems("# Study: a\n\n<!-- x\n\n## Outcome\n").empty());
  EXPECT_FALSE(markdown_problems("# Study: a\n\n[x](javascript:alert(1))\n\n## Outcome\n").empty());
  EXPECT_FALSE(markdown_problems("# Study: a\n\n```\n## Outcome\n").empty());
  EXPECT_TRUE(markdown_problems("# Study: a\n\n[x](https://x.org)\n\n## Outcome\n").empty());
  EXPECT_FALSE(html_problems("<main>\n<script>x</script></main>").empty());
  EXPECT_FALSE(html_problems("<main>\n<a href=\"javascript:x\">x</a></main>").empty());
  EXPECT_FALSE(html_problems("<main>\n<a href=\"&#106;avascript:x\">x</a></main>").empty());
  EXPECT_FALSE(html_problems("<main>\n<p onclick=\"x\">x</p></main>").empty());
  EXPECT_FALSE(html_problems("<main>\n<p><!-- x</p></main>").empty());
  EXPECT_TRUE(html_problems("<main>\n<p><a href=\"https://x.org/?a=1&amp;b=2\">x</a></p></main>").empty());
  const WriterTexts t = writer_texts(std::string("name\0description", 16));
  EXPECT_EQ(t.name, "name");
  EXPECT_EQ(t.description, "description");
  EXPECT_EQ(t.path, "x");  // a missing field
}

}  // namespace
}  // namespace rackopt::fuzz
