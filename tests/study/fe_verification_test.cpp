// `verify: fe` of a study with fake FE solves (no Gmsh, no ccx): the best
// design is compared after the study, a failing solve is reported and does
// not cost the study its results, and the report shows both.
#include "rackopt/study/fe_verification.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <string>

#include "rackopt/study_report/study_report.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "study_test_support.hpp"
#include "support/file_text.hpp"

namespace rackopt::study {
namespace {

using rackopt::test_support::read_text;
using testing::railway_spec;
using testing::scratch_path;

constexpr double kDeg = 3.14159265358979323846 / 180;

// K = 0.9 K_analytic of the drive the FE is given, the analytic shares, and
// compliances of 1e-9 m/N.
fe::FeCalls fake_fe() {
  fe::FeCalls c;
  c.mesh_position = [](const Drive& d, double x, const fe::FeOptions&) {
    const MeshState s = MeshStiffnessModel(d).at(x);
    fe::FePosition p;
    p.travel = x;
    p.stiffness = 0.9 * s.stiffness;
    for (const PairState& q : s.pairs) {
      fe::FePair f;
      f.rack_tooth = q.rack_tooth;
      f.pinion_tooth = q.pinion_tooth;
      f.s = q.s;
      f.load_share = q.load_share;
      p.pairs.push_back(f);
    }
    return p;
  };
  c.tooth_compliance = [](const Drive&, fe::ToothMember m, double s, const fe::FeOptions&) {
    fe::ToothComplianceFe t;
    t.member = m;
    t.s = s;
    t.compliance = 1e-9;
    return t;
  };
  return c;
}

StudySpec verified_spec() {
  StudySpec s = railway_spec(StudyKind::kEvaluate);
  s.variables = {testing::continuous("pinion.pressure_angle", 14 * kDeg, 20 * kDeg, 16 * kDeg)};
  s.report_metrics = {metrics::parse_metric_request("contact_ratio")};
  s.verify_fe = FeVerifySpec{};
  s.verify_fe->positions = 3;
  s.verify_fe->level = 1;
  return s;
}

TEST(FeVerification, TheBestDesignIsComparedAfterTheStudyAndReported) {
  const StudySpec spec = verified_spec();
  RunOptions o;
  o.out_dir = scratch_path("fe_verify");
  o.threads = 2;
  o.fe_calls = fake_fe();
  const StudyResult r = run_study(spec, o);
  ASSERT_TRUE(r.best_drive);
  ASSERT_TRUE(r.fe_verification) << r.fe_verification_error;
  EXPECT_TRUE(r.fe_verification_error.empty());
  EXPECT_EQ(r.fe_verification->rows.size(), 3u);
  EXPECT_EQ(r.fe_verification->fe.level, 1);
  EXPECT_NEAR(r.fe_verification->summary.max_k_error, 1.0 / 0.9 - 1.0, 1e-12);
  // The design compared is the study's: 16 deg, not the problem's 14.
  EXPECT_NEAR(r.best_drive->pinion.pressure_angle, 16 * kDeg, 1e-12);

  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  const std::string md = read_text(o.out_dir + "/report.md");
  EXPECT_NE(md.find("## FE verification of the optimum"), std::string::npos);
  EXPECT_NE(md.find("| X [m] | K FE [MN/m]"), std::string::npos);
  EXPECT_NE(md.find("+11.11 %"), std::string::npos) << md;  // (1 - 0.9) / 0.9
  EXPECT_NE(rep.summary_json.find("\"fe_verification\":{\"requested\":{\"positions\":3,\"level\":1"),
            std::string::npos);
  EXPECT_NE(rep.summary_json.find("\"max_k_error\":"), std::string::npos);
  EXPECT_FALSE(rep.files.get("fe_csv").empty());
  EXPECT_TRUE(std::filesystem::exists(rep.files.get("fe_csv")));
}

TEST(FeVerification, AFailedSolveIsReportedAndTheStudyKeepsItsResults) {
  const StudySpec spec = verified_spec();
  RunOptions o;
  o.out_dir = scratch_path("fe_verify_fail");
  o.fe_calls = fake_fe();
  o.fe_calls.mesh_position = [](const Drive&, double, const fe::FeOptions&) -> fe::FePosition {
    throw fe::CcxError("*ERROR in contact: no convergence", "/tmp/rackopt-ccx-abc/job.inp", "job.log");
  };
  const StudyResult r = run_study(spec, o);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(to_string(r.status), "ok");
  EXPECT_FALSE(r.fe_verification);
  EXPECT_NE(r.fe_verification_error.find("no convergence"), std::string::npos) << r.fe_verification_error;
  EXPECT_NE(r.fe_verification_error.find("/tmp/rackopt-ccx-abc/job.inp"), std::string::npos);
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  const std::string md = read_text(o.out_dir + "/report.md");
  EXPECT_NE(md.find("was not verified by FE: FE solve failed: *ERROR in contact"), std::string::npos) << md;
  EXPECT_NE(rep.summary_json.find("\"ok\":false,\"error\":\"FE solve failed"), std::string::npos);
  EXPECT_TRUE(rep.files.get("fe_csv").empty());
}

TEST(FeVerification, AStopDuringTheSolvesStopsTheStudyAndTheReportSaysSo) {
  const StudySpec spec = verified_spec();
  RunOptions o;
  o.out_dir = scratch_path("fe_verify_stop");
  o.threads = 1;
  std::atomic<bool> stop{false};
  o.stop = [&stop] { return stop.load(); };
  o.fe_calls = fake_fe();
  const auto solve = o.fe_calls.mesh_position;
  // Ctrl-C while the first FE position solves.
  o.fe_calls.mesh_position = [&stop, solve](const Drive& d, double x, const fe::FeOptions& f) {
    stop = true;
    return solve(d, x, f);
  };
  const StudyResult r = run_study(spec, o);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(to_string(r.status), "stopped");
  EXPECT_FALSE(r.fe_verification);
  EXPECT_NE(r.fe_verification_error.find("stopped"), std::string::npos) << r.fe_verification_error;
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  EXPECT_NE(rep.summary_json.find("\"status\":\"stopped\""), std::string::npos) << rep.summary_json;
  const std::string md = read_text(o.out_dir + "/report.md");
  EXPECT_NE(md.find("stopped after 1 evaluation, during the FE verification of the best design"), std::string::npos)
      << md;
  EXPECT_NE(md.find("--resume"), std::string::npos);
}

TEST(FeVerification, NothingWithoutVerifyAndNoSolveWithoutADesign) {
  StudySpec spec = verified_spec();
  spec.verify_fe.reset();
  RunOptions o;
  o.out_dir = scratch_path("fe_verify_none");
  int solves = 0;
  o.fe_calls = fake_fe();
  o.fe_calls.mesh_position = [&](const Drive&, double, const fe::FeOptions&) -> fe::FePosition {
    ++solves;
    return {};
  };
  const StudyResult r = run_study(spec, o);
  EXPECT_FALSE(r.fe_verification);
  EXPECT_TRUE(r.fe_verification_error.empty());
  const study_report::StudyReport rep = study_report::write_study_report(spec, r, o.out_dir);
  EXPECT_EQ(read_text(o.out_dir + "/report.md").find("FE verification"), std::string::npos);
  EXPECT_EQ(rep.summary_json.find("fe_verification"), std::string::npos);

  StudyResult none;
  none.status = study::StudyStatus::kNoFeasiblePoint;
  verify_best_design_by_fe(verified_spec(), o, none);
  EXPECT_EQ(solves, 0);
  EXPECT_NE(none.fe_verification_error.find("no design to verify"), std::string::npos);
}

}  // namespace
}  // namespace rackopt::study
