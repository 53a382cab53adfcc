// Grouping warnings by kind (study/warning_groups.hpp): numbers become "…",
// digits inside names stay, and each kind counts the designs that gave it.
#include "rackopt/study/warning_groups.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rackopt::study {
namespace {

TEST(WarningKind, NumbersBecomeAnEllipsisNamesKeepTheirDigits) {
  EXPECT_EQ(warning_kind("pinion undercut: z = 17 < z_min = 18.3"), "pinion undercut: z = … < z_min = …");
  EXPECT_EQ(warning_kind("path of contact starts at s = -3.25 mm, 1e-3 r_b"), "path of contact starts at s = … mm, … r_b");
  EXPECT_EQ(warning_kind("12 of 400 samples failed; wear_life_at_R(0.9) at R90"),
            "… of … samples failed; wear_life_at_R(…) at R90");
  EXPECT_EQ(warning_kind("outside the calibrated range (0.55..3, 0.03..0.15)"),
            "outside the calibrated range (…..…, …..…)");
  EXPECT_EQ(warning_kind("see v1.2 and file.3"), "see v1.2 and file.3");
  EXPECT_EQ(warning_kind("no numbers here"), "no numbers here");
  EXPECT_EQ(warning_kind("the 3rd tooth, version v2"), "the 3rd tooth, version v2");
}

TEST(WarningTally, NearDuplicatesAreOneGroupCountingDesigns) {
  WarningTally t;
  t.add({"pinion undercut: z = 17 < z_min = 18.3", "tip radius 0.2 mm"}, 3);
  t.add({}, 4);
  t.add({"pinion undercut: z = 16 < z_min = 18.1"}, 7);
  // Two messages of one kind in one design count that design once.
  t.add({"pinion undercut: z = 17 < z_min = 18.3", "pinion undercut: z = 15 < z_min = 17.9"}, 12);
  ASSERT_EQ(t.groups().size(), 2u);
  const WarningGroup& g = t.groups()[0];
  EXPECT_EQ(g.kind, "pinion undercut: z = … < z_min = …");
  EXPECT_EQ(g.example, "pinion undercut: z = 17 < z_min = 18.3");
  EXPECT_EQ(g.designs, 3u);
  EXPECT_EQ(g.messages, 3u);
  EXPECT_EQ(g.evaluations, (std::vector<std::int64_t>{3, 7, 12}));
  EXPECT_EQ(t.groups()[1].kind, "tip radius … mm");
  EXPECT_EQ(t.groups()[1].designs, 1u);
  EXPECT_EQ(t.dropped(), 0u);
}

TEST(WarningTally, ListsTheFirstEvaluationsAndCapsTheKinds) {
  WarningTally t;
  for (std::int64_t id = 1; id <= 1000; ++id) t.add({"remark " + std::to_string(id)}, id);
  ASSERT_EQ(t.groups().size(), 1u);
  EXPECT_EQ(t.groups()[0].designs, 1000u);
  ASSERT_EQ(t.groups()[0].evaluations.size(), kMaxListedEvaluations);
  EXPECT_EQ(t.groups()[0].evaluations.back(), static_cast<std::int64_t>(kMaxListedEvaluations));
  WarningTally kinds;
  for (std::size_t k = 0; k < kMaxWarningKinds + 5; ++k) kinds.add({"kind " + std::string(k + 1, 'x')}, 1);
  EXPECT_EQ(kinds.groups().size(), kMaxWarningKinds);
  EXPECT_EQ(kinds.dropped(), 5u);
}

}  // namespace
}  // namespace rackopt::study
