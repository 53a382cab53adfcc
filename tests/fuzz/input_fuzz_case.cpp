#include "input_fuzz_case.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/studyfile/study_loader.hpp"

namespace rackopt::fuzz {
namespace {

// A valid problem for the --set path: small, so that a run stays fast.
const char* const kSmallProblem =
    "pinion: {teeth: 20, module: 10 mm, face_width: 50 mm}\n"
    "rack: {body_height: 80 mm, span: 2 m}\n"
    "load: {force: 10 kN}\n";

constexpr std::size_t kMaxSetLines = 8;

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) {
    throw std::logic_error(std::string("non-finite ") + what + " from a drive the loader accepted");
  }
}

void exercise_geometry(const Drive& drive) {
  const MeshGeometry g = build_mesh_geometry(drive);
  require_finite(g.path.contact_ratio, "contact ratio");
  require_finite(g.path.s_start, "start of contact");
  require_finite(g.path.s_end, "end of contact");
  require_finite(g.pinion.tip_thickness, "tip thickness");
  for (const auto& change : pair_count_changes(g)) require_finite(change.s, "pair count change");
  for (double s : contact_positions(g, g.path.s_start)) require_finite(s, "contact position");
}

// Runs `step`; InputError and DesignError are the correct answer to bad input.
template <typename F>
void refused_or_ok(F step) {
  try {
    step();
  } catch (const InputError&) {
  } catch (const DesignError&) {
  }
}

}  // namespace

void run_input_fuzz_case(std::string_view data, const std::string& studies_dir) {
  const std::string text(data);
  std::vector<std::string> overrides;
  std::string first_line;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (start == 0) first_line = line;
    if (line.rfind("#set ", 0) == 0 && overrides.size() < kMaxSetLines) overrides.push_back(line.substr(5));
    start = end + 1;
  }

  refused_or_ok([&] { exercise_geometry(load_problem_text(text, "fuzz.yaml", overrides)); });
  refused_or_ok([&] { exercise_geometry(load_problem_text(kSmallProblem, "small.yaml", {first_line})); });
  refused_or_ok([&] { studyfile::load_study_text(text, "fuzz_study.yaml", studies_dir, overrides); });
}

}  // namespace rackopt::fuzz
