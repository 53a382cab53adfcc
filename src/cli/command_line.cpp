// The rackopt command line, declared with CLI11: each command with its
// options, their meaning, range and default, and an example. The help, the
// parsing and the usage errors all come from this one declaration, so they
// cannot disagree.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "cli.hpp"
#include "rackopt/core/drive.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/units/units.hpp"
#include "rackopt/version.hpp"

namespace rackopt::cli {
namespace {

constexpr long kMaxThreads = kThreadsLimit.hi;  // 0 (all cores) is what leaving --threads out means
constexpr long kMaxLevel = 6;  // FeOptions::level
constexpr long kMaxSeed = kSeedLimit.hi;
// --ranks: mpirun's own limit is the machines given to it; this one only
// keeps a typo (an extra digit or two) from asking for a job nobody meant.
constexpr long kMaxRanks = 65536;

long parse_whole(const std::string& flag, const std::string& text, long lo, long hi) {
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || v < lo || v > hi) {
    throw UsageError(flag + " needs a whole number in " + std::to_string(lo) + ".." + std::to_string(hi) +
                     ", got '" + text + "'");
  }
  return v;
}

std::string range(long lo, long hi) { return std::to_string(lo) + ".." + std::to_string(hi); }

// An option taking a whole number in lo..hi. The value is read as text and
// checked here, so a bad one gets the same message whatever CLI11 thinks of
// it ("-1" looks like an option to it, "two" is no number).
template <class Store>
void add_whole(CLI::App& cmd, const std::string& names, const std::string& metavar, long lo, long hi,
               const std::string& meaning, Store store) {
  const std::string flag = names.substr(names.rfind(',') + 1);
  cmd.add_option_function<std::string>(
         names, [flag, lo, hi, store](const std::string& text) { store(parse_whole(flag, text, lo, hi)); }, meaning)
      ->type_name(metavar);
}

void add_file(CLI::App& cmd, Args& a, const std::string& name, const std::string& meaning) {
  cmd.add_option(name, a.file, meaning)->required()->type_name("");
}

void add_set(CLI::App& cmd, Args& a, const std::string& meaning) {
  // One KEY=VALUE per --set: a vector option would otherwise swallow the FILE after it.
  cmd.add_option("-s,--set", a.overrides, meaning + ";\nrepeatable, applied in order")
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void add_out(CLI::App& cmd, Args& a, const std::string& default_dir) {
  cmd.add_option("-o,--out", a.out_dir,
                 "output folder (default " + default_dir + ");\nmade if missing, refused while another run uses it")
      ->type_name("DIR");
}

void add_json(CLI::App& cmd, Args& a, const std::string& what) {
  // --json=false is no JSON: the one flag that takes a value, read the same
  // way by json_requested() before parsing.
  cmd.add_flag("--json", a.json,
               "print one JSON object on stdout: " + what +
                   ";\non an error {\"ok\": false, \"error\": kind, \"message\": text};\nthe text for people "
                   "goes to stderr; --json=false: none")
      ->disable_flag_override(false);
}

void add_threads(CLI::App& cmd, Args& a, const std::string& default_text) {
  add_whole(cmd, "-j,--threads", "N", 1, kMaxThreads,
            "worker threads, " + range(1, kMaxThreads) + " (default " + default_text + ")",
            [&a](long v) { a.threads = static_cast<int>(v); });
}

const char* kProblemSet = "override a key of the problem (docs/yaml.md),\ne.g. --set rack.span=\"1.2 m\"";

void add_check(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand("check", "validate a problem file and print the contact geometry");
  add_file(c, a, "FILE", "the problem file (YAML, docs/yaml.md)");
  add_set(c, a, kProblemSet);
  add_json(c, a,
           "ok, contact_ratio,\npressure_angle_range {lower, upper [rad], lower_limit,\nupper_limit: what bounds "
           "each end} and warnings");
  c.footer(
      "Prints the geometry (contact ratio, undercut, the pressure angles the cutter\n"
      "allows) and \"ok: FILE\"; exit 2 with file:line:column and key for a bad file.\n"
      "Examples:\n"
      "  rackopt check problems/ship_lift.yaml\n"
      "  rackopt check problems/rack_railway.yaml --set pinion.teeth=24 --json");
}

void add_stiffness(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand("stiffness", "mesh stiffness, ripple and transmission error over one rack span");
  add_file(c, a, "FILE", "the problem file (YAML, docs/yaml.md)");
  add_set(c, a, kProblemSet);
  add_out(c, a, "out/<problem file name>");
  add_json(c, a,
           "the stiffness figures,\nzones, ripple, transmission error, files and timings\n(docs/output.md)");
  c.footer(
      "Writes DIR/stiffness.csv and DIR/stiffness.png.\n"
      "Examples:\n"
      "  rackopt stiffness problems/rack_railway.yaml --set rack.span=\"1.2 m\" --out=out/span\n"
      "  rackopt stiffness problems/ship_lift.yaml -o out/ship_lift --json");
}

void add_dynamics(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand(
      "dynamics", "natural frequencies, steady dynamic response, dynamic factor K_V\nover speed, Campbell diagram");
  add_file(c, a, "FILE", "the problem file (YAML, docs/yaml.md;\nsection dynamics)");
  add_set(c, a, kProblemSet);
  add_out(c, a, "out/<problem file name>_dynamics");
  add_json(c, a,
           "natural_frequencies_hz, kv_curve [{speed_m_per_s, kv}],\nkv_max, static_mesh_force_N, the whole "
           "analysis\nunder dynamics, files (docs/output.md)");
  // A speed with its unit ("0.5 m/s", "30 m/min"); a bare number is m/s.
  c.add_option_function<std::string>(
       "--speed",
       [&a](const std::string& text) {
         double v = 0;
         try {
           v = rackopt::parse_quantity(text, rackopt::QuantityKind::kSpeed);
         } catch (const std::exception& e) {
           throw UsageError(std::string("--speed: ") + e.what(), "dynamics");
         }
         if (!(v > 0)) throw UsageError("--speed needs a speed > 0, got '" + text + "'", "dynamics");
         a.speed = v;
       },
       "operating speed for the steady response, e.g. \"0.5 m/s\"\n(default load.speed)")
      ->type_name("V");
  c.add_flag("--sweep", a.sweep,
             "K_V over the speed range (dynamics.speed_range, default\nload.speed/20 .. 1.25 load.speed), up and down");
  c.add_flag("--stability", a.stability, "Floquet multipliers over the speed range");
  c.footer(
      "Writes DIR/dynamics.json, the CSV tables and DIR/dynamics.png\n(docs/output.md, docs/models/dynamics.md).\n"
      "Examples:\n"
      "  rackopt dynamics problems/gantry_axis.yaml --sweep\n"
      "  rackopt dynamics problems/rack_railway.yaml --speed \"3 m/s\" --json");
}

void add_wear(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand("wear", "Archard wear of both flanks, wear life and life at reliability R");
  add_file(c, a, "FILE", "the problem file (YAML, docs/yaml.md;\nkeys wear, duty, reliability)");
  add_set(c, a, kProblemSet);
  add_out(c, a, "out/<problem file name>_wear");
  add_json(c, a, "the wear, the lives\nand the files (docs/output.md)");
  add_whole(c, "-n,--samples", "N", 1, kMaxReliabilitySamples,
            "Monte Carlo samples, " + range(1, kMaxReliabilitySamples) + "\n(default reliability.samples)",
            [&a](long v) { a.samples = v; });
  add_whole(c, "--seed", "S", 0, kMaxSeed, "random seed, " + range(0, kMaxSeed) + "\n(default reliability.seed)",
            [&a](long v) { a.seed = v; });
  add_threads(c, a, "all cores");
  c.footer(
      "Writes DIR/wear_profile.csv and, with reliability inputs, life_samples.csv,\n"
      "reliability.csv, life_histogram.csv and plots. The same seed gives the same\n"
      "lives on any number of threads.\n"
      "Examples:\n"
      "  rackopt wear problems/ship_lift.yaml --samples 1000 --json\n"
      "  rackopt wear problems/ship_lift.yaml -n 200 --seed 7 -j 2 -o out/ship_lift_wear");
}

void add_fe(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand("fe", "the analytic mesh model against finite elements (Gmsh + CalculiX)");
  add_file(c, a, "FILE", "the problem file (YAML, docs/yaml.md)");
  add_set(c, a, kProblemSet);
  add_out(c, a, "out/<problem file name>_fe");
  add_json(c, a, "the contents of\nDIR/fe.json (docs/fe.md)");
  add_whole(c, "-p,--positions", "N", 1, fe::kMaxFePositions,
            "travel positions over one mesh period,\n" + range(1, fe::kMaxFePositions) + " (default 4)",
            [&a](long v) { a.positions = static_cast<int>(v); });
  add_whole(c, "-l,--level", "L", 0, kMaxLevel,
            "FE mesh level, " + range(0, kMaxLevel) + " (default 0: the coarsest,\nelements of module/6)",
            [&a](long v) { a.level = static_cast<int>(v); });
  c.add_flag("--extended-contact", a.extended_contact,
             "also let the flanks next to the theoretical pairs touch;\ntheir load is reported, not compared");
  c.add_flag("--pictures", a.pictures, "DIR/fe_mesh.png and DIR/fe_deformed.png of the first\nposition");
  c.add_flag("--rack-supports", a.rack_supports,
             "the rack on its hinged supports in both codes (FE: the\nwhole span; analytic: the coupled rack-span "
             "beam)\ninstead of a rigid body");
  add_threads(c, a, "all cores");
  c.footer(
      "Needs CalculiX ccx (Debian calculix-ccx) and the Gmsh library (libgmsh-dev).\n"
      "Writes DIR/fe.csv, DIR/fe.json and DIR/fe_stiffness.png; docs/fe.md.\n"
      "Examples:\n"
      "  rackopt fe problems/gantry_axis.yaml --positions 4\n"
      "  rackopt fe problems/gantry_axis.yaml -p 8 -l 1 --pictures -o out/gantry_fe");
}

void add_run(CLI::App& app, Args& a) {
  CLI::App& c = *app.add_subcommand("run", "run a study file: evaluate, sweep, optimize, pareto or reliability");
  add_file(c, a, "STUDY", "the study file (YAML, docs/studies.md)");
  add_set(c, a,
          "override a key: problem.<key>=value the problem, any\nother key the study "
          "(e.g. solver.max_evaluations=50)");
  add_out(c, a, "out/<study name>");
  add_json(c, a, "the contents of\nDIR/summary.json");
  add_threads(c, a, "all cores;\n1 per MPI rank under mpirun");
  c.add_flag("--resume", a.resume,
             "continue the study recorded in DIR/evaluations.sqlite\nwithout redoing recorded evaluations");
  c.add_flag("--progress", a.progress, "show the progress bar even when stderr is not a\nterminal");
  add_whole(c, "--ranks", "N", 1, kMaxRanks,
            "run on N MPI ranks, " + range(1, kMaxRanks) + ": starts mpirun -np N with\nthe other options "
            "(Ctrl-C stops cleanly); 1: in this\nprocess, without mpirun",
            [&a](long v) { a.ranks = static_cast<int>(v); });
  c.footer(
      "Every evaluation goes to DIR/evaluations.sqlite as it happens, then\n"
      "DIR/summary.json, CSVs, plots and DIR/report.md. Ctrl-C stops cleanly and\n"
      "writes the results so far.\n"
      "Examples:\n"
      "  rackopt run studies/rack_railway_sizing.yaml --set solver.max_evaluations=50\n"
      "  rackopt run studies/ship_lift_wear_tradeoff.yaml -j 4 -o out/ship_lift_front --resume\n"
      "  rackopt run studies/ship_lift_four_objectives.yaml --ranks 2 --out out/four_mpi");
}

std::unique_ptr<CLI::App> make_app(Args& a) {
  auto app = std::make_unique<CLI::App>("rackopt: design analysis and optimization of rack-and-pinion drives", "rackopt");
  app->get_formatter()->label("Usage", "usage");
  app->get_formatter()->column_width(26);
  app->get_formatter()->label("SUBCOMMAND", "COMMAND");
  app->set_version_flag("-V,--version", std::string("rackopt ") + RACKOPT_VERSION_STRING,
                        "print the version and exit (with --json: {\"ok\": true, \"version\": ...})");
  // Unknown arguments are collected, not thrown, so that the error can name
  // the command and suggest the nearest option.
  app->allow_extras();
  // One command: the name of another after it is an argument too many, not
  // a second command.
  app->require_subcommand(0, 1);
  // A value given twice: the last one counts, as with most programs.
  app->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  // A flag takes no value (--resume=false would read as a typo of intent);
  // --json alone does, as json_requested() reads it before parsing.
  app->option_defaults()->disable_flag_override();
  add_check(*app, a);
  add_stiffness(*app, a);
  add_wear(*app, a);
  add_dynamics(*app, a);
  add_fe(*app, a);
  add_run(*app, a);
  add_json(*app->add_subcommand("version", "print the version, as --version does"), a, "{\"ok\": true, \"version\": text}");
  app->add_subcommand("help", "list the commands, or with COMMAND its options, as --help does");
  for (CLI::App* c : app->get_subcommands([](CLI::App*) { return true; })) c->allow_extras()->group("Commands");
  app->footer(
      "'rackopt COMMAND --help' lists the options of a command, with examples.\n"
      "exit codes: 0 ok (also a study with no feasible design), 1 run failed (also a\n"
      "study whose every evaluation failed, or a result file that cannot be written),\n"
      "2 bad input, usage error or output folder conflict (in use by another run,\n"
      "holds another study), 130 stopped by Ctrl-C or SIGTERM (a second one quits at\n"
      "once); docs/output.md, docs/cli.md");
  return app;
}

std::string selected_command(CLI::App& app) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  return chosen.empty() ? std::string() : chosen.front()->get_name();
}

bool is_option(const std::string& s) { return s.size() > 1 && s[0] == '-'; }

std::vector<std::string> long_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  }
  return names;
}

// The version line, or with --json the object {"ok": true, "version": ...}.
std::string version_text(bool json) {
  if (!json) return std::string("rackopt ") + RACKOPT_VERSION_STRING + "\n";
  JsonWriter j;
  j.begin_object().key("ok").value(true).key("version").value(std::string(RACKOPT_VERSION_STRING)).end_object();
  return j.str() + "\n";
}

// The value of a value option as written: empty or another option means the
// value was forgotten. CLI11 would take `--out= --json` as the folder
// "--json", `-o=DIR` as the folder "=DIR" and `--out ""` as the working
// directory, so argv is checked before it parses. A negative number ("-1")
// is left to the option's own range check.
void check_option_value(const std::string& option, const std::string& long_name, const std::string& value,
                        const std::string& command) {
  if (value.empty()) throw UsageError(option + " needs a value, got an empty one", command);
  const bool number = value.size() > 1 && (std::isdigit(static_cast<unsigned char>(value[1])) || value[1] == '.');
  if (value[0] == '-' && value.size() > 1 && !number) {
    throw UsageError(option + " needs a value, got the option " + value +
                         " (a value that starts with '-' is written " + long_name + "=./" + value + ")",
                     command);
  }
}

// Every value option's value in argv (before "--"), by check_option_value;
// a short option joined to its value by '=' (`-o=DIR`) is refused too.
void refuse_missing_values(CLI::App& app, int argc, char** argv) {
  std::set<std::string> commands;
  std::map<std::string, std::string> long_of;  // "-o" and "--out" -> "--out"
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) {
    commands.insert(c->get_name());
    for (const CLI::Option* o : c->get_options()) {
      if (!o->nonpositional() || o->get_expected_max() == 0) continue;  // FILE, flags
      const std::string long_name = "--" + o->get_lnames().front();
      for (const std::string& n : o->get_snames()) long_of["-" + n] = long_name;
      for (const std::string& n : o->get_lnames()) long_of["--" + n] = long_name;
    }
  }
  std::string command;
  for (int i = 1; i < argc; ++i) {
    const std::string a(argv[i]);
    if (a == "--") break;
    if (command.empty() && commands.count(a) > 0) command = a;
    const std::size_t eq = a.find('=');
    if (a.rfind("--", 0) == 0 && eq != std::string::npos && long_of.count(a.substr(0, eq)) > 0) {
      check_option_value(a.substr(0, eq), long_of[a.substr(0, eq)], a.substr(eq + 1), command);
    } else if (long_of.count(a) > 0) {
      if (i + 1 < argc) check_option_value(a, long_of[a], argv[++i], command);  // else CLI11: "needs a value"
    } else if (a.size() > 2 && a[0] == '-' && a[1] != '-' && long_of.count(a.substr(0, 2)) > 0) {
      if (a[2] == '=') {
        throw UsageError(a.substr(0, 2) + " takes its value after a space (" + a.substr(0, 2) + " " + a.substr(3) +
                             "), not after '='; got " + a,
                         command);
      }
    }
  }
}

// "--set, --out, --json": what `cmd` accepts besides --help.
std::string accepted_options(const CLI::App& cmd) {
  std::string out;
  for (const CLI::Option* o : cmd.get_options()) {
    if (!o->nonpositional() || o == cmd.get_help_ptr() || o->get_lnames().empty()) continue;
    out += (out.empty() ? "--" : ", --") + o->get_lnames().front();
  }
  return out;
}

std::string did_you_mean(const std::string& given, const std::vector<std::string>& candidates) {
  const std::string near = nearest_name(given, candidates);
  return near.empty() ? std::string() : "; did you mean " + near + "?";
}

// The first argument `cmd` did not take, as a usage error: an option of
// another command, an unknown option (with the nearest one), or an argument
// too many.
[[noreturn]] void refuse_extra(CLI::App& app, const CLI::App& cmd, const std::string& extra, bool after_dashes) {
  const std::string name = cmd.get_name();
  if (after_dashes) {
    throw UsageError("unexpected argument " + extra + " after '--' (every argument after '--' is a file name, and " +
                         name + " takes one FILE; options go before '--')",
                     name);
  }
  if (!is_option(extra)) throw UsageError("unexpected argument " + extra, name);
  const std::string option = extra.substr(0, extra.find('='));
  for (const CLI::App* other : app.get_subcommands([](const CLI::App*) { return true; })) {
    for (const CLI::Option* o : other->get_options()) {
      if (o->nonpositional() && o->check_name(option)) {
        const std::string accepted = accepted_options(cmd);
        throw UsageError("option " + option + " does not apply to '" + name + "' (" + name +
                             (accepted.empty() ? " takes no options)" : " accepts " + accepted + ")"),
                         name);
      }
    }
  }
  const bool is_long = option.rfind("--", 0) == 0;
  throw UsageError("unknown option " + option + (is_long ? did_you_mean(option, long_names(cmd)) : ""), name);
}

[[noreturn]] void refuse_command(CLI::App& app, const std::string& word) {
  std::vector<std::string> commands;
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(c->get_name());
  const std::string near = nearest_name(word, commands);
  throw UsageError("unknown command '" + word + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?"));
}

// `rackopt help [COMMAND]`: the help of the program or of COMMAND.
std::string help_text(CLI::App& app, const std::vector<std::string>& words) {
  if (words.empty()) return app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
  if (words.size() > 1) throw UsageError("unexpected argument " + words[1], "help");
  const std::string& topic = words.front();
  const std::vector<CLI::App*> found = app.get_subcommands([&topic](CLI::App* c) { return c->get_name() == topic; });
  if (found.empty()) refuse_command(app, topic);
  return found.front()->help(app.get_name());
}

// CLI11's wording of a value missing or given to a flag, in the words of the
// other usage errors.
std::string mismatch_message(const std::string& what) {
  auto ends_with = [&what](const std::string& end) {
    return what.size() > end.size() && what.compare(what.size() - end.size(), end.size(), end) == 0;
  };
  if (ends_with(" missing")) return what.substr(0, what.find(':')) + " needs a value";  // "--out: 1 required DIR missing"
  if (ends_with(" was given a disallowed flag override")) return "--" + what.substr(0, what.find(' ')) + " takes no value";
  return what;
}

}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
  CommandLine line;
  line.args.arguments.assign(argv + 1, argv + argc);
  const std::unique_ptr<CLI::App> app = make_app(line.args);
  if (argc > 1 && std::string(argv[1]) == "help") {
    // Before parsing: CLI11 would take the command named after it for a second command.
    line.text = help_text(*app, std::vector<std::string>(argv + 2, argv + argc));
    return line;
  }
  refuse_missing_values(*app, argc, argv);
  try {
    app->parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    line.text = app->help();  // the selected command's, if one was given
    return line;
  } catch (const CLI::CallForVersion&) {
    line.text = version_text(json_requested(argc, argv));
    return line;
  } catch (const CLI::RequiredError&) {  // the only required argument is a command's FILE
    const std::string cmd = selected_command(*app);
    throw UsageError(cmd + " needs a " + (cmd == "run" ? "study" : "problem") + " FILE", cmd);
  } catch (const CLI::ArgumentMismatch& e) {
    throw UsageError(mismatch_message(e.what()), selected_command(*app));
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what(), selected_command(*app));
  } catch (const UsageError& e) {  // a bad value (add_whole): it knows no command
    throw UsageError(e.what(), selected_command(*app));
  }
  // CLI11 leaves the "--" itself among the arguments it did not take.
  auto without_dashes = [](std::vector<std::string> args) {
    args.erase(std::remove(args.begin(), args.end(), std::string("--")), args.end());
    return args;
  };
  const std::vector<std::string> before = without_dashes(app->remaining());
  const std::vector<CLI::App*> chosen = app->get_subcommands();
  if (chosen.empty()) {
    if (before.empty()) throw UsageError("no command given");
    if (is_option(before.front())) {
      throw UsageError("unknown option " + before.front() + did_you_mean(before.front(), long_names(*app)));
    }
    refuse_command(*app, before.front());
  }
  CLI::App& cmd = *chosen.front();
  line.args.command = cmd.get_name();
  // Whether `arg` came after a "--" (a file name, whatever it looks like).
  auto after_dashes = [&](const std::string& arg) {
    const char* const* begin = argv + 1;
    const char* const* end = argv + argc;
    const char* const* dashes = std::find_if(begin, end, [](const char* a) { return std::string(a) == "--"; });
    return std::find_if(dashes, end, [&](const char* a) { return arg == a; }) != end;
  };
  if (!before.empty() && after_dashes(before.front())) refuse_extra(*app, cmd, before.front(), true);
  if (!before.empty()) {
    throw UsageError("option " + before.front() + " before the command; options go after it", cmd.get_name());
  }
  const std::vector<std::string> extra = without_dashes(cmd.remaining());
  if (!extra.empty()) refuse_extra(*app, cmd, extra.front(), after_dashes(extra.front()));
  if (line.args.command == "version") {
    line.text = version_text(line.args.json);
    line.args.command.clear();
  }
  return line;
}

bool json_requested(int argc, char** argv) {
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a(argv[i]);
    if (a == "--") break;  // after it, "--json" is a file name
    if (a == "--json") {
      json = true;
    } else if (a.rfind("--json=", 0) == 0) {
      // CLI11's words for a flag's value; anything else is its usage error.
      const std::string v = a.substr(7);
      for (const char* yes : {"true", "on", "yes", "1", "enable"}) json = json || v == yes;
      for (const char* no : {"false", "off", "no", "0", "disable"}) {
        if (v == no) json = false;
      }
    }
  }
  return json;
}

std::string program_help() {
  Args unused;
  return make_app(unused)->help();
}

}  // namespace rackopt::cli
