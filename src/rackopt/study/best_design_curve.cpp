#include "rackopt/study/best_design_curve.hpp"

#include <memory>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"

namespace rackopt::study {

void attach_best_design_curve(const StudySpec& spec, StudyResult& result) {
  if (!spec.output.stiffness_curve || !result.best_drive) return;
  try {
    const MeshStiffnessModel model(*result.best_drive);
    result.best_curve = std::make_shared<const StiffnessCurve>(model.curve());
  } catch (const DesignError& e) {
    // A design the optimizer kept can still be one the whole-span curve
    // refuses; the study's results stand, the report says why it has no curve.
    result.best_curve_error = std::string("no stiffness curve of the best design (") + e.code() + "): " + e.what();
  }
}

}  // namespace rackopt::study
