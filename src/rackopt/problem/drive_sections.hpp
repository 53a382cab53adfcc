// The readers of the problem file's sections, each filling its part of the
// Drive (docs/yaml.md is the reference of every key). build_drive composes
// them in the order that the later sections' derived limits need: geometry
// first (the module bounds reliefs, wear depth and clearance), then load,
// model settings, faults, wear, duty, reliability and dynamics (which checks
// effects.dynamics against the load).
#pragma once

#include <map>
#include <string>

#include "rackopt/core/drive.hpp"
#include "rackopt/marked_yaml/section_reader.hpp"

namespace rackopt {

// The top-level map of a problem file.
SectionReader problem_top_section(const MarkedNode& root, const std::string& file);

// The whole schema: a validated tree (overrides and variant already merged)
// to a Drive.
Drive build_drive(const MarkedNode& root, const std::string& file);

// `materials`: built-in steel, then the file's (which may redefine steel).
std::map<std::string, Material> read_materials(const SectionReader& top);
void read_pinion(const SectionReader& top, const std::map<std::string, Material>& materials, Drive& drive);
void read_rack(const SectionReader& top, const std::map<std::string, Material>& materials, Drive& drive);
void read_mounting(const SectionReader& top, Drive& drive);

// A tip or root relief of one member; `schema_path` is the relief map's
// ("pinion.tip_relief"). Absent: no relief.
ProfileRelief read_relief(const SectionReader& member, const std::string& key, const std::string& schema_path,
                          double module);

void read_load(const SectionReader& top, Drive& drive);
void read_effects(const SectionReader& top, Drive& drive);
void read_numerics(const SectionReader& top, Drive& drive);
void read_faults(const SectionReader& top, Drive& drive);

// A hardness profile map (or a single hardness: constant profile) at `path`.
HardnessProfile read_hardness(const MarkedNode& node, const std::string& path);
void read_wear(const SectionReader& top, Drive& drive);
void read_duty(const SectionReader& top, Drive& drive);
void read_reliability(const SectionReader& top, Drive& drive);
// `dynamics` (docs/yaml.md): the drive as a vibrating system. Read after load
// and effects: effects.dynamics needs a moving mass and load.speed.
void read_dynamics(const SectionReader& top, Drive& drive);

}  // namespace rackopt
