#include "rackopt/problem/drive_sections.hpp"

#include "rackopt/problem/problem_key_schema.hpp"

namespace rackopt {
namespace {

const std::vector<std::string> kTopKeys = {"name",   "description", "variant",   "variants", "pinion",
                                           "rack",   "mounting",    "materials", "load",     "effects",
                                           "faults", "numerics",    "wear",      "duty",     "reliability", "dynamics"};

}  // namespace

SectionReader problem_top_section(const MarkedNode& root, const std::string& file) {
  if (!root.is_null() && !root.is_map()) {
    throw InputError(root.mark, "",
                     "a problem file is a map of sections (pinion, rack, load, ...), found " + root.type_name());
  }
  const SourceMark top_mark = root.is_null() ? SourceMark{file, 1, 1} : root.mark;
  return problem_section(&root, "", "", top_mark, kTopKeys);
}

Drive build_drive(const MarkedNode& root, const std::string& file) {
  const SectionReader top = problem_top_section(root, file);
  Drive drive;
  drive.source_file = file;
  {
    std::string stem = file;
    const std::size_t slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    const std::size_t dot = stem.rfind('.');
    if (dot != std::string::npos && dot > 0) stem = stem.substr(0, dot);
    drive.name = top.text("name", stem);
  }
  top.text("description", "");  // checked to be text; the Drive has no field for it

  const std::map<std::string, Material> materials = read_materials(top);
  read_pinion(top, materials, drive);
  read_rack(top, materials, drive);
  read_mounting(top, drive);
  read_load(top, drive);
  read_effects(top, drive);
  read_faults(top, drive);
  read_numerics(top, drive);
  read_wear(top, drive);
  read_duty(top, drive);
  read_reliability(top, drive);
  read_dynamics(top, drive);
  return drive;
}

}  // namespace rackopt
