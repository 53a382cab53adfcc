// PairCompliance: which range warnings a pair gives. Sainsot's table is
// fitted for theta_f 0.01..0.12 rad; the FE calibration of the fillet
// foundation (docs/models/fillet_calibration.md) was fitted on top of that
// table extrapolated in theta_f over 0.06..0.26 rad, so inside the
// calibration's range only Sainsot's h_f range is worth a warning.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/fillet_calibration.hpp"
#include "rackopt/stiffness/fillet_foundation.hpp"
#include "rackopt/stiffness/pair_compliance.hpp"
#include "test_drives.hpp"

namespace rackopt {
namespace {

Drive gantry(const std::vector<std::string>& overrides = {}) {
  return test::problem("gantry_axis.yaml", overrides);
}

bool any_warning_starts(const PairCompliance& pair, const std::string& head) {
  for (const std::string& w : pair.warnings()) {
    if (w.rfind(head, 0) == 0) return true;
  }
  return false;
}

TEST(PairComplianceWarnings, SainsotThetaRangeIsCoveredByTheCalibration) {
  // The gantry's 20-tooth pinion: theta_f above Sainsot's 0.12 rad, inside
  // the calibration's 0.06..0.26 rad.
  Drive d = gantry();
  const MeshGeometry g = build_mesh_geometry(d);
  const FilletFoundationCompliance sainsot(g, d.pinion);
  const FilletCalibration calibration(g, d.pinion);
  ASSERT_GT(sainsot.theta_f(), 0.12);
  ASSERT_FALSE(calibration.outside_fitted_range());
  ASSERT_GE(sainsot.h_f(), 1.4);
  ASSERT_LE(sainsot.h_f(), 7.0);

  EXPECT_FALSE(any_warning_starts(PairCompliance(d, g), "fillet foundation"));
  EXPECT_FALSE(any_warning_starts(PairCompliance(d, g), "fillet calibration"));

  d.effects.fillet_calibration = false;
  EXPECT_TRUE(any_warning_starts(PairCompliance(d, g), "fillet foundation"));
}

TEST(PairComplianceWarnings, HfOutsideSainsotWarnsEvenWhenCalibrated) {
  // A bore close to the root circle: h_f = r_f / r_bore below 1.4.
  Drive d = gantry();
  const MeshGeometry g0 = build_mesh_geometry(d);
  d.pinion.bore_radius = 0.8 * g0.pinion.root_radius;
  const MeshGeometry g = build_mesh_geometry(d);
  ASSERT_LT(FilletFoundationCompliance(g, d.pinion).h_f(), 1.4);
  const PairCompliance pair(d, g);
  EXPECT_TRUE(any_warning_starts(pair, "fillet foundation"));
  bool names_calibration = false;
  for (const std::string& w : pair.warnings()) {
    names_calibration = names_calibration || w.find("theta_f covered by the FE calibration") != std::string::npos;
  }
  EXPECT_TRUE(names_calibration);
}

TEST(PairComplianceWarnings, ThetaOutsideTheCalibrationWarnsAboutTheCalibration) {
  // Many teeth: theta_f far below the calibration's 0.06 rad.
  Drive d = gantry({"pinion.teeth=120"});
  const MeshGeometry g = build_mesh_geometry(d);
  const FilletCalibration calibration(g, d.pinion);
  ASSERT_TRUE(calibration.outside_fitted_range()) << calibration.theta_f();
  EXPECT_TRUE(any_warning_starts(PairCompliance(d, g), "fillet calibration"));
}

}  // namespace
}  // namespace rackopt
