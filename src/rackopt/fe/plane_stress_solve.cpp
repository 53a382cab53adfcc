#include "rackopt/fe/plane_stress_solve.hpp"

#include <cmath>
#include <map>
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
        // ccx's RF is the node's internal force K u, which on a node that is
        // both supported and loaded includes the load: the support's
        // reaction is RF minus the load there (the total printed by ccx is
        // not used for that reason).
        std::map<int, Point2> load_at;
        for (const NodeLoad& l : model.loads) {
          load_at[l.node].x += l.fx;
          load_at[l.node].y += l.fy;
        }
        const DatBlock& rf = find_dat_block(blocks, "forces", kSupportSet);
        for (const auto& [node, v] : rf.rows) {
          const auto it = load_at.find(node - 1);
          const Point2 f = it == load_at.end() ? Point2{} : it->second;
          result.reactions.push_back({node - 1, v[0] / t - f.x, v[1] / t - f.y});
          result.total_reaction.x += result.reactions.back().fx;
          result.total_reaction.y += result.reactions.back().fy;
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
