// The FE comparison's own logic with fake FE solves (no Gmsh, no ccx): which
// positions, which drive the solves see, the error arithmetic, ordering,
// thread-count invariance, error propagation and the files' shape.
#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>
#include <thread>

#include "fe_test_helpers.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/fe/fe_comparison.hpp"
#include "rackopt/fe/fe_comparison_report.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/output/file_check.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

using testing::gantry;

// Fake FE: K = 0.8 K_analytic of the drive it is given, shares moved by
// +0.05 / -0.05 between the first and the last pair, compliances a known
// function of s and the member. Deterministic; the sleep (longer for early
// positions) makes the threads finish out of order.
struct Fake {
  std::mutex m;
  std::vector<Drive> seen;
  bool sleep = false;
  FeCalls calls() {
    FeCalls c;
    c.mesh_position = [this](const Drive& d, double x, const FeOptions&) {
      {
        std::lock_guard<std::mutex> lock(m);
        seen.push_back(d);
      }
      const MeshStiffnessModel model(d);
      const MeshState s = model.at(x);
      if (sleep) std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<int>(20 - 1000 * std::fmod(x, 0.02))));
      FePosition p;
      p.travel = x;
      p.stiffness = 0.8 * s.stiffness;
      p.force = d.load.force;
      p.seconds = 2.0;
      p.nodes = 100;
      p.elements = 40;
      for (std::size_t k = 0; k < s.pairs.size(); ++k) {
        FePair q;
        q.rack_tooth = s.pairs[k].rack_tooth;
        q.pinion_tooth = s.pairs[k].pinion_tooth;
        q.s = s.pairs[k].s;
        q.load_share = s.pairs[k].load_share;
        if (s.pairs.size() > 1) q.load_share += (k == 0 ? 0.05 : k + 1 == s.pairs.size() ? -0.05 : 0.0);
        p.pairs.push_back(q);
      }
      return p;
    };
    c.tooth_compliance = [](const Drive&, ToothMember member, double s, const FeOptions&) {
      ToothComplianceFe t;
      t.member = member;
      t.s = s;
      t.compliance = (member == ToothMember::kPinion ? 2e-9 : 1e-9) * (1 + 10 * s);
      t.seconds = member == ToothMember::kPinion ? 0.5 : 0.25;
      return t;
    };
    return c;
  }
};

TEST(FeComparison, PositionsStartWhereAPairEntersAndSitAtCellMidpoints) {
  const MeshStiffnessModel model(fe_reference_drive(gantry()));
  double x0 = 0;
  const std::vector<double> x = fe_positions(model, 4, &x0);
  const double p = model.geometry().rack.pitch;
  ASSERT_EQ(x.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x[static_cast<std::size_t>(i)], x0 + (i + 0.5) * p / 4, 1e-12);
  // A pair enters at X0: fewer pairs just before than just after.
  EXPECT_LT(model.at(x0, -1).pairs.size(), model.at(x0, +1).pairs.size());
  EXPECT_LT(std::abs(x0 - 0.5 * model.drive().rack.span), p);
  EXPECT_THROW(fe_positions(model, 0), std::invalid_argument);
  EXPECT_THROW(fe_positions(model, kMaxFePositions + 1), std::invalid_argument);
}

TEST(FeComparison, ReferenceDriveHasARigidRackBodyAndNoSpallsOrRelief) {
  Drive d = gantry();
  d.pinion.tip_relief.amount = 1e-5;
  d.pinion.tip_relief.length = 1e-3;
  d.rack.root_relief.amount = 1e-5;
  d.rack.root_relief.length = 1e-3;
  d.spalls.push_back(Spall{});
  const Drive r = fe_reference_drive(d);
  EXPECT_EQ(r.effects.rack_span, RackSpanModel::kRigid);
  EXPECT_FALSE(r.effects.spalling);
  EXPECT_TRUE(r.spalls.empty());
  EXPECT_FALSE(r.pinion.tip_relief.active());
  EXPECT_FALSE(r.rack.root_relief.active());
  EXPECT_EQ(r.effects.hertz, d.effects.hertz);
  EXPECT_EQ(r.effects.fillet_foundation, d.effects.fillet_foundation);
}

TEST(FeComparison, ErrorsAreAnalyticMinusFeOverFeAndMatchAnIndependentAnalyticModel) {
  const Drive d = gantry();
  ASSERT_NE(d.effects.rack_span, RackSpanModel::kRigid);  // the comparison must change it
  Fake fake;
  FeComparisonOptions opt;
  opt.positions = 5;
  opt.threads = 1;
  opt.calls = fake.calls();
  const FeComparison c = compare_with_fe(d, opt);
  ASSERT_EQ(c.rows.size(), 5u);
  ASSERT_FALSE(fake.seen.empty());
  for (const Drive& seen : fake.seen) EXPECT_EQ(seen.effects.rack_span, RackSpanModel::kRigid);

  // The analytic numbers, computed here on our own.
  Drive rigid = d;
  rigid.effects.rack_span = RackSpanModel::kRigid;
  const MeshStiffnessModel model(rigid);
  double max_pinion = 0, max_rack = 0;
  for (const ComparedPosition& r : c.rows) {
    const MeshState s = model.at(r.travel);
    EXPECT_DOUBLE_EQ(r.k_analytic, s.stiffness);
    EXPECT_DOUBLE_EQ(r.k_fe, 0.8 * s.stiffness);
    EXPECT_NEAR(r.k_error, 0.25, 1e-12);  // (1 - 0.8) / 0.8
    ASSERT_EQ(r.pairs.size(), s.pairs.size());
    EXPECT_TRUE(r.extended_pairs.empty());
    EXPECT_DOUBLE_EQ(r.fe_mesh_seconds, 2.0);
    EXPECT_DOUBLE_EQ(r.fe_tooth_seconds, 0.75 * static_cast<double>(s.pairs.size()));
    for (std::size_t k = 0; k < s.pairs.size(); ++k) {
      const ComparedPair& p = r.pairs[k];
      const PairState& a = s.pairs[k];
      EXPECT_EQ(p.rack_tooth, a.rack_tooth);
      EXPECT_TRUE(p.carried_in_fe);
      if (k > 0) {
        EXPECT_GT(r.pairs[k - 1].s, p.s);  // s descending
      }
      EXPECT_DOUBLE_EQ(p.pinion_analytic, a.pinion.total() + a.fillet);
      EXPECT_DOUBLE_EQ(p.rack_analytic, a.rack.total() + a.rack_foundation);
      const double pf = 2e-9 * (1 + 10 * a.s), rf = 1e-9 * (1 + 10 * a.s);
      EXPECT_DOUBLE_EQ(p.pinion_fe, pf);
      EXPECT_NEAR(p.pinion_error, (p.pinion_analytic - pf) / pf, 1e-12);
      EXPECT_NEAR(p.rack_error, (p.rack_analytic - rf) / rf, 1e-12);
      max_pinion = std::max(max_pinion, std::abs(p.pinion_error));
      max_rack = std::max(max_rack, std::abs(p.rack_error));
      const double shift = s.pairs.size() > 1 ? (k == 0 ? 0.05 : k + 1 == s.pairs.size() ? -0.05 : 0.0) : 0.0;
      EXPECT_NEAR(p.share_error, -shift, 1e-12);  // analytic - FE
    }
  }
  EXPECT_NEAR(c.summary.max_k_error, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(c.summary.max_pinion_error, max_pinion);
  EXPECT_DOUBLE_EQ(c.summary.max_rack_error, max_rack);
  EXPECT_NEAR(c.summary.max_share_error, 0.05, 1e-12);  // the gantry has double-contact positions
  EXPECT_DOUBLE_EQ(c.summary.fe_mesh_seconds_per_position, 2.0);
  EXPECT_GT(c.summary.analytic_seconds_per_position, 0);
  EXPECT_NEAR(c.summary.time_ratio, c.summary.fe_seconds_per_position / c.summary.analytic_seconds_per_position,
              1e-9 * c.summary.time_ratio);
  // The analytic curve covers the period, sorted, with K > 0.
  ASSERT_GT(c.analytic_curve.size(), 200u);
  EXPECT_DOUBLE_EQ(c.analytic_curve.front().first, c.period_start);
  EXPECT_NEAR(c.analytic_curve.back().first, c.period_start + c.pitch, 1e-12);
  for (std::size_t i = 1; i < c.analytic_curve.size(); ++i) {
    EXPECT_LE(c.analytic_curve[i - 1].first, c.analytic_curve[i].first);
    EXPECT_GT(c.analytic_curve[i].second, 0);
  }
}

// The analytic compliances the comparison takes from the mesh model equal
// the single-tooth analytic of the FE's own definition (another path through
// the tooth models: fe/tooth_compliance_fe.hpp).
TEST(FeComparison, AnalyticCompliancesAgreeWithTheSingleToothDefinition) {
  Fake f;
  FeComparisonOptions opt;
  opt.positions = 4;
  opt.calls = f.calls();
  for (const char* problem : {"gantry_axis", "rack_railway"}) {
    const Drive d = test_support::load_shipped_problem(std::string(problem) + ".yaml");
    const FeComparison c = compare_with_fe(d, opt);
    const Drive ref = fe_reference_drive(d);
    for (const ComparedPosition& r : c.rows) {
      for (const ComparedPair& p : r.pairs) {
        const double pin = analytic_tooth_compliance(ref, ToothMember::kPinion, p.s);
        const double rack = analytic_tooth_compliance(ref, ToothMember::kRack, p.s);
        EXPECT_NEAR(p.pinion_analytic, pin, 1e-3 * pin) << problem << " s = " << p.s;
        EXPECT_NEAR(p.rack_analytic, rack, 1e-3 * rack) << problem << " s = " << p.s;
      }
    }
  }
}

TEST(FeComparison, ResultsDoNotDependOnTheThreadCount) {
  const Drive d = gantry();
  Fake a, b;
  b.sleep = true;
  FeComparisonOptions o1, o4;
  o1.positions = o4.positions = 7;
  o1.threads = 1;
  o4.threads = 4;
  o1.calls = a.calls();
  o4.calls = b.calls();
  std::vector<std::size_t> done;
  std::size_t total = 0;
  o4.progress = [&](std::size_t k, std::size_t n) {
    done.push_back(k);
    total = n;
  };
  const FeComparison c1 = compare_with_fe(d, o1), c4 = compare_with_fe(d, o4);
  // Progress: every solve once, counted up to the total (1 mesh + 2 per pair per position).
  std::size_t solves = 0;
  for (const ComparedPosition& r : c4.rows) solves += 1 + 2 * r.pairs.size();
  EXPECT_EQ(total, solves);
  ASSERT_EQ(done.size(), solves);
  for (std::size_t i = 0; i < done.size(); ++i) EXPECT_EQ(done[i], i + 1);
  EXPECT_EQ(c4.threads, 4u);
  const std::string csv1 = fe_comparison_csv(c1), csv4 = fe_comparison_csv(c4);
  // Every column but the analytic time (measured) is the same.
  auto without_times = [](const std::string& csv) {
    std::istringstream in(csv);
    std::string line, out;
    std::size_t analytic_s = 0;  // its column, found in the header
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::string cellv;
      std::istringstream ls(line);
      while (std::getline(ls, cellv, ',')) cells.push_back(cellv);
      if (out.empty()) analytic_s = static_cast<std::size_t>(std::find(cells.begin(), cells.end(), "analytic_s") - cells.begin());
      cells.at(analytic_s) = "";
      for (const auto& s : cells) out += s + ",";
      out += "\n";
    }
    return out;
  };
  EXPECT_EQ(without_times(csv1), without_times(csv4));
  for (std::size_t i = 1; i < c4.rows.size(); ++i) EXPECT_LT(c4.rows[i - 1].travel, c4.rows[i].travel);
}

TEST(FeComparison, TheFirstFailingSolveInPositionOrderIsReportedWhateverTheThreads) {
  const Drive d = gantry();
  for (unsigned threads : {1u, 3u}) {
    Fake f;
    FeCalls calls = f.calls();
    const FeCalls good = calls;
    calls.tooth_compliance = [&](const Drive& dr, ToothMember member, double s, const FeOptions& o) -> ToothComplianceFe {
      if (member == ToothMember::kRack) throw CcxError("rack solve at s = " + std::to_string(s) + " failed", "deck.inp", "log");
      return good.tooth_compliance(dr, member, s, o);
    };
    FeComparisonOptions opt;
    opt.positions = 4;
    opt.threads = threads;
    opt.calls = calls;
    // The first rack solve is that of the first pair of the first position.
    const MeshStiffnessModel model(fe_reference_drive(d));
    const std::vector<double> x = fe_positions(model, 4);
    const double s0 = model.at(x[0]).pairs.front().s;
    try {
      (void)compare_with_fe(d, opt);
      ADD_FAILURE() << "no error";
    } catch (const CcxError& e) {
      EXPECT_EQ(std::string(e.what()), "rack solve at s = " + std::to_string(s0) + " failed") << threads;
      EXPECT_EQ(e.deck(), "deck.inp");
    }
  }
}

TEST(FeComparison, NonPositiveFeResultsAndBadOptionsAreRefused) {
  const Drive d = gantry();
  Fake f;
  FeComparisonOptions opt;
  opt.positions = 2;
  opt.calls = f.calls();
  FeCalls bad = f.calls();
  const auto good_mesh = bad.mesh_position;
  bad.mesh_position = [&](const Drive& dr, double x, const FeOptions& o) {
    FePosition p = good_mesh(dr, x, o);
    p.stiffness = 0;
    return p;
  };
  FeComparisonOptions ob = opt;
  ob.calls = bad;
  EXPECT_THROW(compare_with_fe(d, ob), std::runtime_error);
  FeComparisonOptions o2 = opt;
  o2.positions = 0;
  EXPECT_THROW(compare_with_fe(d, o2), std::invalid_argument);
  o2 = opt;
  o2.fe.level = 7;
  EXPECT_THROW(compare_with_fe(d, o2), std::invalid_argument);
  // An impossible design is a DesignError before any FE solve.
  Drive pointed = d;
  pointed.pinion.addendum_coef = 3.0;
  int solves = 0;
  FeComparisonOptions op = opt;
  op.calls.mesh_position = [&](const Drive&, double, const FeOptions&) -> FePosition {
    ++solves;
    return {};
  };
  EXPECT_THROW(compare_with_fe(pointed, op), DesignError);
  EXPECT_EQ(solves, 0);
}

TEST(FeComparison, AMissingCcxIsReportedBeforeAnyWorkWithTheRealSolves) {
  FeComparisonOptions opt;
  opt.fe.ccx.program = "/nonexistent/ccx";
  try {
    (void)compare_with_fe(gantry(), opt);
    ADD_FAILURE() << "no error";
  } catch (const CcxNotFound& e) {
    EXPECT_NE(std::string(e.what()).find("calculix-ccx"), std::string::npos) << e.what();
  }
}

TEST(FeComparison, AStopRequestEndsTheComparisonAsInterrupted) {
  Fake f;
  FeComparisonOptions opt;
  opt.positions = 3;
  opt.calls = f.calls();
  opt.stop = [] { return true; };
  EXPECT_THROW(compare_with_fe(gantry(), opt), Interrupted);
  EXPECT_TRUE(f.seen.empty());
}

TEST(FeComparison, ExtendedContactPairsAreListedApartAndNotCompared) {
  Fake f;
  FeCalls calls = f.calls();
  const auto good_mesh = calls.mesh_position;
  calls.mesh_position = [&](const Drive& dr, double x, const FeOptions& o) {
    FePosition p = good_mesh(dr, x, o);
    FePair extra;
    extra.rack_tooth = 99;
    extra.pinion_tooth = 7;
    extra.theoretical = false;
    extra.load_share = 0.01;
    p.pairs.push_back(extra);
    return p;
  };
  FeComparisonOptions opt;
  opt.positions = 2;
  opt.calls = calls;
  opt.fe.extended_contact = true;
  const FeComparison c = compare_with_fe(gantry(), opt);
  for (const ComparedPosition& r : c.rows) {
    ASSERT_EQ(r.extended_pairs.size(), 1u);
    EXPECT_EQ(r.extended_pairs[0].rack_tooth, 99);
    EXPECT_DOUBLE_EQ(r.extended_share_fe, 0.01);
    for (const ComparedPair& p : r.pairs) EXPECT_NE(p.rack_tooth, 99);
  }
  const std::string json = fe_comparison_json(gantry(), c, {}, {});
  EXPECT_NE(json.find("\"extended_share_fe\":0.01,\"extended_pairs\":[{\"rack_tooth\":99"), std::string::npos) << json;
  EXPECT_NE(json.find("\"pictures\":null"), std::string::npos);
  // fe.csv: the extended pairs counted and their share summed, beside pairs_in_mesh.
  std::istringstream csv(fe_comparison_csv(c));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_NE(header.find(",pairs_in_mesh,extended_pairs_fe,extended_share_fe,"), std::string::npos) << header;
  const auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) out.push_back(cell);
    return out;
  };
  const std::vector<std::string> h = cells(header), v = cells(row);
  const auto col = [&](const char* name) { return v.at(static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin())); };
  EXPECT_EQ(col("extended_pairs_fe"), "1");
  EXPECT_EQ(col("extended_share_fe"), "0.01");
}

// The paper's rack railway keeps the geometric path of contact, which starts
// below the pinion's base-circle tangent point, and its pinion is undercut:
// pairs there (s <= 0 or below the form circle) have no involute to load, so their pinion solve is left out and said so; the mesh
// solve and the rack tooth are still compared.
TEST(FeComparison, PinionContactsOffTheInvoluteAreNotComparedAndSaidSo) {
  const Drive d = test_support::load_shipped_problem("rack_railway_paper.yaml");
  Fake f;
  FeCalls calls = f.calls();
  const auto tooth = calls.tooth_compliance;
  std::mutex m;
  int pinion_calls = 0;
  calls.tooth_compliance = [&](const Drive& dr, ToothMember member, double s, const FeOptions& o) {
    if (member == ToothMember::kPinion) {
      EXPECT_TRUE(pinion_contact_on_involute(build_mesh_geometry(dr), s)) << "a pinion solve off the involute";
      const std::lock_guard<std::mutex> lock(m);
      ++pinion_calls;
    }
    return tooth(dr, member, s, o);
  };
  FeComparisonOptions opt;
  opt.positions = 8;
  opt.calls = calls;
  const FeComparison c = compare_with_fe(d, opt);
  const MeshGeometry g = build_mesh_geometry(fe_reference_drive(d));
  int off = 0, pairs = 0;
  for (const ComparedPosition& r : c.rows) {
    for (const ComparedPair& p : r.pairs) {
      ++pairs;
      // On the involute: beyond the base circle's tangent point and at or above the form circle.
      const bool involute = p.s > 0 && g.pinion_contact_radius(p.s) >= g.pinion.form_radius;
      EXPECT_EQ(p.pinion_compared, involute) << "s = " << p.s;
      EXPECT_GT(p.rack_fe, 0);
      if (p.pinion_compared) {
        EXPECT_GT(p.pinion_fe, 0);
        continue;
      }
      ++off;
      EXPECT_EQ(p.pinion_fe, 0);
      EXPECT_EQ(p.pinion_error, 0);
      EXPECT_GT(p.pinion_analytic, 0);
    }
  }
  ASSERT_GT(off, 0) << "no pair below the base circle: the test no longer sees the case";
  EXPECT_EQ(pinion_calls, pairs - off);
  EXPECT_TRUE(std::any_of(c.notes.begin(), c.notes.end(),
                          [](const std::string& n) { return n.find("off the involute") != std::string::npos; }));
  const std::string json = fe_comparison_json(d, c, FeFiles{}, {});
  EXPECT_EQ(check_json_complete(json), "");
  EXPECT_NE(json.find("\"pinion_fe\":null"), std::string::npos);
  EXPECT_NE(json.find("\"pinion_compared\":false"), std::string::npos);
  EXPECT_NE(fe_comparison_markdown(c).find("off involute"), std::string::npos);
  EXPECT_NE(fe_comparison_csv(c).find(",,"), std::string::npos);
}

TEST(FeComparison, FilesHaveOneRowPerPositionAndCompleteJson) {
  const Drive d = gantry();
  Fake f;
  FeComparisonOptions opt;
  opt.positions = 3;
  opt.calls = f.calls();
  const FeComparison c = compare_with_fe(d, opt);
  const std::string csv = fe_comparison_csv(c);
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("travel_m,k_fe_N_per_m,k_analytic_N_per_m,k_error,", 0), 0u) << header;
  EXPECT_NE(header.find("pair0_c_pinion_fe_m_per_N"), std::string::npos);
  EXPECT_NE(header.find("pair" + std::to_string(c.slots - 1) + "_c_rack_error"), std::string::npos);
  const auto columns = std::count(header.begin(), header.end(), ',');
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << line;
  }
  EXPECT_EQ(rows, 3);
  FeFiles files;
  files.csv = "out/fe.csv";
  const std::string json = fe_comparison_json(d, c, files, {"a warning"});
  EXPECT_EQ(check_json_complete(json), "");
  for (const char* key : {"\"k_fe\":", "\"k_analytic\":", "\"k_error\":", "\"max_k_error\":", "\"time_ratio\":",
                          "\"period_start\":", "\"conventions\":", "\"level\":0", "\"plot\":null", "\"a warning\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
  const std::string gp = fe_comparison_gnuplot(c, "gantry", "fe_stiffness.png.tmp");
  EXPECT_NE(gp.find("set output 'fe_stiffness.png.tmp'"), std::string::npos);
  EXPECT_NE(gp.find("$fe using"), std::string::npos);
  const std::string md = fe_comparison_markdown(c);
  EXPECT_NE(md.find("| X [m] | K FE [MN/m]"), std::string::npos);
  EXPECT_NE(md.find("rack body rigid"), std::string::npos);
  EXPECT_NE(fe_comparison_summary(c).find("FE / analytic = "), std::string::npos);
}

}  // namespace
}  // namespace rackopt::fe
