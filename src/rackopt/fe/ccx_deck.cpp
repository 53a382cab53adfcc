#include "rackopt/fe/ccx_deck.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rackopt::fe {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// CalculiX reads at most 16 entries per data line of *NSET.
void write_set(std::ostringstream& o, const std::string& name, const std::vector<int>& nodes) {
  o << "*NSET, NSET=" << name << "\n";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    o << nodes[i] + 1 << (i + 1 == nodes.size() || (i + 1) % 16 == 0 ? ",\n" : ", ");
  }
}

}  // namespace

double slice_thickness_for(const Mesh2D& mesh) {
  if (mesh.nodes.empty()) throw std::invalid_argument("slice_thickness_for: empty mesh");
  double x0 = mesh.nodes[0].x, x1 = x0, y0 = mesh.nodes[0].y, y1 = y0;
  for (const Point2& p : mesh.nodes) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  return 1e-3 * std::max(x1 - x0, y1 - y0);
}

void write_ccx_equations(std::ostream& out, const std::vector<NodeEquation>& equations, int node_offset) {
  if (equations.empty()) return;
  out << "*EQUATION\n";
  for (const NodeEquation& eq : equations) {
    out << eq.terms.size() << "\n";
    // At most four terms (12 entries) per line.
    for (std::size_t i = 0; i < eq.terms.size(); ++i) {
      const EquationTerm& t = eq.terms[i];
      out << t.node + node_offset + 1 << ", " << t.dof << ", " << t.coefficient
          << (i + 1 == eq.terms.size() || (i + 1) % 4 == 0 ? "\n" : ", ");
    }
  }
}

std::string ccx_deck(const PlaneStressModel& model, double slice_thickness) {
  check_model(model);
  if (!(slice_thickness > 0) || !std::isfinite(slice_thickness)) {
    throw std::invalid_argument("ccx_deck: the slice thickness must be positive");
  }
  std::set<std::string> seen;
  for (const auto& [name, nodes] : model.mesh.node_sets) {
    const std::string u = upper(name);
    if (u == kSupportSet || u == "NALL" || u == "EALL") throw std::invalid_argument("node set name " + name + " is reserved");
    if (!seen.insert(u).second) throw std::invalid_argument("node sets " + name + " and another differ only in case");
  }
  std::ostringstream o;
  o.precision(13);  // ccx reads at most 20 characters per number: -1.234567890123E-05
  o << "*HEADING\nrackopt FE reference: plane stress, CPS6, slice thickness " << slice_thickness << " m\n";
  o << "*NODE, NSET=NALL\n";
  for (std::size_t i = 0; i < model.mesh.nodes.size(); ++i) {
    o << i + 1 << ", " << model.mesh.nodes[i].x << ", " << model.mesh.nodes[i].y << ", 0\n";
  }
  o << "*ELEMENT, TYPE=CPS6, ELSET=EALL\n";
  for (std::size_t e = 0; e < model.mesh.triangles.size(); ++e) {
    o << e + 1;
    for (int n : model.mesh.triangles[e]) o << ", " << n + 1;
    o << "\n";
  }
  for (const auto& [name, nodes] : model.mesh.node_sets) {
    if (!nodes.empty()) write_set(o, name, nodes);
  }
  std::set<int> supported;
  for (const PrescribedDisplacement& s : model.supports) supported.insert(s.node);
  for (const NodeEquation& eq : model.equations) {
    for (const EquationTerm& t : eq.terms) supported.insert(t.node);
  }
  write_set(o, kSupportSet, std::vector<int>(supported.begin(), supported.end()));
  o << "*MATERIAL, NAME=SOLID\n*ELASTIC\n" << model.youngs_modulus << ", " << model.poisson_ratio << "\n";
  o << "*SOLID SECTION, ELSET=EALL, MATERIAL=SOLID\n" << slice_thickness << "\n";
  o << "*BOUNDARY\n";
  for (const PrescribedDisplacement& s : model.supports) {
    o << s.node + 1 << ", " << s.dof << ", " << s.dof << ", " << s.value << "\n";
  }
  write_ccx_equations(o, model.equations);
  o << "*STEP\n*STATIC\n";
  // Forces summed per node and direction: a node loaded twice gets one line.
  std::map<int, std::pair<double, double>> load;
  for (const NodeLoad& l : model.loads) {
    load[l.node].first += l.fx;
    load[l.node].second += l.fy;
  }
  if (!load.empty()) {
    o << "*CLOAD\n";
    for (const auto& [node, f] : load) {
      if (f.first != 0) o << node + 1 << ", 1, " << f.first * slice_thickness << "\n";
      if (f.second != 0) o << node + 1 << ", 2, " << f.second * slice_thickness << "\n";
    }
  }
  o << "*NODE PRINT, NSET=NALL\nU\n";
  o << "*NODE PRINT, NSET=" << kSupportSet << ", TOTALS=YES\nRF\n";
  o << "*END STEP\n";
  return o.str();
}

}  // namespace rackopt::fe
