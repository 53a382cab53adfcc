// The command line itself (docs/cli.md): help per command, --version, the
// forms of an option and its value, and usage errors that say what to type.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rackopt/version.hpp"
#include "support/cli_process.hpp"
#include "support/scratch_dir.hpp"

namespace {

using rackopt::test_support::CliResult;
using rackopt::test_support::run_cli;
using rackopt::test_support::scratch_path;

struct CommandOptions {
  const char* command;
  std::vector<const char*> options;  // as the help shows them: "-o,--out" when there is a short alias
};

const std::vector<CommandOptions>& every_command_option() {
  static const std::vector<CommandOptions> table = {
      {"check", {"-s,--set", "--json"}},
      {"stiffness", {"-s,--set", "-o,--out", "--json"}},
      {"wear", {"-s,--set", "-o,--out", "--json", "-n,--samples", "--seed", "-j,--threads"}},
      {"fe",
       {"-s,--set", "-o,--out", "--json", "-p,--positions", "-l,--level", "--extended-contact", "--pictures",
        "--rack-supports", "-j,--threads"}},
      {"run", {"-s,--set", "-o,--out", "--json", "-j,--threads", "--resume", "--progress", "--ranks"}},
  };
  return table;
}

TEST(CommandLine, EachCommandsHelpListsEveryOptionAndAnExample) {
  const CliResult top = run_cli("--help");
  EXPECT_EQ(top.code, 0);
  for (const CommandOptions& c : every_command_option()) {
    EXPECT_NE(top.out.find(std::string("\n  ") + c.command + " "), std::string::npos) << c.command << "\n" << top.out;
    const CliResult r = run_cli(std::string(c.command) + " --help");
    EXPECT_EQ(r.code, 0) << c.command;
    EXPECT_NE(r.out.find(std::string("usage: rackopt ") + c.command + " [OPTIONS] "), std::string::npos) << r.out;
    for (const char* option : c.options) EXPECT_NE(r.out.find(option), std::string::npos) << c.command << " " << option;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(std::string("  rackopt ") + c.command + " "), std::string::npos) << r.out;  // an example line
    // The ranges and defaults are in the help, not only in docs/cli.md.
    if (std::string(c.command) == "fe") {
      EXPECT_NE(r.out.find("1..64 (default 4)"), std::string::npos) << r.out;
      EXPECT_NE(r.out.find("0..6 (default 0"), std::string::npos) << r.out;
    }
  }
  // check --json says what the object holds.
  const CliResult check = run_cli("check -h");
  EXPECT_EQ(check.code, 0);
  for (const char* key : {"contact_ratio", "pressure_angle_range", "warnings"}) {
    EXPECT_NE(check.out.find(key), std::string::npos) << key << "\n" << check.out;
  }
}

TEST(CommandLine, HelpCommandIsHelpOption) {
  const CliResult top = run_cli("help");
  EXPECT_EQ(top.code, 0);
  EXPECT_EQ(top.out, run_cli("--help").out);
  const CliResult fe = run_cli("help fe");
  EXPECT_EQ(fe.code, 0);
  EXPECT_EQ(fe.out, run_cli("fe --help").out);
  const CliResult typo = run_cli("help wera");
  EXPECT_EQ(typo.code, 2);
  EXPECT_NE(typo.err.find("unknown command 'wera'; did you mean 'wear'?"), std::string::npos) << typo.err;
}

TEST(CommandLine, VersionIsTheBuildsVersion) {
  for (const char* args : {"--version", "-V", "version", "--version --json=false"}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.code, 0) << args;
    EXPECT_EQ(r.out, std::string("rackopt ") + RACKOPT_VERSION_STRING + "\n") << args;
  }
  // With --json, like every other answer, one JSON object.
  for (const char* args : {"--version --json", "-V --json", "version --json"}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    ASSERT_TRUE(nlohmann::json::accept(r.out)) << args << "\n" << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["ok"], true) << args;
    EXPECT_EQ(j["version"], RACKOPT_VERSION_STRING) << args;
  }
}

// A value option given no value, an empty one or another option: CLI11
// alone would make `--out= --json` write into a folder named "--json".
TEST(CommandLine, AnEmptyValueOrAnOptionForAValueIsAUsageErrorNamingTheOption) {
  struct Case {
    std::string args;
    std::string says;
  };
  const std::string dir = scratch_path("never_written");
  for (const Case& c : {Case{"stiffness problems/rack_railway.yaml --out= --json", "--out needs a value"},
                        Case{"stiffness problems/rack_railway.yaml --json --out ''", "--out needs a value, got an empty one"},
                        Case{"stiffness problems/rack_railway.yaml --json -o --json", "-o needs a value, got the option --json"},
                        Case{"stiffness problems/rack_railway.yaml --json -o=" + dir, "-o takes its value after a space"},
                        Case{"check problems/rack_railway.yaml --set= --json", "--set needs a value"},
                        Case{"wear problems/ship_lift.yaml --samples= --json", "--samples needs a value"}}) {
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    // --json was not taken for the value: the error is the one JSON object.
    ASSERT_TRUE(nlohmann::json::accept(r.out)) << c.args << "\n" << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["error"], "usage") << c.args;
    EXPECT_NE(j["message"].get<std::string>().find(c.says), std::string::npos) << c.args << "\n" << j["message"];
  }
  EXPECT_FALSE(std::filesystem::exists(std::string(RACKOPT_SOURCE_DIR) + "/--json"));
  std::filesystem::remove_all(std::string(RACKOPT_SOURCE_DIR) + "/--json");  // left by a failing run
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(CommandLine, JsonTakesTrueOrFalse) {
  const CliResult no = run_cli("check problems/rack_railway.yaml --json=false");
  EXPECT_EQ(no.code, 0) << no.err;
  EXPECT_FALSE(nlohmann::json::accept(no.out)) << no.out;
  EXPECT_NE(no.out.find("ok: problems/rack_railway.yaml"), std::string::npos) << no.out;
  const CliResult yes = run_cli("check problems/rack_railway.yaml --json=true");
  EXPECT_EQ(yes.code, 0) << yes.err;
  EXPECT_TRUE(nlohmann::json::accept(yes.out)) << yes.out;
  // The last one counts, before parsing as after: a usage error is text here.
  const CliResult last = run_cli("check problems/rack_railway.yaml --json --json=false --jsno");
  EXPECT_EQ(last.code, 2);
  EXPECT_EQ(last.out, "");
  EXPECT_NE(last.err.find("unknown option --jsno"), std::string::npos) << last.err;
}

// After "--" every argument is a file name, "--json" too: no JSON, and the
// message says why it is one argument too many.
TEST(CommandLine, AnArgumentAfterTheDoubleDashIsAFileName) {
  const CliResult r = run_cli("check problems/ship_lift.yaml -- --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("unexpected argument --json after '--'"), std::string::npos) << r.err;
  const CliResult file = run_cli("check -- problems/ship_lift.yaml");
  EXPECT_EQ(file.code, 0) << file.err;
}

TEST(CommandLine, AValueFollowsItsOptionOrAnEqualsSign) {
  const std::string equals = scratch_path("out_equals");
  const CliResult a = run_cli("stiffness problems/rack_railway.yaml --json --out=" + equals);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_TRUE(std::filesystem::exists(equals + "/stiffness.csv"));
  const std::string alias = scratch_path("out_alias");
  const CliResult b = run_cli("stiffness problems/rack_railway.yaml --json -o " + alias);
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_TRUE(std::filesystem::exists(alias + "/stiffness.csv"));
  // --set in all its forms, before or after FILE, gives the same drive.
  const double plain = nlohmann::json::parse(run_cli("check problems/rack_railway.yaml --json").out)["contact_ratio"];
  std::vector<double> ratios;
  for (const char* args : {"check problems/rack_railway.yaml --json --set pinion.teeth=26",
                           "check problems/rack_railway.yaml --json --set=pinion.teeth=26",
                           "check problems/rack_railway.yaml --json -s pinion.teeth=26",
                           "check --set pinion.teeth=26 problems/rack_railway.yaml --json"}) {
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.code, 0) << args << "\n" << r.err;
    ratios.push_back(nlohmann::json::parse(r.out)["contact_ratio"].get<double>());
  }
  EXPECT_NE(ratios[0], plain);
  for (double x : ratios) EXPECT_EQ(x, ratios[0]);
  // --set repeats, in order: the last value of a key counts.
  const CliResult twice = run_cli("check problems/rack_railway.yaml --json -s pinion.teeth=30 --set pinion.teeth=26");
  ASSERT_EQ(twice.code, 0) << twice.err;
  EXPECT_EQ(nlohmann::json::parse(twice.out)["contact_ratio"].get<double>(), ratios[0]);
}

TEST(CommandLine, AnUnknownOptionSuggestsTheNearestOne) {
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& c : {Case{"wear problems/ship_lift.yaml --thread 2", "unknown option --thread; did you mean --threads?"},
                        Case{"check problems/ship_lift.yaml --jsno", "unknown option --jsno; did you mean --json?"},
                        Case{"fe problems/gantry_axis.yaml --position=3", "did you mean --positions?"},
                        Case{"run studies/rack_railway_sizing.yaml --resum", "did you mean --resume?"},
                        Case{"stifness problems/ship_lift.yaml", "unknown command 'stifness'; did you mean 'stiffness'?"}}) {
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
  }
  // Nothing near: no guess, and the help to read instead.
  const CliResult far = run_cli("check problems/ship_lift.yaml --frobnicate");
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  EXPECT_NE(far.err.find("rackopt check --help"), std::string::npos) << far.err;
  // With --json the suggestion is in the one JSON object.
  const CliResult j = run_cli("check problems/ship_lift.yaml --json --jsno");
  EXPECT_EQ(j.code, 2);
  EXPECT_EQ(nlohmann::json::parse(j.out)["message"], "unknown option --jsno; did you mean --json?");
}

TEST(CommandLine, AnOptionOfAnotherCommandIsRefusedNamingTheCommand) {
  const CliResult alias = run_cli("check problems/ship_lift.yaml -o " + scratch_path("refused"));
  EXPECT_EQ(alias.code, 2);
  EXPECT_NE(alias.err.find("option -o does not apply to 'check' (check accepts --set, --json)"), std::string::npos)
      << alias.err;
  const CliResult equals = run_cli("stiffness problems/ship_lift.yaml --positions=3");
  EXPECT_EQ(equals.code, 2);
  EXPECT_NE(equals.err.find("option --positions does not apply to 'stiffness' (stiffness accepts --set, --out, --json)"),
            std::string::npos)
      << equals.err;
  EXPECT_FALSE(std::filesystem::exists(scratch_path("refused")));
}

TEST(CommandLine, AMissingValueOrAMisplacedOptionIsAUsageError) {
  const CliResult missing = run_cli("wear problems/ship_lift.yaml --samples");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("--samples needs a value"), std::string::npos) << missing.err;
  const CliResult before = run_cli("--json check problems/ship_lift.yaml");
  EXPECT_EQ(before.code, 2);
  EXPECT_NE(before.err.find("option --json before the command; options go after it"), std::string::npos) << before.err;
  const CliResult extra = run_cli("check problems/ship_lift.yaml problems/rack_railway.yaml");
  EXPECT_EQ(extra.code, 2);
  EXPECT_NE(extra.err.find("unexpected argument problems/rack_railway.yaml"), std::string::npos) << extra.err;
  // One command per line: a second command name is an argument too many, not ignored.
  const CliResult second = run_cli("check problems/ship_lift.yaml stiffness");
  EXPECT_EQ(second.code, 2);
  EXPECT_NE(second.err.find("unexpected argument stiffness"), std::string::npos) << second.err;
  const CliResult flag_value = run_cli("run studies/rack_railway_sizing.yaml --resume=false");
  EXPECT_EQ(flag_value.code, 2) << flag_value.err;
  EXPECT_NE(flag_value.err.find("--resume takes no value"), std::string::npos) << flag_value.err;
}

}  // namespace
