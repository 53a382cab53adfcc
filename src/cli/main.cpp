// rackopt command line.
//
//   rackopt check FILE [--set key=value]...
//   rackopt stiffness FILE [--set key=value]... [--out DIR] [--json]
//
// Exit codes: 0 ok, 1 run failed, 2 bad input (file, key, value or an
// impossible design). With --json exactly one JSON object goes to stdout and
// everything meant for people goes to stderr.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>

#include "rackopt/core/error.hpp"
#include "rackopt/output/atomic_file.hpp"
#include "rackopt/output/json_writer.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace {

constexpr int kOk = 0;
constexpr int kRunFailed = 1;
constexpr int kBadInput = 2;

const char* kUsage =
    "usage:\n"
    "  rackopt check FILE [--set key=value]...\n"
    "      validate a problem file and print the contact geometry\n"
    "  rackopt stiffness FILE [--set key=value]... [--out DIR] [--json]\n"
    "      mesh stiffness over one rack span: DIR/stiffness.csv, DIR/stiffness.png\n"
    "      (default DIR: out/<problem name>); --json prints one JSON object on stdout\n"
    "\n"
    "  --set key=value   override any key of the problem, e.g. --set rack.span=\"1.2 m\"\n"
    "exit codes: 0 ok, 1 run failed, 2 bad input\n";

struct Args {
  std::string command;
  std::string file;
  std::vector<std::string> overrides;
  std::string out_dir;
  bool json = false;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Args parse_args(int argc, char** argv) {
  Args a;
  std::vector<std::string> rest(argv + 1, argv + argc);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const std::string& s = rest[i];
    auto need_value = [&](const std::string& flag) -> std::string {
      if (i + 1 >= rest.size()) throw UsageError(flag + " needs a value");
      return rest[++i];
    };
    if (s == "--set") {
      a.overrides.push_back(need_value(s));
    } else if (s.rfind("--set=", 0) == 0) {
      a.overrides.push_back(s.substr(6));
    } else if (s == "--out") {
      a.out_dir = need_value(s);
    } else if (s.rfind("--out=", 0) == 0) {
      a.out_dir = s.substr(6);
    } else if (s == "--json") {
      a.json = true;
    } else if (s == "-h" || s == "--help") {
      a.command = "help";
    } else if (!s.empty() && s[0] == '-') {
      throw UsageError("unknown option " + s);
    } else if (a.command.empty()) {
      a.command = s;
    } else if (a.file.empty()) {
      a.file = s;
    } else {
      throw UsageError("unexpected argument " + s);
    }
  }
  return a;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Runs gnuplot on DIR/stiffness.gp; the PNG is written under a temporary
// name and renamed, so a failed plot never leaves a half-written image.
// Returns the PNG path, or "" (with a warning) when gnuplot is unavailable.
std::string render_plot(const std::filesystem::path& dir, std::vector<std::string>& warnings) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    warnings.push_back("gnuplot not found: wrote stiffness.gp but no plot (install gnuplot-nox)");
    return "";
  }
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot stiffness.gp >/dev/null 2>gnuplot.log";
  if (std::system(cmd.c_str()) != 0) {
    warnings.push_back("gnuplot failed: see " + (dir / "gnuplot.log").string());
    return "";
  }
  std::filesystem::remove(dir / "gnuplot.log");
  std::error_code ec;
  std::filesystem::rename(dir / "stiffness.png.tmp", dir / "stiffness.png", ec);
  if (ec) {
    warnings.push_back("could not place the plot: " + ec.message());
    return "";
  }
  return (dir / "stiffness.png").string();
}

int cmd_check(const Args& a) {
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  const rackopt::MeshStiffnessModel model(drive);
  std::string text = rackopt::geometry_summary(drive, model.geometry());
  for (std::size_t i = model.geometry().warnings.size(); i < model.warnings().size(); ++i) {
    text += "  warning: " + model.warnings()[i] + "\n";
  }
  if (a.json) {
    rackopt::JsonWriter j;
    j.begin_object();
    j.key("ok").value(true);
    j.key("contact_ratio").value(model.geometry().path.contact_ratio);
    j.key("warnings").begin_array();
    for (const auto& w : model.warnings()) j.value(w);
    j.end_array();
    j.end_object();
    std::cerr << text;
    std::cout << j.str() << "\n";
  } else {
    std::cout << text << "ok: " << a.file << "\n";
  }
  return kOk;
}

int cmd_stiffness(const Args& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const rackopt::Drive drive = rackopt::load_problem(a.file, a.overrides);
  const rackopt::MeshStiffnessModel model(drive);
  rackopt::Timings t;
  t.model_ms = ms_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  rackopt::StiffnessCurve curve = model.curve();
  t.curve_ms = ms_since(t1);

  namespace fs = std::filesystem;
  fs::path dir = a.out_dir.empty() ? fs::path("out") / fs::path(a.file).stem() : fs::path(a.out_dir);
  const fs::path csv = dir / "stiffness.csv";
  rackopt::write_file_atomic(csv.string(), rackopt::stiffness_csv(curve));
  const std::string title = (drive.name.empty() ? fs::path(a.file).stem().string() : drive.name);
  rackopt::write_file_atomic((dir / "stiffness.gp").string(),
                             rackopt::stiffness_gnuplot(curve, title, "stiffness.csv", "stiffness.png.tmp"));
  const std::string png = render_plot(dir, curve.warnings);
  t.total_ms = ms_since(t0);

  std::string text = rackopt::geometry_summary(drive, model.geometry()) + rackopt::stiffness_summary(curve);
  text += "  wrote " + csv.string() + "\n";
  text += png.empty() ? "  no plot (see warnings)\n" : "  plot  " + png + "\n";
  for (std::size_t i = model.warnings().size(); i < curve.warnings.size(); ++i) {
    text += "  warning: " + curve.warnings[i] + "\n";
  }
  if (a.json) {
    std::cerr << text;
    std::cout << rackopt::stiffness_json(drive, model.geometry(), curve, t, csv.string(), png) << "\n";
  } else {
    std::cout << text;
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();  // GSL would abort() the process otherwise
  Args args;
  try {
    args = parse_args(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "rackopt: " << e.what() << "\n" << kUsage;
    return kBadInput;
  }
  if (args.command.empty() || args.command == "help") {
    std::cerr << kUsage;
    return args.command == "help" ? kOk : kBadInput;
  }
  if (args.command != "check" && args.command != "stiffness") {
    std::cerr << "rackopt: unknown command '" << args.command << "'\n" << kUsage;
    return kBadInput;
  }
  if (args.file.empty()) {
    std::cerr << "rackopt: " << args.command << " needs a problem FILE\n" << kUsage;
    return kBadInput;
  }
  auto fail = [&](int code, const std::string& kind, const std::string& msg) {
    if (args.json) {
      rackopt::JsonWriter j;
      j.begin_object().key("ok").value(false).key("error").value(kind).key("message").value(msg).end_object();
      std::cout << j.str() << "\n";
    }
    std::cerr << "rackopt: " << msg << "\n";
    return code;
  };
  try {
    return args.command == "check" ? cmd_check(args) : cmd_stiffness(args);
  } catch (const rackopt::InputError& e) {
    return fail(kBadInput, "input", e.what());
  } catch (const rackopt::DesignError& e) {
    return fail(kBadInput, "design:" + e.code(), std::string("impossible design (") + e.code() + "): " + e.what());
  } catch (const std::exception& e) {
    return fail(kRunFailed, "run", std::string("run failed: ") + e.what());
  }
}
