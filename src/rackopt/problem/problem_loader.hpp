// Problem files (YAML) -> rackopt::Drive, with errors that say where and why.
//
// docs/yaml.md is the user-facing reference of every key (kind, default unit,
// default value, allowed range). The key paths are a contract: studies and
// `--set` address them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/units/units.hpp"

namespace rackopt {

// Reads the problem file at `path` and returns the drive in SI units.
// `overrides` are `--set` assignments "key.path=value" applied in order over
// the file before validation (docs/yaml.md "Overrides"); `variant=<name>`
// selects one of the file's `variants`.
// Throws InputError (file:line:column, dotted key path, what is allowed) for
// anything the file or an override gets wrong; values from overrides carry the
// file name "<command line>". The file not being readable is an InputError too.
// Everything the Drive leaves as "0 = not given" is filled in: rack face width,
// body width, tooth offset, the rack section, the bore radius (0.5 r_f; left
// 0 only when r_f <= 0, which the geometry rejects), and for wear: each
// hardness profile's core (measured data: its value at the deepest measured
// point; constant: the surface), a case-hardened limit (0.8 x surface) and
// duty.pinion_meshes_per_year (= the rack's). Exceptions, on purpose:
// wear.coefficient stays 0 when the file has no `wear` section (wear not
// configured), and duty stays 0 when it has no `duty` (lives in cycles only);
// the stress inputs keep their "not given" 0 too: material allowables (the
// safety metrics then refuse to run), rack.root_radius (= the cutter tip
// radius) and load.face_load_factor_bending (derived from K_Hbeta where the
// stresses are computed, metrics::drive_load_factors). Load factors < 1 are
// refused (ISO 6336 factors are >= 1).
// A `wear` section requires wear.coefficient and a hardness for both members.
// An override of a key that changes the design value of a random input the
// file gives as an absolute distribution is an InputError naming both
// (problem/random_input_keys.hpp).
Drive load_problem(const std::string& path, const std::vector<std::string>& overrides = {});

// Same, from text; `name_for_messages` is the file name used in marks and
// (its stem) the default drive name.
Drive load_problem_text(const std::string& yaml_text, const std::string& name_for_messages,
                        const std::vector<std::string>& overrides = {});

// A problem file parsed, its selected variant merged and the overrides
// applied, but not yet turned into a Drive: studies keep one and set design
// variables on copies (apply_override) without re-reading the file.
struct ProblemTree {
  MarkedNode root;
  std::string file;     // for messages
  std::string variant;  // selected variant ("" = none)
};

// load_problem split in two: the tree (every variant validated, like
// load_problem) and the drive built from a tree. load_problem_text(t, n, o)
// == drive_from_tree(load_problem_tree(t, n, o)) followed by
// check_overrides_against_absolute_inputs(drive, o), which callers of the
// two halves run themselves. Same errors as load_problem otherwise.
ProblemTree load_problem_tree(const std::string& yaml_text, const std::string& name_for_messages,
                              const std::vector<std::string>& overrides = {});
ProblemTree load_problem_tree_file(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from a problem already parsed (parse_marked_yaml), its marks kept:
// a problem held in memory, such as a study file's inline `problem:` map,
// whose errors then point into the text it was parsed from.
// `name_for_messages` names the drive (its stem) like the file name does.
ProblemTree load_problem_tree_node(MarkedNode root, const std::string& name_for_messages,
                                   const std::vector<std::string>& overrides = {});
Drive drive_from_tree(const ProblemTree& tree);

// Names of the variants a problem file defines (file order); empty if none.
// Throws InputError like load_problem.
std::vector<std::string> problem_variants(const std::string& path);

// Section properties of a rectangular rack body `width` x `height` [m]:
// A = b h, I = b h^3 / 12, shear area = A / 1.2 (rectangle, Timoshenko
// kappa = 5/6), neutral axis h/2 below the tooth root line.
RackSection rectangular_rack_section(double width, double height);

}  // namespace rackopt
