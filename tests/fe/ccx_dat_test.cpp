// Reading CalculiX .dat output, from text as ccx 2.20 writes it.
#include <gtest/gtest.h>

#include <stdexcept>

#include "rackopt/fe/ccx_dat.hpp"

namespace rackopt::fe {
namespace {

const char* kDat = R"(
 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  0.000000E+00  0.000000E+00 -9.926167E-24
         2  1.000000E-03  1.506604E-13  0.297785-100

 forces (fx,fy,fz) for set LEFT and time  0.1000000E+01

         1 -1.666667E-04 -7.548175E-15 -2.409943E-18
         9 -6.666667E-04  3.274999E-15  2.538724E-17

 total force (fx,fy,fz) for set LEFT and time  0.1000000E+01

       -8.333334E-04 -2.865554E-15  3.917856E-17
)";

TEST(CcxDat, ReadsBlocksRowsAndTotals) {
  const std::vector<DatBlock> blocks = parse_ccx_dat(kDat, "job.dat");
  ASSERT_EQ(blocks.size(), 2u);
  const DatBlock& u = find_dat_block(blocks, "displacements", "nall");
  EXPECT_EQ(u.set, "NALL");
  EXPECT_DOUBLE_EQ(u.time, 1.0);
  ASSERT_EQ(u.rows.size(), 2u);
  EXPECT_EQ(u.rows[1].first, 2);
  EXPECT_DOUBLE_EQ(u.rows[1].second[0], 1e-3);
  EXPECT_DOUBLE_EQ(u.rows[1].second[2], 0.297785e-100);  // Fortran's E-less three-digit exponent
  const DatBlock& f = find_dat_block(blocks, "forces", "LEFT");
  EXPECT_EQ(f.rows.size(), 2u);
  ASSERT_TRUE(f.has_total);
  EXPECT_DOUBLE_EQ(f.total[0], -8.333334e-4);
  EXPECT_FALSE(u.has_total);
}

TEST(CcxDat, MissingBlockNamesIt) {
  const std::vector<DatBlock> blocks = parse_ccx_dat(kDat, "job.dat");
  try {
    find_dat_block(blocks, "forces", "ROOT");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("forces for set ROOT"), std::string::npos) << e.what();
  }
}

TEST(CcxDat, BadLinesNameFileAndLine) {
  const std::string broken =
      "\n displacements (vx,vy,vz) for set NALL and time  0.1000000E+01\n\n"
      "         1  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "         3  1.0E-03  nonsense  0.0\n";
  try {
    parse_ccx_dat(broken, "job.dat");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("job.dat:5: not a number 'nonsense'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_ccx_dat(" displacements (vx,vy,vz) for set NALL and time  1.0\n 1 NaN 0 0\n", "x.dat"),
               std::runtime_error);
  EXPECT_THROW(parse_ccx_dat("  1 0 0 0\n", "x.dat"), std::runtime_error);  // data before any header
}

}  // namespace
}  // namespace rackopt::fe
