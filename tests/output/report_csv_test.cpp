// The CSV files of `rackopt stiffness` and `rackopt wear`
// (output/stiffness_report.hpp, output/wear_report.hpp) from results built
// here, checked against docs/output.md: the columns and their order, SI
// units, one row per sample, the derived columns computed by hand, empty
// cells where the documentation says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/output/wear_report.hpp"

namespace rackopt {
namespace {

using Table = std::vector<std::vector<std::string>>;

// Plain comma-separated cells (these files quote nothing).
Table cells(const std::string& csv) {
  Table t;
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::size_t at = 0;
    while (true) {
      const std::size_t comma = line.find(',', at);
      row.push_back(line.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
    t.push_back(row);
  }
  return t;
}

double num(const std::string& cell) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  EXPECT_TRUE(!cell.empty() && *end == '\0') << "not a number: '" << cell << "'";
  return v;
}

// The per-slot suffixes in the order of docs/output.md's table.
const std::vector<std::string> kPairSuffixes = {
    "in_mesh",        "rack_tooth",     "pinion_tooth",  "s_m",           "x_m",
    "load_share",     "c_pinion_bending", "c_pinion_shear", "c_pinion_axial", "c_fillet",
    "c_hertz",        "c_rack_bending", "c_rack_shear",  "c_rack_axial",  "c_rack_foundation",
    "c_body",         "relief_m"};

PairState pair(int slot, double scale) {
  PairState p;
  p.slot = slot;
  p.rack_tooth = 7 + slot;
  p.pinion_tooth = 3 + slot;
  p.s = 0.01 * scale;
  p.x = 0.5 + 0.001 * scale;
  p.load_share = 0.25 * scale;
  p.pinion = {1e-10 * scale, 2e-10 * scale, 3e-11 * scale};
  p.fillet = 4e-10 * scale;
  p.hertz = 5e-10 * scale;
  p.rack = {6e-10 * scale, 7e-10 * scale, 8e-11 * scale};
  p.rack_foundation = 9e-11 * scale;
  p.body = 1.1e-9 * scale;
  p.relief = 2e-6 * scale;
  return p;
}

// Three samples with two pair slots: one pair in slot 1 only (listed first:
// pairs are ordered by s, not by slot), both slots, and no pair.
StiffnessCurve synthetic_curve() {
  StiffnessCurve c;
  c.max_pairs = 2;
  MeshState a;
  a.travel = 0.0;
  a.stiffness = 4.0e8;
  a.local_stiffness = 5.0e8;
  a.approach = 1.25e-4;
  a.pairs = {pair(1, 1.0)};
  MeshState b;
  b.travel = 0.0123456789012;
  b.stiffness = 7.5e8;
  b.local_stiffness = 9.0e8;
  b.approach = 6.7e-5;
  b.pairs = {pair(1, 2.0), pair(0, 3.0)};
  MeshState none;
  none.travel = 0.025;
  c.samples = {a, b, none};
  return c;
}

TEST(StiffnessCsv, HeaderHasTheDocumentedColumnsPerSlot) {
  const Table t = cells(stiffness_csv(synthetic_curve()));
  ASSERT_FALSE(t.empty());
  std::vector<std::string> want = {"travel_m", "stiffness_N_per_m", "rigid_body_stiffness_N_per_m", "pairs_in_mesh",
                                   "body_equivalent_compliance_m_per_N", "transmission_error_m"};
  for (int q = 0; q < 2; ++q) {
    for (const std::string& s : kPairSuffixes) want.push_back("pair" + std::to_string(q) + "_" + s);
  }
  EXPECT_EQ(t[0], want);
  ASSERT_EQ(t.size(), 4u);  // one row per sample
  for (const auto& row : t) EXPECT_EQ(row.size(), want.size());
}

TEST(StiffnessCsv, RowsHoldTheSampleInSiWithTheDerivedColumns) {
  const StiffnessCurve c = synthetic_curve();
  const Table t = cells(stiffness_csv(c));
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t i = 0; i < c.samples.size(); ++i) {
    SCOPED_TRACE(i);
    const MeshState& s = c.samples[i];
    const auto& row = t[i + 1];
    EXPECT_NEAR(num(row[0]), s.travel, 1e-9 * std::abs(s.travel));
    EXPECT_NEAR(num(row[1]), s.stiffness, 1e-9 * s.stiffness);
    EXPECT_NEAR(num(row[2]), s.local_stiffness, 1e-9 * s.local_stiffness);
    EXPECT_EQ(row[3], std::to_string(s.pairs.size()));
    // 1/K - 1/K_rigid: what the rack body adds in series (0 without pairs).
    const double body = s.stiffness > 0 ? 1 / s.stiffness - 1 / s.local_stiffness : 0.0;
    EXPECT_NEAR(num(row[4]), body, 1e-9 * std::abs(body));
    EXPECT_NEAR(num(row[5]), s.approach, 1e-9 * s.approach);
  }
  // Sample 0: slot 0 empty (in_mesh 0, the rest empty), slot 1 holds the pair.
  const auto& r0 = t[1];
  const std::size_t slot0 = 6, slot1 = 6 + kPairSuffixes.size();
  EXPECT_EQ(r0[slot0], "0");
  for (std::size_t k = 1; k < kPairSuffixes.size(); ++k) EXPECT_EQ(r0[slot0 + k], "") << kPairSuffixes[k];
  EXPECT_EQ(r0[slot1], "1");
  // Sample 1: each pair in its own slot, whatever its place in the list.
  for (const auto& [slot, scale] : {std::pair<std::size_t, double>{slot0, 3.0}, {slot1, 2.0}}) {
    const PairState p = pair(slot == slot0 ? 0 : 1, scale);
    const auto& r = t[2];
    const std::vector<double> want = {p.s,           p.x,           p.load_share,  p.pinion.bending, p.pinion.shear,
                                      p.pinion.axial, p.fillet,     p.hertz,       p.rack.bending,   p.rack.shear,
                                      p.rack.axial,  p.rack_foundation, p.body,    p.relief};
    EXPECT_EQ(r[slot], "1");
    EXPECT_EQ(r[slot + 1], std::to_string(p.rack_tooth));
    EXPECT_EQ(r[slot + 2], std::to_string(p.pinion_tooth));
    for (std::size_t k = 0; k < want.size(); ++k) {
      EXPECT_NEAR(num(r[slot + 3 + k]), want[k], 1e-9 * std::abs(want[k])) << kPairSuffixes[k + 3];
    }
  }
  // Sample 2: no pair in mesh.
  EXPECT_EQ(t[3][3], "0");
  EXPECT_EQ(t[3][slot0], "0");
  EXPECT_EQ(t[3][slot1], "0");
}

TEST(WearProfileCsv, OneRowPerProfilePointPinionThenRackPerSnapshot) {
  WearLifeResult n;
  for (int k = 1; k <= 2; ++k) {
    WearSnapshot s;
    s.fraction = 0.5 * k;
    s.years = 10.0 * k;
    s.contact_ratio = 1.6 - 0.1 * k;
    s.pinion = {{0.01, 0.02, 0.03}, {0.0, 1e-3, 2e-3}, {0.05, 0.051, 0.052}, {1e-6 * k, 2e-6 * k, 3e-6 * k}};
    s.rack = {{0.015, 0.025}, {0.0, 5e-4}, {0.004, 0.005}, {4e-6 * k, 5e-6 * k}};
    n.snapshots.push_back(s);
  }
  const Table t = cells(wear_profile_csv(n));
  EXPECT_EQ(t[0], (std::vector<std::string>{"member", "fraction_of_life", "years", "contact_ratio", "s_m",
                                            "position_m", "radius_or_height_m", "depth_m"}));
  ASSERT_EQ(t.size(), 1u + 2 * (3 + 2));
  std::size_t row = 1;
  for (const WearSnapshot& s : n.snapshots) {
    for (const auto& [member, p] : {std::pair<std::string, const WearProfile*>{"pinion", &s.pinion}, {"rack", &s.rack}}) {
      for (std::size_t i = 0; i < p->s.size(); ++i, ++row) {
        const auto& r = t[row];
        ASSERT_EQ(r.size(), 8u);
        EXPECT_EQ(r[0], member);
        EXPECT_DOUBLE_EQ(num(r[1]), s.fraction);
        EXPECT_NEAR(num(r[2]), s.years, 1e-9 * s.years);
        EXPECT_NEAR(num(r[3]), s.contact_ratio, 1e-9);
        EXPECT_NEAR(num(r[4]), p->s[i], 1e-9 * p->s[i]);
        EXPECT_NEAR(num(r[5]), p->position[i], 1e-12);
        EXPECT_NEAR(num(r[6]), p->radius_or_height[i], 1e-9 * p->radius_or_height[i]);
        EXPECT_NEAR(num(r[7]), p->depth[i], 1e-9 * p->depth[i]);
      }
    }
  }
}

statistics::SampleResult life(double seconds) {
  statistics::SampleResult s;
  s.status = statistics::SampleResult::Status::kOk;
  s.value = seconds;
  return s;
}

// Two inputs, three samples: a life, a failure at once (life 0, status ok),
// and a sample outside an input's domain with a non-finite value.
WearReliabilityResult three_samples() {
  WearReliabilityResult r;
  r.input_keys = {"contact_ratio", "wear.coefficient"};
  r.input_values = {{1.5, 3e-6}, {0.9, 2e-6}, {std::numeric_limits<double>::infinity(), -1e-6}};
  statistics::SampleResult bad;
  bad.status = statistics::SampleResult::Status::kDesignError;
  bad.message = "wear.coefficient = -1e-06, outside (0, inf),\nskipped";
  r.lives = {life(40 * kSecondsPerYear), life(0), bad};
  r.criteria = {"max_depth", "initial_contact_ratio", ""};
  return r;
}

TEST(LifeSamplesCsv, InputsLivesInYearsAndFailedSamplesWithoutInfinity) {
  const Table t = cells(life_samples_csv(three_samples()));
  EXPECT_EQ(t[0], (std::vector<std::string>{"sample", "contact_ratio", "wear.coefficient", "life_years", "status",
                                            "criterion", "message"}));
  ASSERT_EQ(t.size(), 4u);
  for (const auto& row : t) EXPECT_EQ(row.size(), 7u);  // a comma or newline in a message stays inside its cell
  EXPECT_EQ(t[1][0], "0");
  EXPECT_DOUBLE_EQ(num(t[1][1]), 1.5);
  EXPECT_DOUBLE_EQ(num(t[1][2]), 3e-6);
  EXPECT_NEAR(num(t[1][3]), 40.0, 1e-9);
  EXPECT_EQ(t[1][4], "ok");
  EXPECT_EQ(t[1][5], "max_depth");
  EXPECT_EQ(t[1][6], "");
  // Failure at once: life 0, status ok and its criterion.
  EXPECT_EQ(num(t[2][3]), 0.0);
  EXPECT_EQ(t[2][4], "ok");
  EXPECT_EQ(t[2][5], "initial_contact_ratio");
  // Outside the domain: empty life, design_error, the reason; the
  // non-finite value empty.
  EXPECT_EQ(t[3][1], "");
  EXPECT_DOUBLE_EQ(num(t[3][2]), -1e-6);
  EXPECT_EQ(t[3][3], "");
  EXPECT_EQ(t[3][4], "design_error");
  EXPECT_NE(t[3][6].find("outside (0"), std::string::npos) << t[3][6];
  const std::string text = life_samples_csv(three_samples());
  EXPECT_EQ(text.find("inf,"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

TEST(LifeHistogramCsv, BinsSpanTheLivesAndCountEveryValidLife) {
  WearReliabilityResult r = three_samples();
  for (double years : {10.0, 12.0, 12.5, 20.0}) r.lives.push_back(life(years * kSecondsPerYear));
  const int bins = 4;
  const Table t = cells(life_histogram_csv(r, bins));
  EXPECT_EQ(t[0], (std::vector<std::string>{"bin_left_years", "bin_right_years", "count", "fit_count"}));
  ASSERT_EQ(t.size(), 1u + bins);
  // Valid lives (status ok): 40, 0, 10, 12, 12.5, 20 years; bins of 10 years from 0.
  const std::vector<long> want = {1, 3, 1, 1};
  long total = 0;
  for (int b = 0; b < bins; ++b) {
    const auto& row = t[1 + b];
    EXPECT_NEAR(num(row[0]), 10.0 * b, 1e-9);
    EXPECT_NEAR(num(row[1]), 10.0 * (b + 1), 1e-9);
    EXPECT_EQ(std::stol(row[2]), want[b]) << "bin " << b;
    EXPECT_EQ(row[3], "");  // no fit was chosen
    total += std::stol(row[2]);
  }
  EXPECT_EQ(total, 6);
}

// stiffness.csv is written as it is formatted: pieces of about 64 KiB, never
// the whole table of a long curve as one string.
TEST(StiffnessCsv, ALongCurveIsWrittenInBoundedPiecesThatMakeEveryRow) {
  StiffnessCurve c = synthetic_curve();
  const std::vector<MeshState> base = c.samples;
  for (int k = 1; k <= 3000; ++k) {
    for (MeshState s : base) {
      s.travel += k;
      c.samples.push_back(s);
    }
  }
  std::string joined;
  std::size_t pieces = 0, largest = 0;
  write_stiffness_csv(c, [&](std::string_view piece) {
    joined += piece;
    ++pieces;
    largest = std::max(largest, piece.size());
  });
  EXPECT_GT(pieces, 4u);
  EXPECT_LT(largest, std::size_t{72 * 1024});
  const Table t = cells(joined);
  ASSERT_EQ(t.size(), c.samples.size() + 1);
  for (const auto& row : t) EXPECT_EQ(row.size(), t[0].size());
  EXPECT_NEAR(num(t.back()[0]), c.samples.back().travel, 1e-8 * c.samples.back().travel);
}

}  // namespace
}  // namespace rackopt
