// The CalculiX runner's failure paths: a missing solver, a deck ccx rejects,
// a model ccx "solves" although it floats, a solver past its time limit; and
// that a successful solve leaves nothing behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fe_test_support.hpp"
#include "rackopt/fe/ccx_deck.hpp"
#include "rackopt/fe/plane_stress_solve.hpp"

namespace rackopt::fe {
namespace {

namespace fs = std::filesystem;

// A fresh, empty folder for one test's solve folders, removed afterwards.
class WorkFolder {
 public:
  WorkFolder() {
    std::string pattern = (fs::temp_directory_path() / "rackopt-fe-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    path_ = pattern;
  }
  ~WorkFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(path_), fs::directory_iterator()));
  }

 private:
  fs::path path_;
};

PlaneStressModel small_plate() {
  PlaneStressModel m;
  m.mesh = mesh_rectangle(0, 0, 0.02, 0.01, 0.005);
  m.youngs_modulus = testing::kE;
  m.poisson_ratio = testing::kNu;
  fix_node_set(m, "LEFT", 1);
  fix_node_set(m, "BOTTOM_LEFT", 2);
  m.loads = edge_traction_loads(m.mesh, "RIGHT", [](Point2) { return Point2{1e6, 0}; });
  return m;
}

TEST(CcxRunner, SuccessLeavesNoFolder) {
  const WorkFolder work;
  CcxOptions options;
  options.work_parent = work.path().string();
  const PlaneStressResult r = solve_plane_stress(small_plate(), options);
  EXPECT_EQ(r.displacement.size(), small_plate().mesh.nodes.size());
  EXPECT_EQ(work.entries(), 0u);
}

TEST(CcxRunner, MissingSolverNamesTheDebianPackage) {
  CcxOptions options;
  options.program = "/nonexistent/ccx";
  try {
    solve_plane_stress(small_plate(), options);
    FAIL() << "no error for a missing ccx";
  } catch (const CcxNotFound& e) {
    EXPECT_NE(std::string(e.what()).find("calculix-ccx"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ccx"), std::string::npos) << e.what();
  }
}

TEST(CcxRunner, MissingFromPathIsCcxNotFound) {
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path != nullptr ? old_path : "";
  const char* old_ccx = std::getenv("RACKOPT_CCX");
  const std::string saved_ccx = old_ccx != nullptr ? old_ccx : "";
  const WorkFolder empty_bin;
  ::setenv("PATH", empty_bin.path().c_str(), 1);
  ::unsetenv("RACKOPT_CCX");
  EXPECT_THROW(find_ccx(), CcxNotFound);
  ::setenv("PATH", saved.c_str(), 1);
  if (old_ccx != nullptr) ::setenv("RACKOPT_CCX", saved_ccx.c_str(), 1);
  EXPECT_NO_THROW(find_ccx());
}

TEST(CcxRunner, RejectedDeckIsKeptAndNamed) {
  const WorkFolder work;
  CcxOptions options;
  options.work_parent = work.path().string();
  std::string deck = ccx_deck(small_plate(), 1e-5);
  const std::string section = "*SOLID SECTION, ELSET=EALL";
  deck.replace(deck.find(section), section.size(), "*SOLID SECTION, ELSET=NO_SUCH_SET");
  try {
    run_ccx(deck, [](const std::string&) {}, options);
    FAIL() << "ccx accepted a deck with an undefined element set";
  } catch (const CcxError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("*ERROR"), std::string::npos) << what;  // the solver's own words
    EXPECT_NE(what.find(e.deck()), std::string::npos) << what;
    EXPECT_TRUE(fs::exists(e.deck()));
    EXPECT_TRUE(fs::exists(e.log()));
    std::ifstream in(e.deck());
    const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(kept, deck);
  }
}

// Spooles factorizes a floating model without complaint; the balance check
// catches it and keeps the deck.
TEST(CcxRunner, UnsupportedModelIsAnError) {
  const WorkFolder work;
  CcxOptions options;
  options.work_parent = work.path().string();
  PlaneStressModel m = small_plate();
  m.supports.clear();
  fix_node_set(m, "LEFT", 1);  // nothing holds it in y
  m.loads = edge_traction_loads(m.mesh, "RIGHT", [](Point2) { return Point2{1e6, 1e6}; });
  try {
    solve_plane_stress(m, options);
    FAIL() << "no error for a model free to move in y";
  } catch (const CcxError& e) {
    EXPECT_NE(std::string(e.what()).find("balance"), std::string::npos) << e.what();
    EXPECT_TRUE(fs::exists(e.deck()));
  }
}

TEST(CcxRunner, TimeLimitKillsTheSolver) {
  const WorkFolder work;
  const fs::path fake = work.path() / "slow_ccx";
  {
    std::ofstream s(fake);
    s << "#!/bin/sh\nsleep 30\n";
  }
  fs::permissions(fake, fs::perms::owner_all);
  CcxOptions options;
  options.program = fake.string();
  options.time_limit_seconds = 0.3;
  options.work_parent = work.path().string();
  try {
    run_ccx("*HEADING\n", [](const std::string&) {}, options);
    FAIL() << "a hung solver was not stopped";
  } catch (const CcxError& e) {
    EXPECT_NE(std::string(e.what()).find("did not finish within 0.3 s"), std::string::npos) << e.what();
    EXPECT_TRUE(fs::exists(e.deck()));
  }
}

TEST(CcxRunner, BadModelIsRejectedBeforeTheSolve) {
  PlaneStressModel m = small_plate();
  m.poisson_ratio = 0.5;
  EXPECT_THROW(ccx_deck(m, 1e-5), std::invalid_argument);
  m = small_plate();
  m.supports.clear();
  EXPECT_THROW(ccx_deck(m, 1e-5), std::invalid_argument);
  m = small_plate();
  m.mesh.node_sets["nall"] = {0};
  EXPECT_THROW(ccx_deck(m, 1e-5), std::invalid_argument);
}

}  // namespace
}  // namespace rackopt::fe
