#include "rackopt/problem/drive_sections.hpp"

#include <limits>

#include "rackopt/problem/problem_key_schema.hpp"

namespace rackopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// dynamics.speed_range: from <= to, both > 0 (the schema), and a point count
// that fits them: one point is one speed (from == to), two or more span a
// range of distinct speeds.
void read_speed_range(const SectionReader& dyn, DynamicsSpec& spec) {
  const SectionReader range =
      problem_section(dyn.get("speed_range"), "dynamics.speed_range", "dynamics.speed_range",
                      dyn.key_mark("speed_range"), {"from", "to", "points"});
  if (range.node() == nullptr) return;  // the dynamic model's default range around load.speed
  spec.speed_from = range.number("from", std::nullopt);
  spec.speed_to = range.number("to", std::nullopt);
  spec.speed_points = range.whole("points", std::nullopt);
  range.check_range("to", spec.speed_to, ValueRange{spec.speed_from, kInf, false, false},
                    " (the sweep runs up from speed_range.from; both speeds in the travel direction of load)");
  if (spec.speed_points == 1 && spec.speed_to != spec.speed_from) {
    range.check_range("points", static_cast<double>(spec.speed_points), ValueRange{2, kInf, false, false},
                      " (one point is one speed: give from == to, or at least 2 points to span " +
                          format_quantity(spec.speed_from, QuantityKind::kSpeed, "m/s") + " .. " +
                          format_quantity(spec.speed_to, QuantityKind::kSpeed, "m/s") + ")");
  }
  if (spec.speed_points > 1 && spec.speed_to == spec.speed_from) {
    range.check_range("points", static_cast<double>(spec.speed_points), ValueRange{1, 1, false, false},
                      " (from == to is a single speed: points: 1, or widen the range)");
  }
}

}  // namespace

void read_dynamics(const SectionReader& top, Drive& drive) {
  const SectionReader dyn =
      problem_section(top.get("dynamics"), "dynamics", "dynamics", top.key_mark("dynamics"),
                      {"moving_mass", "drive_inertia", "drive_stiffness", "damping_ratio", "speed_range"});
  DynamicsSpec& spec = drive.dynamics;
  const DynamicsSpec defaults;
  // Absent: not given (0). Only the dynamic model reads the section; it
  // refuses to run without a moving mass, and so does effects.dynamics below.
  spec.moving_mass = dyn.number("moving_mass", 0.0);
  spec.drive_inertia = dyn.number("drive_inertia", 0.0);
  spec.drive_stiffness = dyn.number("drive_stiffness", 0.0);
  spec.damping_ratio = dyn.number(
      "damping_ratio", defaults.damping_ratio,
      " (a fraction of critical damping; a gear mesh is never overdamped: measured ratios lie in 0.02 .. 0.1)");
  read_speed_range(dyn, spec);

  // A drive spring joins the pinion to the drive's inertia: without that
  // inertia the spring's far end has no mass and the drive train no motion.
  if (spec.drive_stiffness > 0 && !(spec.drive_inertia > 0)) {
    throw InputError(dyn.key_mark("drive_stiffness"), "dynamics.drive_stiffness",
                     "a drive spring (dynamics.drive_stiffness) needs the inertia it connects the pinion to: give "
                     "dynamics.drive_inertia (motor + gearbox reduced to the pinion shaft, J_motor i^2), or remove "
                     "drive_stiffness for a rigid drive train");
  }
  if (drive.effects.dynamics) {
    const SourceMark where = MarkedMap(top.get("effects"), "effects", top.key_mark("effects"), {}).key_mark("dynamics");
    if (!spec.given()) {
      throw InputError(where, "effects.dynamics",
                       "effects.dynamics: on takes K_V from the dynamic model, which needs the drive as a vibrating "
                       "system: give dynamics.moving_mass (what this pinion drives along the rack, e.g. 12 t)");
    }
    if (!(drive.load.speed > 0)) {
      throw InputError(where, "effects.dynamics",
                       "effects.dynamics: on computes K_V at the operating speed: give load.speed (e.g. 0.5 m/s)");
    }
  }
}

}  // namespace rackopt
