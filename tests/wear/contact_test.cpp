// Contact along the rack-pinion path (docs/models/wear.md)
// for the wear paper's ship-lift drive.
#include <gtest/gtest.h>

#include <cmath>

#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/stiffness/hertz.hpp"
#include "rackopt/wear/contact.hpp"
#include "wear_drives.hpp"

namespace rackopt {
namespace {

// docs/models/wear.md table: full load on one pair, b = 120 mm, E* = 111.9 GPa.
TEST(Contact, WearPaperHertzAlongThePath) {
  const Drive d = test::ship_lift();
  const double e_star = effective_modulus(d.pinion.material, d.rack.material);
  EXPECT_NEAR(e_star / 1e9, 111.9, 0.05);  // docs/models/tooth.md
  const double w = d.load.force / d.pinion.face_width;
  struct Row {
    double s_mm, a_mm, p0_mpa;
  };
  for (const Row& r : {Row{80.3, 2.70, 1880}, Row{172.4, 3.95, 1283}, Row{365.9, 5.76, 881}}) {
    const HertzLineContact c = hertz_line_contact(w, r.s_mm * 1e-3, e_star);  // R' = s (flat rack)
    EXPECT_NEAR(c.half_width * 1e3, r.a_mm, 0.006) << r.s_mm;
    EXPECT_NEAR(c.peak_pressure / 1e6, r.p0_mpa, 0.003 * r.p0_mpa) << r.s_mm;
    // The elliptic pressure carries w: p_mean * 2a = w, p_mean = pi/4 p0.
    EXPECT_NEAR(c.mean_pressure * 2 * c.half_width / w, 1.0, 1e-14);
    EXPECT_NEAR(c.mean_pressure / c.peak_pressure, M_PI / 4, 1e-15);
  }
  EXPECT_EQ(hertz_line_contact(0, 0.1, e_star).half_width, 0.0);
  EXPECT_THROW(hertz_line_contact(-1, 0.1, e_star), InputError);
  EXPECT_THROW(hertz_line_contact(1, 0, e_star), InputError);
}

// docs/models/wear.md: zeta_rack = -1.12 at the pinion tip, zeta_pinion = -1.15 at
// the pinion root; zero sliding at the pitch point.
TEST(Contact, WearPaperSpecificSliding) {
  const MeshGeometry g = build_mesh_geometry(test::ship_lift());
  EXPECT_NEAR(g.path.s_start * 1e3, 80.3, 0.05);  // docs/models/reliability.md
  EXPECT_NEAR(g.path.s_end * 1e3, 365.9, 0.05);
  const RackPinionSliding k(g.path.s_pitch, 1e-3 * g.pinion.base_radius);
  EXPECT_NEAR(k.rack_specific_sliding(g.path.s_end), -1.12, 0.005);
  EXPECT_NEAR(k.pinion_specific_sliding(g.path.s_start), -1.15, 0.005);
  EXPECT_EQ(k.sliding(g.path.s_pitch), 0.0);
  EXPECT_EQ(k.rack_sliding_ratio(g.path.s_pitch), 0.0);
  EXPECT_EQ(k.pinion_sliding_ratio(g.path.s_pitch), 0.0);
  // The rack root (meets the pinion tip) slides more than the rack tip.
  EXPECT_GT(k.rack_sliding_ratio(g.path.s_end), k.rack_sliding_ratio(g.path.s_start));
  // s -> 0: the pinion rolling speed is floored, the ratio stays finite.
  EXPECT_TRUE(std::isfinite(k.pinion_sliding_ratio(0.0)));
  EXPECT_TRUE(std::isfinite(k.pinion_sliding_ratio(-1.0)));
}

// docs/models/wear.md: the wear paper's law dh = K p0 s2 / H with s2 = 12.9 mm at the
// pinion tip (full load on one pair) gives 2.6e5 meshes to 1.5 mm for K = 3e-6;
// ours (p_mean, docs/models/wear.md) is 4/pi smaller per pass, so 4/pi more meshes.
TEST(Contact, WearPaperReferenceWearRateAndTheFourOverPiFactor) {
  const Drive d = test::ship_lift();
  const MeshGeometry g = build_mesh_geometry(d);
  const double e_star = effective_modulus(d.pinion.material, d.rack.material);
  const double w = d.load.force / d.pinion.face_width;
  const double s = g.path.s_end;
  const HertzLineContact c = hertz_line_contact(w, s, e_star);
  const RackPinionSliding kin(g.path.s_pitch, 1e-3 * g.pinion.base_radius);
  const double s2 = 2 * c.half_width * kin.rack_sliding_ratio(s);
  EXPECT_NEAR(s2 * 1e3, 12.9, 0.05);
  const double H = 596 * kPaPerHB, K = 3e-6;
  const double seed_dh = K * c.peak_pressure * s2 / H;
  EXPECT_NEAR(1.5e-3 / seed_dh / 2.6e5, 1.0, 0.02);
  const double ours = archard_pass_wear(K / H, w, kin.rack_sliding_ratio(s));
  EXPECT_NEAR(seed_dh / ours, 4 / M_PI, 1e-12);
  EXPECT_NEAR(ours, K / H * c.mean_pressure * s2, 1e-12 * ours);
}

}  // namespace
}  // namespace rackopt
