// The models one evaluate_metrics call computed for one design, as the metric
// computations read them.
//
// Each model is computed at most once per call and only when a requested
// metric declared it (MetricDefinition::models). A metric reads a model
// through the accessor below: the accessor re-raises the model's DesignError
// when the model failed for this design (so the metric fails with the model's
// own code and message), and throws std::logic_error when the metric did not
// declare the model (a programming error the registry test catches).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/core/error.hpp"
#include "rackopt/dynamics/drive_dynamics.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"
#include "rackopt/metrics/evaluate_metrics.hpp"
#include "rackopt/metrics/mesh_dynamics_metrics.hpp"
#include "rackopt/metrics/tooth_stress.hpp"
#include "rackopt/stiffness/mesh_stiffness.hpp"
#include "rackopt/wear/wear_life.hpp"

namespace rackopt::metrics {

// Why a model could not be computed for this design (a DesignError's code
// and message) and which model's limit it is: "geometry" when the drive's
// geometry itself is impossible, whichever model ran into it.
struct ModelFailure {
  std::string code;
  std::string message;
  std::string model;  // model_name() of the cause
};

// A model's failure as a metric computation meets it: a DesignError that
// also says which model failed.
class ModelFailed : public DesignError {
 public:
  explicit ModelFailed(const ModelFailure& f) : DesignError(f.code, f.message), model_(f.model) {}
  const std::string& model() const { return model_; }

 private:
  std::string model_;
};

// A model's outcome: a value, a failure, or neither (not computed).
template <class T>
struct ModelSlot {
  std::optional<T> value;
  std::optional<ModelFailure> failure;
  bool computed() const { return value.has_value() || failure.has_value(); }
};

// The life at each requested reliability R (wear_life_at_R).
struct LifeAtR {
  std::vector<double> reliabilities;  // distinct R values, request order
  std::vector<double> life_s;         // per R [s]
  std::vector<std::string> remark;    // per R: which path gave it
};

struct ModelResults {
  const Drive* drive = nullptr;
  const MetricOptions* options = nullptr;
  StressInputs stress_inputs;

  ModelSlot<MeshGeometry> geometry_slot;
  ModelSlot<StiffnessCurve> curve_slot;
  MeshDynamicsFigures dynamics_figures;  // with the curve: only the parts a requested metric needs
  ModelSlot<WearLifeResult> wear_slot;   // nominal life (from the wear model or the reliability run)
  ModelSlot<LifeAtR> life_at_R_slot;
  ModelSlot<ToothStress> stress_slot;
  ModelSlot<DriveDynamics> dynamics_slot;  // only the parts the requested metrics read

  const MeshGeometry& geometry() const { return get(geometry_slot, "geometry"); }
  const StiffnessCurve& curve() const { return get(curve_slot, "stiffness_curve"); }
  const MeshRipple& mesh_ripple() const { return figure(dynamics_figures.ripple, "mesh_ripple"); }
  const TransmissionError& transmission_error() const {
    return figure(dynamics_figures.transmission_error, "transmission_error");
  }
  const WearLifeResult& wear_life() const { return get(wear_slot, "wear_life"); }
  const LifeAtR& life_at_R() const { return get(life_at_R_slot, "wear_reliability"); }
  const ToothStress& stress() const { return get(stress_slot, "stress"); }
  const DriveDynamics& dynamics() const { return get(dynamics_slot, "dynamics"); }

 private:
  // A per-period figure of the curve: a failed curve fails it too.
  template <class T>
  const T& figure(const std::optional<T>& value, const char* model) const {
    curve();
    if (!value) throw std::logic_error(std::string("a metric read the model '") + model +
                                       "' without declaring it in the metric registry");
    return *value;
  }
  template <class T>
  static const T& get(const ModelSlot<T>& slot, const char* model) {
    if (slot.failure) throw ModelFailed(*slot.failure);
    if (!slot.value) throw std::logic_error(std::string("a metric read the model '") + model +
                                            "' without declaring it in the metric registry");
    return *slot.value;
  }
};

}  // namespace rackopt::metrics
