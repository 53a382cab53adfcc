// One fuzzer input turned into the user text of a study (its name,
// description, a variable key, a metric label, a message, a file path) and
// fed to the real writers of the plot scripts, report.md and report.html;
// the body of the libFuzzer target writer_fuzzer.cpp (built with
// -DRACKOPT_FUZZ=ON) and of the regular test that replays the committed
// corpus writer_corpus/, so both check exactly the same things.
// docs/input_limits.md, "Fuzzing".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rackopt::fuzz {

// The texts of one input: the bytes split at NUL into, in order, the name,
// the description, a variable key, a metric label, a message (also a
// warning and a combination label) and a file path (the study file, the
// problem and a --set override); a missing field is "x".
struct WriterTexts {
  std::string name, description, variable_key, metric_label, message, path;
};
WriterTexts writer_texts(std::string_view data);

// Writes every gnuplot script of a study (pareto, convergence, front
// quality, sweep, stiffness, wear), report.md and report.html from `texts`
// and checks what a study file must never do to them. Returns one line per
// broken rule (empty when all hold):
//  * gnuplot: the script has as many lines as the one written from plain
//    texts, every quoted string closes on its line, and outside strings no
//    line holds a backquote, an '@', `system`, `load`, `call`, `eval` or
//    starts with '!' (a shell command);
//  * report.md (parsed with cmark-gfm): its first block is the one level-1
//    heading, there is no raw HTML node, every link and image goes to a
//    relative, http(s) or mailto destination, and the report's own
//    "Outcome" heading follows (the description swallowed nothing);
//  * report.html: no HTML comment, every tag one cmark-gfm writes for
//    Markdown (no <script>, <img>, <iframe>, ...), attributes only href,
//    title, class, align, start, and every href allowed.
std::vector<std::string> check_writers(const WriterTexts& texts);

// The rules of check_writers for one text each (one line per broken rule):
// a gnuplot script named `name`, report.md, report.html.
std::vector<std::string> gnuplot_script_problems(const std::string& name, const std::string& script);
std::vector<std::string> markdown_problems(const std::string& md);
std::vector<std::string> html_problems(const std::string& html);

// writer_texts then check_writers; throws std::logic_error listing the
// broken rules (what the fuzzer reports as a crash).
void run_writer_fuzz_case(std::string_view data);

}  // namespace rackopt::fuzz
