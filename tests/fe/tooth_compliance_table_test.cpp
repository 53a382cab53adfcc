// The measured table of docs/models/fe_reference.md ("Single-tooth
// compliances"): FE vs analytic for every shipped problem at levels 0 and 1,
// pinion and rack, five contacts along the path. Not part of the suite (it
// takes minutes); rerun with
//   build/test_fe --gtest_also_run_disabled_tests --gtest_filter='*ToothComplianceTable*'
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fe_test_helpers.hpp"
#include "rackopt/fe/tooth_compliance_fe.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "support/shipped_problems.hpp"

namespace rackopt::fe {
namespace {

using testing::cpu_seconds;

TEST(FeToothCompliance, DISABLED_ToothComplianceTable) {
  const char* levels_env = std::getenv("RACKOPT_FE_LEVELS");
  const int max_level = levels_env ? std::atoi(levels_env) : 1;
  for (const char* name : {"gantry_axis", "large_module", "rack_railway", "rack_railway_paper", "ship_lift"}) {
    const Drive d = test_support::load_shipped_problem(std::string(name) + ".yaml");
    const MeshGeometry g = build_mesh_geometry(d);
    for (int level = 0; level <= max_level; ++level) {
      FeOptions o;
      o.level = level;
      for (ToothMember member : {ToothMember::kPinion, ToothMember::kRack}) {
        for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
          // The same contacts for both members: on the pinion's involute.
          const double lo = std::max({g.path.s_start, g.path.s_form, 1e-3 * g.path.base_pitch});
          const double s = lo + f * (g.path.s_end - lo);
          const double cpu0 = cpu_seconds();
          const ToothComplianceFe r = fe_tooth_compliance(d, member, s, o);
          const double cpu = cpu_seconds() - cpu0;
          std::printf("| %s | %d | %s | %.2f | %.4g | %.4g | %.3f | %d | %d | %.2f | %.2f |\n", name, level,
                      member == ToothMember::kPinion ? "pinion" : "rack", s * 1e3, r.compliance * 1e9,
                      r.analytic * 1e9, r.compliance / r.analytic, r.elements, r.nodes, r.seconds, cpu);
          std::fflush(stdout);
        }
      }
    }
  }
}

}  // namespace
}  // namespace rackopt::fe
