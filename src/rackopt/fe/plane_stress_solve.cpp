#include "rackopt/fe/plane_stress_solve.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "rackopt/fe/ccx_dat.hpp"
#include "rackopt/fe/ccx_deck.hpp"

namespace rackopt::fe {

PlaneStressResult solve_plane_stress(const PlaneStressModel& model, const CcxOptions& options,
                                     double slice_thickness) {
  PlaneStressResult result;
  result.slice_thickness = slice_thickness > 0 ? slice_thickness : slice_thickness_for(model.mesh);
  const std::string deck = ccx_deck(model, result.slice_thickness);
  const double t = result.slice_thickness;
  const std::size_t n = model.mesh.nodes.size();
  run_ccx(
      deck,
      [&](const std::string& dat_text) {
        const std::vector<DatBlock> blocks = parse_ccx_dat(dat_text, "job.dat");
        const DatBlock& u = find_dat_block(blocks, "displacements", "NALL");
        if (u.rows.size() != n) {
          throw std::runtime_error("job.dat has displacements of " + std::to_string(u.rows.size()) + " nodes, the mesh " +
                                   std::to_string(n));
        }
        result.displacement.assign(n, Point2{});
        for (const auto& [node, v] : u.rows) {
          if (node < 1 || static_cast<std::size_t>(node) > n) throw std::runtime_error("job.dat names node " + std::to_string(node));
          result.displacement[node - 1] = {v[0], v[1]};
        }
        const DatBlock& rf = find_dat_block(blocks, "forces", kSupportSet);
        for (const auto& [node, v] : rf.rows) result.reactions.push_back({node - 1, v[0] / t, v[1] / t});
        result.total_reaction = rf.has_total ? Point2{rf.total[0] / t, rf.total[1] / t} : Point2{};
        if (!rf.has_total) {
          for (const NodeLoad& r : result.reactions) {
            result.total_reaction.x += r.fx;
            result.total_reaction.y += r.fy;
          }
        }
        Point2 applied;
        double scale = 0;
        for (const NodeLoad& l : model.loads) {
          applied.x += l.fx;
          applied.y += l.fy;
          scale += std::hypot(l.fx, l.fy);
        }
        for (const NodeLoad& r : result.reactions) scale += std::hypot(r.fx, r.fy);
        const double imbalance = std::hypot(applied.x + result.total_reaction.x, applied.y + result.total_reaction.y);
        if (imbalance > 1e-5 * scale) {
          std::ostringstream s;
          s << "loads and reactions do not balance (imbalance " << imbalance
            << " N/m): is the model supported against rigid motion?";
          throw std::runtime_error(s.str());
        }
      },
      options);
  return result;
}

}  // namespace rackopt::fe
