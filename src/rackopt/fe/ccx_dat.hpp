// Reading the .dat file CalculiX writes for *NODE PRINT: blocks of
//   " displacements (vx,vy,vz) for set NALL and time  0.1000000E+01"
//   "         1  0.000000E+00  1.000000E-03  0.000000E+00"
// and, with TOTALS=YES, a " total force (fx,fy,fz) for set ..." header
// followed by one line of three numbers. Values carry 7 significant digits
// (CalculiX's E13.6 format): relative resolution 1e-6.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace rackopt::fe {

// One printed block: `quantity` is the header's first words
// ("displacements", "forces", ...), `set` the node set (as CalculiX wrote it,
// upper case), `time` the step time. rows: (node number, three components).
// For forces printed with TOTALS=YES, `has_total` and `total` hold the sum.
struct DatBlock {
  std::string quantity;
  std::string set;
  double time = 0;
  std::vector<std::pair<int, std::array<double, 3>>> rows;
  bool has_total = false;
  std::array<double, 3> total{};
};

// Contact statistics of one contact pair, as *CONTACT PRINT, SLAVE=..,
// MASTER=.. with CF writes them:
//   " statistics for slave set S, master set M and time T", then the total
//   surface force and its moment about the origin (6 numbers), the centre of
//   gravity and mean normal (6), the moment about the centre of gravity (3),
//   and area, normal force (+ = tension) and shear force (3).
// A pair with no contact at that time has zero area and force (its centre
// and mean normal are then NaN), or no statistics at all.
struct ContactStatistics {
  std::string slave;
  std::string master;
  double time = 0;
  std::array<double, 3> force{};   // total surface force (fx, fy, fz)
  std::array<double, 3> moment{};  // its moment about the origin
  std::array<double, 3> centre{};  // centre of gravity of the contact (NaN without contact)
  double area = 0;
  double normal_force = 0;         // + = tension
  double shear_force = 0;
};

// Parses the whole text (contact statistics are skipped: see
// parse_ccx_contact_statistics). Throws std::runtime_error "`file_name`:line: what"
// for a line that is neither a header, a data row nor blank, and for a
// non-finite number (a diverged solve prints NaN).
std::vector<DatBlock> parse_ccx_dat(const std::string& text, const std::string& file_name);

// The contact statistics in the text, in order. Throws std::runtime_error
// "`file_name`:line: what" for a statistics section that does not read.
std::vector<ContactStatistics> parse_ccx_contact_statistics(const std::string& text, const std::string& file_name);

// The last block (the final time) of `quantity` for `set` (any case); throws
// std::runtime_error naming both when there is none.
const DatBlock& find_dat_block(const std::vector<DatBlock>& blocks, const std::string& quantity,
                               const std::string& set);

}  // namespace rackopt::fe
