#include "rackopt/fe/ccx_contact_deck.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "rackopt/fe/ccx_dat.hpp"
#include "rackopt/fe/ccx_deck.hpp"

namespace rackopt::fe {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void fail(const std::string& what) { throw std::invalid_argument("contact model: " + what); }

// CalculiX reads at most 16 entries per data line of *NSET.
void write_set(std::ostringstream& o, const std::string& name, const std::vector<int>& nodes, int offset) {
  o << "*NSET, NSET=" << name << "\n";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    o << nodes[i] + offset + 1 << (i + 1 == nodes.size() || (i + 1) % 16 == 0 ? ",\n" : ", ");
  }
}

std::string set_name(const ContactBody& b, const std::string& set) { return upper(b.name + "_" + set); }

// (element index within the body, face 1..3) of the edges whose three nodes are in `set`.
std::vector<std::pair<int, int>> faces_of(const Mesh2D& mesh, const std::vector<int>& set) {
  const std::set<int> in(set.begin(), set.end());
  std::vector<std::pair<int, int>> out;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const Triangle6& t = mesh.triangles[e];
    // CPS6 faces: 1 = corners 0-1 (mid 3), 2 = corners 1-2 (mid 4), 3 = corners 2-0 (mid 5).
    const int edges[3][3] = {{t[0], t[1], t[3]}, {t[1], t[2], t[4]}, {t[2], t[0], t[5]}};
    for (int f = 0; f < 3; ++f) {
      if (in.count(edges[f][0]) && in.count(edges[f][1]) && in.count(edges[f][2])) {
        out.emplace_back(static_cast<int>(e), f + 1);
      }
    }
  }
  return out;
}

std::vector<int> offsets_of(const std::vector<ContactBody>& bodies, bool elements) {
  std::vector<int> off;
  int n = 0;
  for (const ContactBody& b : bodies) {
    off.push_back(n);
    n += static_cast<int>(elements ? b.mesh.triangles.size() : b.mesh.nodes.size());
  }
  return off;
}

void check(const ContactModel& m) {
  if (m.bodies.empty()) fail("no body");
  if (m.steps < 1) fail("at least one step");
  if (!(m.penalty_slope > 0) || !std::isfinite(m.penalty_slope)) fail("the penalty slope must be positive");
  std::set<std::string> prefixes;
  for (const ContactBody& b : m.bodies) {
    if (b.mesh.triangles.empty()) fail("body " + b.name + " has no triangles");
    if (!(b.youngs_modulus > 0) || !(b.poisson_ratio > -1 && b.poisson_ratio < 0.5)) fail("body " + b.name + ": bad material");
    check_set_name(b.name);
    if (!prefixes.insert(upper(b.name)).second) fail("two bodies named " + b.name);
  }
  const int nb = static_cast<int>(m.bodies.size());
  for (const SteppedDisplacement& s : m.supports) {
    if (s.body < 0 || s.body >= nb) fail("support on body " + std::to_string(s.body));
    if (s.node < 0 || s.node >= static_cast<int>(m.bodies[s.body].mesh.nodes.size())) fail("support on a node not in the body");
    if (s.dof != 1 && s.dof != 2) fail("support dof must be 1 or 2");
    if (static_cast<int>(s.values.size()) != m.steps) fail("a support needs one value per step");
    for (double v : s.values) {
      if (!std::isfinite(v)) fail("support value is not finite");
    }
  }
  for (const BodyEquation& e : m.equations) {
    if (e.body < 0 || e.body >= nb) fail("equation on body " + std::to_string(e.body));
    check_equations({e.equation}, static_cast<int>(m.bodies[e.body].mesh.nodes.size()), "contact model");
  }
  for (const ContactSurfaces& c : m.contacts) {
    if (c.slave_body < 0 || c.slave_body >= nb || c.master_body < 0 || c.master_body >= nb) fail("contact on a body not in the model");
    m.bodies[c.slave_body].mesh.node_set(c.slave_set);  // throws naming the set
    m.bodies[c.master_body].mesh.node_set(c.master_set);
  }
  for (const auto& [b, set] : m.reaction_sets) {
    if (b < 0 || b >= nb) fail("reaction set on a body not in the model");
    m.bodies[b].mesh.node_set(set);
  }
}

// Every node's displacement at the end of the last step (total time = steps),
// split by body. The displacements of the unit-thickness body need no
// scaling: the deck's forces were scaled with the slice.
void read_displacements(const std::vector<DatBlock>& blocks, const ContactModel& m, const std::vector<int>& node_off,
                        ContactStepResult& last) {
  const DatBlock* found = nullptr;
  for (const DatBlock& blk : blocks) {
    if (blk.quantity == "displacements" && upper(blk.set) == "NALL" && std::abs(blk.time - m.steps) < 1e-6) found = &blk;
  }
  if (!found) throw std::runtime_error("job.dat has no displacements at the end of step " + std::to_string(m.steps));
  last.displacements.resize(m.bodies.size());
  std::size_t total = 0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    last.displacements[b].assign(m.bodies[b].mesh.nodes.size(), Point2{});
    total += m.bodies[b].mesh.nodes.size();
  }
  if (found->rows.size() != total) {
    throw std::runtime_error("job.dat has displacements of " + std::to_string(found->rows.size()) + " nodes, the bodies " +
                             std::to_string(total));
  }
  for (const auto& [node, v] : found->rows) {
    const int i = node - 1;
    std::size_t b = m.bodies.size();
    while (b > 0 && i < node_off[b - 1]) --b;
    if (b == 0 || i - node_off[b - 1] >= static_cast<int>(m.bodies[b - 1].mesh.nodes.size())) {
      throw std::runtime_error("job.dat: displacement of node " + std::to_string(node) + " outside every body");
    }
    last.displacements[b - 1][static_cast<std::size_t>(i - node_off[b - 1])] = {v[0], v[1]};
  }
}

}  // namespace

std::string ccx_contact_deck(const ContactModel& m, double slice_thickness) {
  check(m);
  if (!(slice_thickness > 0) || !std::isfinite(slice_thickness)) fail("the slice thickness must be positive");
  const std::vector<int> node_off = offsets_of(m.bodies, false), elem_off = offsets_of(m.bodies, true);
  std::ostringstream o;
  o.precision(13);
  o << "*HEADING\nrackopt FE reference: plane-stress bodies in contact, CPS6, slice thickness " << slice_thickness
    << " m\n";
  o << "*NODE, NSET=NALL\n";
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    for (std::size_t i = 0; i < m.bodies[b].mesh.nodes.size(); ++i) {
      const Point2& p = m.bodies[b].mesh.nodes[i];
      o << node_off[b] + static_cast<int>(i) + 1 << ", " << p.x << ", " << p.y << ", 0\n";
    }
  }
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const ContactBody& body = m.bodies[b];
    o << "*ELEMENT, TYPE=CPS6, ELSET=E_" << upper(body.name) << "\n";
    for (std::size_t e = 0; e < body.mesh.triangles.size(); ++e) {
      o << elem_off[b] + static_cast<int>(e) + 1;
      for (int n : body.mesh.triangles[e]) o << ", " << n + node_off[b] + 1;
      o << "\n";
    }
    for (const auto& [name, nodes] : body.mesh.node_sets) {
      if (!nodes.empty()) write_set(o, set_name(body, name), nodes, node_off[b]);
    }
  }
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const ContactBody& body = m.bodies[b];
    o << "*MATERIAL, NAME=M_" << upper(body.name) << "\n*ELASTIC\n" << body.youngs_modulus << ", " << body.poisson_ratio
      << "\n";
    o << "*SOLID SECTION, ELSET=E_" << upper(body.name) << ", MATERIAL=M_" << upper(body.name) << "\n"
      << slice_thickness << "\n";
  }
  for (const BodyEquation& e : m.equations) write_ccx_equations(o, {e.equation}, node_off[e.body]);
  if (!m.contacts.empty()) {
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
      const ContactSurfaces& c = m.contacts[k];
      for (int side = 0; side < 2; ++side) {
        const int b = side == 0 ? c.slave_body : c.master_body;
        const std::string& set = side == 0 ? c.slave_set : c.master_set;
        const auto faces = faces_of(m.bodies[b].mesh, m.bodies[b].mesh.node_set(set));
        if (faces.empty()) fail("set " + set + " of body " + m.bodies[b].name + " holds no element edge");
        o << "*SURFACE, NAME=C" << k << (side == 0 ? "S" : "M") << ", TYPE=ELEMENT\n";
        for (const auto& [e, f] : faces) o << elem_off[b] + e + 1 << ", S" << f << "\n";
      }
    }
    o << "*SURFACE INTERACTION, NAME=FLANKS\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n" << m.penalty_slope << "\n";
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
      o << "*CONTACT PAIR, INTERACTION=FLANKS, TYPE=SURFACE TO SURFACE\nC" << k << "S, C" << k << "M\n";
    }
  }
  for (int step = 0; step < m.steps; ++step) {
    // Contact makes every step nonlinear. The whole step in one increment
    // first (ccx converges once the set of contact elements stops changing,
    // which takes about as many iterations for a small increment as for a
    // large one); ccx cuts it back when that does not converge.
    o << "*STEP, INC=400\n*STATIC\n1.0, 1.0, 1e-6, 1.0\n*BOUNDARY\n";
    for (const SteppedDisplacement& s : m.supports) {
      o << node_off[s.body] + s.node + 1 << ", " << s.dof << ", " << s.dof << ", " << s.values[step] << "\n";
    }
    for (const auto& [b, set] : m.reaction_sets) o << "*NODE PRINT, NSET=" << set_name(m.bodies[b], set) << "\nRF\n";
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
      o << "*CONTACT PRINT, SLAVE=C" << k << "S, MASTER=C" << k << "M\nCF\n";
    }
    if (m.print_displacements && step + 1 == m.steps) o << "*NODE PRINT, NSET=NALL\nU\n";
    o << "*END STEP\n";
  }
  return o.str();
}

std::vector<ContactStepResult> solve_contact(const ContactModel& m, const CcxOptions& options, double slice_thickness) {
  if (slice_thickness <= 0) {
    Mesh2D all;
    for (const ContactBody& b : m.bodies) all.nodes.insert(all.nodes.end(), b.mesh.nodes.begin(), b.mesh.nodes.end());
    slice_thickness = slice_thickness_for(all);
  }
  const double t = slice_thickness;
  const std::string deck = ccx_contact_deck(m, t);
  const std::vector<int> node_off = offsets_of(m.bodies, false);
  std::vector<ContactStepResult> results(static_cast<std::size_t>(m.steps));
  run_ccx(
      deck,
      [&](const std::string& dat_text) {
        const std::vector<DatBlock> blocks = parse_ccx_dat(dat_text, "job.dat");
        const std::vector<ContactStatistics> stats = parse_ccx_contact_statistics(dat_text, "job.dat");
        // Step k ends at total time k + 1: its last output.
        const auto at_end = [](double time, int step) { return std::abs(time - (step + 1)) < 1e-6; };
        for (int step = 0; step < m.steps; ++step) {
          ContactStepResult& r = results[static_cast<std::size_t>(step)];
          for (const auto& [b, set] : m.reaction_sets) {
            const std::string name = set_name(m.bodies[b], set);
            const DatBlock* found = nullptr;
            for (const DatBlock& blk : blocks) {
              if (blk.quantity == "forces" && upper(blk.set) == name && at_end(blk.time, step)) found = &blk;
            }
            if (!found) throw std::runtime_error("job.dat has no reactions of " + name + " at the end of step " + std::to_string(step + 1));
            std::vector<std::pair<int, Point2>> rows;
            const int lo = node_off[b], n = static_cast<int>(m.bodies[b].mesh.nodes.size());
            for (const auto& [node, v] : found->rows) {
              if (node - 1 < lo || node - 1 >= lo + n) throw std::runtime_error("job.dat: reaction on node " + std::to_string(node) + " outside " + name);
              rows.emplace_back(node - 1 - lo, Point2{v[0] / t, v[1] / t});
            }
            r.reactions.push_back(rows);
          }
          for (std::size_t k = 0; k < m.contacts.size(); ++k) {
            const std::string slave = "C" + std::to_string(k) + "S", master = "C" + std::to_string(k) + "M";
            const ContactStatistics* found = nullptr;
            for (const ContactStatistics& c : stats) {
              if (upper(c.slave) == slave && upper(c.master) == master && at_end(c.time, step)) found = &c;
            }
            r.in_contact.push_back(found != nullptr && found->area > 0);
            r.contact_force.push_back(found ? Point2{found->force[0] / t, found->force[1] / t} : Point2{});
          }
        }
        if (m.print_displacements) read_displacements(blocks, m, node_off, results.back());
      },
      options);
  return results;
}

}  // namespace rackopt::fe
