// The analytic stiffness model against the committed FE reference data
// (tests/data/fe, made by bench/fe_calibration; docs/models/fe_calibration.md).
// No FE runs here: the data carry the FE numbers, the model is evaluated on
// the same designs and contacts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

// One data row: the columns by name, the design as problem + overrides.
struct FeRow {
  std::string problem;
  std::vector<std::string> overrides;
  std::map<std::string, double> num;
  std::map<std::string, std::string> text;  // the cells that are not numbers
  double operator[](const std::string& k) const { return num.at(k); }
};

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// The rows of tests/data/fe/<name> that carry values (skipped designs left out).
std::vector<FeRow> fe_rows(const std::string& name) {
  std::ifstream in(std::string(RACKOPT_SOURCE_DIR) + "/tests/data/fe/" + name);
  EXPECT_TRUE(in.good()) << name;
  std::vector<std::string> header;
  std::vector<FeRow> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = split_csv_line(line);
    if (f[0] == "key") {
      header = f;
      continue;
    }
    if (f.size() != header.size()) continue;  // a skipped design: key, "skipped", reason
    FeRow r;
    r.problem = f[1];
    std::stringstream ss(f[2]);
    for (std::string t; std::getline(ss, t, ';');) {
      if (!t.empty()) r.overrides.push_back(t);
    }
    for (std::size_t i = 3; i < f.size(); ++i) {
      try {
        std::size_t used = 0;
        const double v = std::stod(f[i], &used);
        if (used == f[i].size()) {
          r.num[header[i]] = v;
          continue;
        }
      } catch (const std::exception&) {
      }
      r.text[header[i]] = f[i];
    }
    out.push_back(std::move(r));
  }
  return out;
}

Drive row_drive(const FeRow& r) {
  Drive d = test::problem(r.problem + ".yaml", r.overrides);
  d.effects.rack_span = RackSpanModel::kRigid;  // the FE rack segment's base is held
  return d;
}

// Largest |model / FE - 1| over the rows, with where it happened.
struct WorstError {
  double value = 0;
  std::string where;
  void add(double model, double fe, const FeRow& r) {
    const double e = std::abs(model / fe - 1);
    if (e > value) {
      value = e;
      where = r.problem;
      for (const std::string& o : r.overrides) where += " " + o;
    }
  }
};

TEST(FeAgreement, RackToothOnItsBodyWithinThreePercentOnEverySample) {
  const std::vector<FeRow> rows = fe_rows("rack_tooth.csv");
  ASSERT_GE(rows.size(), 100u);
  WorstError with, without;
  for (const FeRow& r : rows) {
    const Drive d = row_drive(r);
    const MeshGeometry g = build_mesh_geometry(d);
    const PairTeeth t = PairCompliance(d, g).teeth(r["s_star"] * d.pinion.module);
    const double Eb = r["E_Pa"] * r["face_width_m"];
    with.add((t.rack.total() + t.rack_foundation) * Eb, r["fe_Eb"], r);
    without.add(t.rack.total() * Eb, r["fe_Eb"], r);
  }
  EXPECT_LT(with.value, 0.03) << with.where;
  // The clamped tooth alone is far off: the foundation is what closes the gap.
  EXPECT_GT(without.value, 0.3) << without.where;
}

TEST(FeAgreement, PinionToothWithinThreePercentOnEverySample) {
  const std::vector<FeRow> rows = fe_rows("pinion_tooth.csv");
  ASSERT_GE(rows.size(), 80u);
  WorstError with, without;
  for (const FeRow& r : rows) {
    Drive d = row_drive(r);
    const double s = r["s_star"] * d.pinion.module;
    const double Eb = r["E_Pa"] * r["face_width_m"];
    const MeshGeometry g = build_mesh_geometry(d);
    const PairTeeth t = PairCompliance(d, g).teeth(s, nullptr, nullptr, d.pinion.face_width);
    with.add((t.pinion.total() + t.fillet) * Eb, r["fe_Eb"], r);
    d.effects.fillet_calibration = false;
    const PairTeeth u = PairCompliance(d, g).teeth(s, nullptr, nullptr, d.pinion.face_width);
    without.add((u.pinion.total() + u.fillet) * Eb, r["fe_Eb"], r);
  }
  EXPECT_LT(with.value, 0.03) << with.where;
  EXPECT_GT(without.value, 0.15) << without.where;
}

TEST(FeAgreement, LocalContactTermWithinTwoPercentOfWhatFeLeavesBeyondTheTeeth) {
  // FE contact term: the pair's FE compliance in the single-pair zone minus
  // both FE single-tooth compliances (read on the tooth centre lines).
  const std::vector<FeRow> rows = fe_rows("contact.csv");
  ASSERT_GE(rows.size(), 6u);
  WorstError wb, linear;
  for (const FeRow& r : rows) {
    const Drive d = row_drive(r);
    const MeshGeometry g = build_mesh_geometry(d);
    const double force = d.load.force * r["load_fraction"];
    wb.add(PairCompliance(d, g).contact(r["s_m"], force), r["c_contact_fe"], r);
    Drive lin = d;
    lin.effects.hertz = HertzModel::kLinear;
    linear.add(PairCompliance(lin, g).contact(r["s_m"], force), r["c_contact_fe"], r);
  }
  EXPECT_LT(wb.value, 0.02) << wb.where;
  // The constant Yang-Lin term misses most of it.
  EXPECT_GT(linear.value, 0.6) << linear.where;
}

TEST(FeAgreement, SinglePairMeshStiffnessWithinThreePercentOfFe) {
  const std::vector<FeRow> rows = fe_rows("contact.csv");
  ASSERT_GE(rows.size(), 6u);
  WorstError k;
  for (const FeRow& r : rows) {
    Drive d = row_drive(r);
    d.load.force *= r["load_fraction"];  // the force the FE's last step reached
    const MeshState st = MeshStiffnessModel(d).at(r["travel_m"]);
    ASSERT_EQ(st.pairs.size(), 1u);
    k.add(st.stiffness, r["K_fe"], r);
  }
  EXPECT_LT(k.value, 0.03) << k.where;
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// Over one whole mesh period of the shipped problems (tests/data/fe/period.csv):
// K within 3 % in the single- and the double-pair zone, the load shares
// within 0.03. Without the pairs' coupling the double-pair zone is 9.5-12 %
// too stiff (a load on one tooth moves its loaded neighbour).
TEST(FeAgreement, WholeMeshPeriodOfTheShippedProblems) {
  const std::vector<FeRow> rows = fe_rows("period.csv");
  ASSERT_GE(rows.size(), 20u);
  WorstError single, multi;
  double share_error = 0;
  for (const FeRow& r : rows) {
    Drive d = row_drive(r);
    d.load.force *= r["load_fraction"];
    const MeshState st = MeshStiffnessModel(d).at(r["travel_m"]);
    ASSERT_EQ(static_cast<double>(st.pairs.size()), r["pairs"]);
    (st.pairs.size() == 1 ? single : multi).add(st.stiffness, r["K_fe"], r);
    // One pair: the cell is a plain number; more: "a;b".
    std::stringstream shares(r.text.count("shares_fe") ? r.text.at("shares_fe") : std::to_string(r["shares_fe"]));
    std::size_t k = 0;
    for (std::string v; std::getline(shares, v, ';') && k < st.pairs.size(); ++k) {
      share_error = std::max(share_error, std::abs(st.pairs[k].load_share - std::stod(v)));
    }
  }
  std::printf("[ info ] shipped periods: largest K error %.4f single-pair, %.4f multi-pair\n", single.value,
              multi.value);
  EXPECT_LT(single.value, 0.03) << single.where;
  EXPECT_LT(multi.value, 0.03) << multi.where;
  EXPECT_LT(share_error, 0.03);
}

// The coupling's share is fitted on these same positions; fitted on three
// of the problems it predicts the fourth within 1 % (fe_calibration --fit
// coupling). Here: switched off, the double-pair zone is far off again.
TEST(FeAgreement, PairCouplingIsWhatClosesTheDoublePairZone) {
  const std::vector<FeRow> rows = fe_rows("period.csv");
  WorstError without;
  for (const FeRow& r : rows) {
    if (r["pairs"] != 2) continue;
    Drive d = row_drive(r);
    d.load.force *= r["load_fraction"];
    d.effects.pair_coupling = false;
    without.add(MeshStiffnessModel(d).at(r["travel_m"]).stiffness, r["K_fe"], r);
  }
  EXPECT_GT(without.value, 0.09) << without.where;
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// A spread of designs over the range the model claims (tests/data/fe/
// spread.csv: z 12..40, pressure angle 14..25 deg, profile shift -0.3..+0.5,
// modules 4..63 mm, with and without undercut), six positions of a mesh
// period each: K within 5 % everywhere (measured: -1.9 ... +4.4 %, the
// largest in the triple-pair zone of the 14 deg, 40-tooth pinion), the load
// shares within 0.05.
TEST(FeAgreement, DesignSpreadOverWholeMeshPeriods) {
  const std::vector<FeRow> rows = fe_rows("spread.csv");
  EXPECT_GE(rows.size(), 54u);
  WorstError k;
  double share_error = 0;
  std::map<std::string, int> designs;
  for (const FeRow& r : rows) {
    Drive d = row_drive(r);
    d.load.force *= r["load_fraction"];
    const MeshState st = MeshStiffnessModel(d).at(r["travel_m"]);
    ASSERT_EQ(static_cast<double>(st.pairs.size()), r["pairs"]);
    k.add(st.stiffness, r["K_fe"], r);
    std::stringstream shares(r.text.count("shares_fe") ? r.text.at("shares_fe") : std::to_string(r["shares_fe"]));
    std::size_t j = 0;
    for (std::string v; std::getline(shares, v, ';') && j < st.pairs.size(); ++j) {
      share_error = std::max(share_error, std::abs(st.pairs[j].load_share - std::stod(v)));
    }
    std::string key = r.problem;
    for (const std::string& o : r.overrides) key += " " + o;
    ++designs[key];
    std::printf("[ info ] %-80s X %.4f pairs %.0f K error %+.4f\n", key.c_str(), r["travel_m"], r["pairs"],
                st.stiffness / r["K_fe"] - 1);
  }
  EXPECT_EQ(designs.size(), 9u);
  EXPECT_LT(k.value, 0.05) << k.where;
  EXPECT_LT(share_error, 0.05);
}

}  // namespace
}  // namespace rackopt

namespace rackopt {
namespace {

// The rack on its hinged supports (tests/data/fe/supports.csv): 24 FE mesh
// positions of the toothed rack over its whole span, at mid-span and near
// the left hinge, for body depths of 1.3-5 tooth heights, spans of 16-32
// pitches, pressure angles 14-25 deg and the shipped heavy racks, against
// the coupled analytic model on the FE's rectangular body
// (fe/rack_span_fe.hpp's rack_on_supports_drive does the same). With
// effects.supported_rack K is within 5.4 % of FE on the slender spans and
// 10.0 % on the deep short span of the ship lift; without it the beam under
// the teeth is 7-34 % too soft.
Drive supported_row_drive(const FeRow& r) {
  Drive d = test::problem(r.problem + ".yaml", r.overrides);
  d.effects.spalling = false;
  d.spalls.clear();
  d.pinion.tip_relief = {};
  d.pinion.root_relief = {};
  d.rack.tip_relief = {};
  d.rack.root_relief = {};
  const double w = r["face_width_m"], h = r["body_depth_m"];
  d.effects.rack_span = RackSpanModel::kCoupled;
  d.rack.section.area = w * h;
  d.rack.section.second_moment = w * h * h * h / 12;
  d.rack.section.shear_area = w * h / 1.2;
  d.rack.section.neutral_axis_depth = h / 2;
  d.load.force *= r["load_fraction"];
  return d;
}

TEST(FeAgreement, RackOnItsSupportsAgainstFe) {
  const std::vector<FeRow> rows = fe_rows("supports.csv");
  EXPECT_GE(rows.size(), 24u);
  WorstError with, slender, without;
  for (const FeRow& r : rows) {
    Drive d = supported_row_drive(r);
    ASSERT_TRUE(d.effects.supported_rack);
    const MeshState st = MeshStiffnessModel(d).at(r["travel_m"]);
    EXPECT_NEAR(st.pairs.front().a, r["a_first_m"], 1e-6 * r["span_m"]);  // the same position (7 digits)
    with.add(st.stiffness, r["K_fe"], r);
    if (r["span_m"] >= 8 * r["body_depth_m"]) slender.add(st.stiffness, r["K_fe"], r);
    std::string design;
    for (const std::string& o : r.overrides) design += o + " ";
    std::printf("[ info ] %-14s %-66s X %.4f K error %+.4f\n", r.problem.c_str(), design.c_str(), r["travel_m"],
                st.stiffness / r["K_fe"] - 1);
    d.effects.supported_rack = false;
    without.add(MeshStiffnessModel(d).at(r["travel_m"]).stiffness, r["K_fe"], r);
  }
  // The 5 % goal holds on the slender spans (span / body depth >= 8); the
  // ship lift's 1 m span under a 250 mm body (span / depth 4, five teeth on
  // the span) is a deep beam the law does not reach (docs/models/rack_span.md).
  EXPECT_LT(slender.value, 0.06) << slender.where;
  EXPECT_LT(with.value, 0.11) << with.where;
  EXPECT_GT(without.value, 0.1) << without.where;
}

}  // namespace
}  // namespace rackopt
