// Several plane-stress bodies in frictionless penalty contact, solved by
// CalculiX in load steps driven by prescribed displacements: the deck and
// the solve. The slice is thin as in ccx_deck.hpp (the plane-stress trap);
// forces read back are per metre of thickness.
//
// Contact: one *CONTACT PAIR per pair of flanks, TYPE=SURFACE TO SURFACE
// (face-to-face penalty, the form the CalculiX manual recommends for
// quadratic elements), PRESSURE-OVERCLOSURE=LINEAR with the given slope
// (pressure per overclosure, Pa/m). The penetration at contact pressure p is
// p / slope: the slope must be high enough that this is negligible against
// the deflection, which a caller shows by doubling it.
#pragma once

#include <string>
#include <vector>

#include "rackopt/fe/ccx_runner.hpp"
#include "rackopt/fe/plane_stress_model.hpp"

namespace rackopt::fe {

struct ContactBody {
  std::string name;  // prefix of its sets in the deck (letters/digits, short)
  Mesh2D mesh;
  double youngs_modulus = 0;
  double poisson_ratio = 0;
};

// The faces of `slave_set` (of body slave_body) against those of
// `master_set`: every triangle edge whose three nodes are in the set.
struct ContactSurfaces {
  int slave_body = 0;
  std::string slave_set;
  int master_body = 0;
  std::string master_set;
};

// Component `dof` (1 = x, 2 = y) of `node` of `body` held at values[k] in
// step k (one value per step).
struct SteppedDisplacement {
  int body = 0;
  int node = 0;
  int dof = 1;
  std::vector<double> values;
};

// A linear constraint between the nodes of one body (plane_stress_model.hpp).
struct BodyEquation {
  int body = 0;
  NodeEquation equation;
};

struct ContactModel {
  std::vector<ContactBody> bodies;
  std::vector<SteppedDisplacement> supports;
  std::vector<BodyEquation> equations;  // ties within a body (a hinge's rigid patch)
  std::vector<ContactSurfaces> contacts;
  double penalty_slope = 0;  // Pa/m
  int steps = 1;
  // Node sets (body, set) whose support reactions are read back per node.
  std::vector<std::pair<int, std::string>> reaction_sets;
  // Also read back every node's displacement at the end of the last step
  // (for pictures; it makes the .dat file a line per node longer).
  bool print_displacements = false;
};

// What one step ended with.
struct ContactStepResult {
  // Per reaction set: (node index in its body, force the support exerts, N/m).
  std::vector<std::vector<std::pair<int, Point2>>> reactions;
  // Per contact: total contact force (as ccx's statistics give it, N/m) and
  // whether the pair was in contact at all.
  std::vector<Point2> contact_force;
  std::vector<bool> in_contact;
  // Per body, per node: the displacement [m]; only in the last step's
  // result and only when the model asked for it (print_displacements).
  std::vector<std::vector<Point2>> displacements;
};

// The deck. Throws std::invalid_argument naming what is wrong (no body, a
// body without triangles or support, bad material, a set or contact face
// that does not exist, a support with the wrong number of values).
std::string ccx_contact_deck(const ContactModel& model, double slice_thickness);

// Solves it (slice_thickness <= 0: slice_thickness_for of the bodies'
// joint bounding box). One result per step. Errors: those of run_ccx
// (CcxNotFound, CcxError with the deck kept, non-convergence included) and
// of ccx_contact_deck.
std::vector<ContactStepResult> solve_contact(const ContactModel& model, const CcxOptions& options = {},
                                             double slice_thickness = 0);

}  // namespace rackopt::fe
