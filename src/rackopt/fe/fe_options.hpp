// Settings shared by the FE reference solves of a drive (single-tooth
// compliances, mesh positions): fidelity level, contact model, solver.
#pragma once

#include "rackopt/fe/ccx_runner.hpp"

namespace rackopt::fe {

struct FeOptions {
  // Refinement level 0..6: element size gear_element_size(module, level) on
  // the loaded teeth (0 = module / 6, each level halves it); finer discs at
  // the contacts and fillets follow the same level.
  int level = 0;
  // false: contact only between the flanks of the pairs the analytic model
  // has in mesh (the theoretical pairs). true: also the neighbouring flanks,
  // which touch early under load without tip relief; their load is reported.
  bool extended_contact = false;
  // Depth of the FE rack segment's body below the root line [m]; <= 0: the
  // drive's rack body height (its section depth below the root line when
  // the section was given explicitly: twice the neutral-axis depth).
  double rack_body_depth = 0;
  // true: a mesh-position solve hands back its mesh and the nodal
  // displacements of its last load step (FePosition::shape), for pictures.
  // The numbers do not depend on it.
  bool keep_shape = false;
  // false: the rack segment's base is held (a rigid rack body). true: the
  // rack is the whole span (rack.span, all its teeth, fine only on the teeth
  // in mesh and their neighbours) on its two hinges at the neutral axis,
  // pin-pin or pin-roller as rack.supports says (fe/rack_span_fe.hpp), so
  // the body bends and stretches as the analytic rack-span model has it.
  // Mesh positions only; the single-tooth compliances keep their segment.
  bool rack_on_supports = false;
  // The ccx program, time limit and work folder.
  CcxOptions ccx;
};

// Throws std::invalid_argument naming the field when a value is out of range.
void check_fe_options(const FeOptions& options);

}  // namespace rackopt::fe
