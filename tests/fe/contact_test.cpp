// The contact pipeline against a closed form: two blocks of different
// materials pressed together through a frictionless penalty contact on
// non-matching meshes. Uniaxial stress in both, so the stiffness is the
// series value W / (H1/E1 + H2/E2) per unit thickness; the penalty adds
// p / slope of overclosure, which the secant of two steps does not remove.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "rackopt/fe/ccx_contact_deck.hpp"
#include "rackopt/fe/ccx_dat.hpp"
#include "rackopt/fe/gmsh_mesher.hpp"

namespace rackopt::fe {
namespace {

constexpr double kW = 0.02, kH1 = 0.01, kH2 = 0.015, kE1 = 210e9, kE2 = 70e9;

struct Blocks {
  double k = 0;            // secant stiffness (N/m per m of thickness)
  double contact_sum = 0;  // contact force change / reaction change (y)
};

Blocks press(double slope_factor) {
  ContactModel m;
  m.bodies.push_back({"LOW", mesh_rectangle(0, 0, kW, kH1, kH1 / 4), kE1, 0.3});
  m.bodies.push_back({"UP", mesh_rectangle(0, kH1, kW, kH2, kH2 / 5), kE2, 0.25});
  m.steps = 2;
  const double d1 = 1e-6, d2 = 3e-6;
  for (int n : m.bodies[0].mesh.node_set("BOTTOM")) m.supports.push_back({0, n, 2, {0, 0}});
  m.supports.push_back({0, m.bodies[0].mesh.node_set("BOTTOM_LEFT")[0], 1, {0, 0}});
  for (int n : m.bodies[1].mesh.node_set("TOP")) m.supports.push_back({1, n, 2, {-d1, -d2}});
  m.supports.push_back({1, m.bodies[1].mesh.node_set("TOP_LEFT")[0], 1, {0, 0}});
  m.contacts.push_back({1, "BOTTOM", 0, "TOP"});
  m.penalty_slope = slope_factor * kE2 / kH2;
  m.reaction_sets = {{0, "BOTTOM"}};
  const std::vector<ContactStepResult> r = solve_contact(m);
  EXPECT_EQ(r.size(), 2u);
  double f[2] = {0, 0};
  for (int s = 0; s < 2; ++s) {
    for (const auto& [node, force] : r[s].reactions[0]) f[s] += force.y;
    EXPECT_TRUE(r[s].in_contact[0]);
  }
  Blocks b;
  b.k = (f[1] - f[0]) / (d2 - d1);
  b.contact_sum = std::abs(r[1].contact_force[0].y - r[0].contact_force[0].y) / (f[1] - f[0]);
  return b;
}

TEST(ContactPipeline, BlocksInSeriesMatchTheClosedForm) {
  const double exact = kW / (kH1 / kE1 + kH2 / kE2);
  const Blocks b = press(1e4);
  EXPECT_NEAR(b.k / exact, 1.0, 5e-3);
  // The contact statistics carry the same force as the supports.
  EXPECT_NEAR(b.contact_sum, 1.0, 1e-4);
  // Doubling the penalty slope moves the stiffness by less than 0.1 %.
  const Blocks stiffer = press(2e4);
  EXPECT_LT(std::abs(stiffer.k / b.k - 1), 1e-3);
}

TEST(ContactPipeline, MissingCcxIsCcxNotFound) {
  ContactModel m;
  m.bodies.push_back({"A", mesh_rectangle(0, 0, 1, 1, 0.5), kE1, 0.3});
  for (int n : m.bodies[0].mesh.node_set("BOTTOM")) m.supports.push_back({0, n, 2, {0}});
  m.penalty_slope = 1;
  CcxOptions o;
  o.program = "/nonexistent/ccx";
  EXPECT_THROW(solve_contact(m, o), CcxNotFound);
}

TEST(ContactPipeline, NonConvergenceIsCcxErrorWithTheDeckKept) {
  namespace fs = std::filesystem;
  std::string folder = (fs::temp_directory_path() / "rackopt-fe-test-XXXXXX").string();
  ASSERT_NE(::mkdtemp(folder.data()), nullptr);
  ContactModel m;
  m.bodies.push_back({"LOW", mesh_rectangle(0, 0, kW, kH1, kH1 / 2), kE1, 0.3});
  m.bodies.push_back({"UP", mesh_rectangle(0, kH1, kW, kH2, kH2 / 2), kE2, 0.25});
  for (int n : m.bodies[0].mesh.node_set("BOTTOM")) m.supports.push_back({0, n, 2, {0}});
  m.supports.push_back({0, m.bodies[0].mesh.node_set("BOTTOM_LEFT")[0], 1, {0}});
  for (int n : m.bodies[1].mesh.node_set("TOP")) m.supports.push_back({1, n, 2, {-1e-6}});
  m.supports.push_back({1, m.bodies[1].mesh.node_set("TOP_LEFT")[0], 1, {0}});
  m.contacts.push_back({1, "BOTTOM", 0, "TOP"});
  m.penalty_slope = 1e29 * kE2 / kH2;  // far beyond what the Newton iteration can follow
  m.reaction_sets = {{0, "BOTTOM"}};
  CcxOptions o;
  o.work_parent = folder;
  try {
    solve_contact(m, o);
    ADD_FAILURE() << "the solve converged";
  } catch (const CcxError& e) {
    EXPECT_TRUE(fs::exists(e.deck())) << e.what();
    EXPECT_NE(std::string(e.what()).find("cutbacks"), std::string::npos) << e.what();
  }
  std::error_code ec;
  fs::remove_all(folder, ec);
}

TEST(CcxDat, ReadsContactStatistics) {
  const char* dat = R"(
 forces (fx,fy,fz) for set LOW_BOTTOM and time  0.1000000E+01

         1 -1.000000E+00  2.000000E+00  0.000000E+00

 statistics for slave set C0S, master set C0M and time  0.1000000E+01

   total surface force (fx,fy,fz) and moment about the origin (mx,my,mz)

   -1.106472E-14  1.665556E+02  3.783198E-12 -6.916899E-10 -2.299718E-12  8.327786E+01

   center of gravity and mean normal

    5.000002E-01  9.999992E-01  3.166551E-20  6.643256E-17 -1.000000E+00 -2.271433E-14

   moment about the center of gravity(mx,my,mz)

   -6.954731E-10 -4.081180E-13 -2.477558E-07

   area,  normal force (+ = tension) and shear force (size)

    1.000000E-03 -1.665556E+02  1.178964E-18
)";
  const std::vector<ContactStatistics> s = parse_ccx_contact_statistics(dat, "job.dat");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].slave, "C0S");
  EXPECT_EQ(s[0].master, "C0M");
  EXPECT_DOUBLE_EQ(s[0].time, 1.0);
  EXPECT_DOUBLE_EQ(s[0].force[1], 166.5556);
  EXPECT_DOUBLE_EQ(s[0].centre[1], 0.9999992);
  EXPECT_DOUBLE_EQ(s[0].area, 1e-3);
  EXPECT_DOUBLE_EQ(s[0].normal_force, -166.5556);
  // The ordinary reader skips the statistics and keeps the blocks.
  const std::vector<DatBlock> blocks = parse_ccx_dat(dat, "job.dat");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].rows.size(), 1u);
  // A pair out of contact: zero area and force, NaN centre; a NaN force is an error.
  const char* apart = R"(
 statistics for slave set C1S, master set C1M and time  0.2000000E+01

   total surface force (fx,fy,fz) and moment about the origin (mx,my,mz)

    0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00

   center of gravity and mean normal

             NaN           NaN           NaN           NaN           NaN           NaN

   moment about the center of gravity(mx,my,mz)

             NaN           NaN           NaN

   area,  normal force (+ = tension) and shear force (size)

    0.000000E+00           NaN           NaN
)";
  const std::vector<ContactStatistics> a = parse_ccx_contact_statistics(apart, "job.dat");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].area, 0);
  EXPECT_EQ(a[0].force[0], 0);
  EXPECT_EQ(a[0].normal_force, 0);
  std::string diverged = apart;
  diverged.replace(diverged.find("0.000000E+00"), 12, "NaN");
  EXPECT_THROW(parse_ccx_contact_statistics(diverged, "job.dat"), std::runtime_error);
  // A truncated section is an error.
  EXPECT_THROW(parse_ccx_contact_statistics(std::string(dat).substr(0, std::string(dat).size() - 60), "job.dat"),
               std::runtime_error);
}

}  // namespace
}  // namespace rackopt::fe
