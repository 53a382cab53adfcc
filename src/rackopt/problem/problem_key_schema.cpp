#include "rackopt/problem/problem_key_schema.hpp"

#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "rackopt/core/drive.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/statistics/goodness_of_fit.hpp"  // kMinBootstrapReplicates

namespace rackopt {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Numeric keys: kind and the static part of the allowed range, in SI.
// Ranges that depend on other keys (bore radius < root radius, clearance
// relative to the module, tooth index, tooth offset <= span) are checked by
// the section readers on top of these.
struct KeySpec {
  const char* pattern;  // "pinion.module", "materials.*.E", "faults[].depth"
  NumberRule rule;
};

// Plausibility: every physical quantity has a lower bound as well as an upper
// one, generous enough for any real drive (a watch-size module 0.05 mm to a
// ship lift's 63 mm and beyond) but far above the tiny values that would
// underflow in the model (a 1e-300 mm body has I = 0) or that show a unit was
// forgotten (E: 5e-324 Pa). docs/yaml.md states each range next to its key.
constexpr double kMinLength = 0.1e-3;     // 0.1 mm: the smallest tooth, body or face dimension
constexpr double kMinSmallLength = 1e-6;  // 1 um: spall sizes, wear depths

constexpr KeySpec kKeySpecs[] = {
    {"pinion.teeth", {QuantityKind::kCount, {5, 1000, false, false}}},
    {"pinion.module", {QuantityKind::kLength, {0.05e-3, 1.0, false, false}}},
    {"pinion.pressure_angle", {QuantityKind::kAngle, {5 * kDeg, 45 * kDeg, false, false}}},
    {"pinion.face_width", {QuantityKind::kLength, {kMinLength, 10.0, false, false}}},
    {"pinion.profile_shift", {QuantityKind::kDimensionless, {-2, 2, false, false}}},
    {"pinion.addendum", {QuantityKind::kDimensionless, {0.1, 3, false, false}}},
    {"pinion.dedendum", {QuantityKind::kDimensionless, {0.1, 3, false, false}}},
    {"pinion.tip_radius", {QuantityKind::kDimensionless, {0, 1, false, false}}},
    {"pinion.bore_radius", {QuantityKind::kLength, {kMinLength, 10.0, false, false}}},
    // Profile relief (docs/yaml.md): amount along the flank normal; length a
    // multiple of the module (a length with its unit is accepted too, up to 5 m_n).
    {"pinion.tip_relief.amount", {QuantityKind::kLength, {0, 10e-3, false, false}}},
    {"pinion.tip_relief.length", {QuantityKind::kDimensionless, {0.01, 5, false, false}}},
    {"pinion.root_relief.amount", {QuantityKind::kLength, {0, 10e-3, false, false}}},
    {"pinion.root_relief.length", {QuantityKind::kDimensionless, {0.01, 5, false, false}}},
    {"rack.tip_relief.amount", {QuantityKind::kLength, {0, 10e-3, false, false}}},
    {"rack.tip_relief.length", {QuantityKind::kDimensionless, {0.01, 5, false, false}}},
    {"rack.root_relief.amount", {QuantityKind::kLength, {0, 10e-3, false, false}}},
    {"rack.root_relief.length", {QuantityKind::kDimensionless, {0.01, 5, false, false}}},
    {"rack.addendum", {QuantityKind::kDimensionless, {0.1, 3, false, false}}},
    {"rack.dedendum", {QuantityKind::kDimensionless, {0.1, 3, false, false}}},
    {"rack.face_width", {QuantityKind::kLength, {kMinLength, 10.0, false, false}}},
    {"rack.body_height", {QuantityKind::kLength, {kMinLength, 10.0, false, false}}},
    {"rack.body_width", {QuantityKind::kLength, {kMinLength, 10.0, false, false}}},
    {"rack.section.area", {QuantityKind::kArea, {1e-8, 100, false, false}}},
    {"rack.section.second_moment", {QuantityKind::kSecondMoment, {1e-18, 1000, false, false}}},
    {"rack.section.shear_area", {QuantityKind::kArea, {1e-8, 100, false, false}}},
    {"rack.section.neutral_axis_depth", {QuantityKind::kLength, {0.01e-3, 10.0, false, false}}},
    {"rack.span", {QuantityKind::kLength, {1e-3, 100.0, false, false}}},
    {"rack.tooth_offset", {QuantityKind::kLength, {0, 100.0, false, false}}},
    // 0 = the cutter tip radius; a round larger than the rack space is
    // clamped by the stress model (it depends on the geometry).
    {"rack.root_radius", {QuantityKind::kLength, {1e-6, 1.0, false, false}, true}},
    {"mounting.clearance", {QuantityKind::kLength, {0, 1.0, false, false}}},
    // 0.1 GPa: polyethylene; 1200 GPa: diamond.
    {"materials.*.E", {QuantityKind::kModulus, {0.1e9, 1200e9, false, false}}},
    {"materials.*.nu", {QuantityKind::kDimensionless, {0, 0.5, false, true}}},
    // Permissible stresses: 5 GPa is several times any gear steel's (a
    // case-hardened sigma_HP is ~1.5 GPa); above it a unit was forgotten.
    {"materials.*.allowable_bending", {QuantityKind::kModulus, {1e6, 5e9, false, false}}},
    {"materials.*.allowable_contact", {QuantityKind::kModulus, {1e6, 5e9, false, false}}},
    // Metals and polymers lie in 900..23000 kg/m^3 (POM ~1400, steel 7850).
    {"materials.*.density", {QuantityKind::kDensity, {500, 25000, false, false}}},
    // 1 mN (an instrument drive) .. 10 GN (ten times the largest ship lift).
    {"load.force", {QuantityKind::kForce, {1e-3, 1e10, false, false}}},
    {"load.torque", {QuantityKind::kTorque, {1e-6, 1e10, false, false}}},
    {"load.thrust", {QuantityKind::kForce, {1e-3, 1e10, false, false}}},
    // 50 m/s (180 km/h) is beyond any rack drive; above it a unit was forgotten.
    {"load.speed", {QuantityKind::kSpeed, {1e-6, 50, false, false}}},
    {"load.efficiency", {QuantityKind::kDimensionless, {0.05, 1, false, false}}},
    // ISO 6336 load factors are >= 1 by definition (1 = no extra load);
    // above 10 the simplified method is meaningless.
    {"load.application_factor", {QuantityKind::kDimensionless, {1, 10, false, false}}},
    {"load.dynamic_factor", {QuantityKind::kDimensionless, {1, 10, false, false}}},
    {"load.face_load_factor", {QuantityKind::kDimensionless, {1, 10, false, false}}},
    {"load.face_load_factor_bending", {QuantityKind::kDimensionless, {1, 10, false, false}}},
    {"load.transverse_load_factor", {QuantityKind::kDimensionless, {1, 10, false, false}}},
    {"faults[].tooth", {QuantityKind::kCount, {0, 1e9, false, false}}},
    {"faults[].start", {QuantityKind::kLength, {0, 10.0, false, false}}},
    {"faults[].length", {QuantityKind::kLength, {kMinSmallLength, 10.0, false, false}}},
    {"faults[].width", {QuantityKind::kLength, {kMinSmallLength, 10.0, false, false}}},
    {"faults[].depth", {QuantityKind::kLength, {kMinSmallLength, 1.0, false, false}}},
    {"numerics.quadrature_order", {QuantityKind::kCount, {2, 64, false, false}}},
    {"numerics.positions_per_period",
     {QuantityKind::kCount, {kPositionsPerPeriodLimit.lo, kPositionsPerPeriodLimit.hi, false, false}}},
    // Wear (docs/models/wear.md). Archard K spans mild wear ~1e-8 to severe
    // ~1e-2 (10.4); 1e-20..1 leaves room for any reading of a paper's k.
    {"wear.coefficient", {QuantityKind::kDimensionless, {1e-20, 1, false, false}}},
    {"wear.max_depth", {QuantityKind::kLength, {kMinSmallLength, 1.0, false, false}}},
    // Below 1 the drive loses continuous contact whatever the wear: the
    // allowable contact ratio of the wear paper's criterion is at least 1.
    {"wear.min_contact_ratio", {QuantityKind::kDimensionless, {1, 5, false, false}}},
    {"wear.profile_points", {QuantityKind::kCount, {5, 2000, false, false}}},
    {"wear.block_fraction", {QuantityKind::kDimensionless, {1e-6, 0.5, false, false}}},
    // One schema for wear.hardness, wear.pinion_hardness, wear.rack_hardness.
    // 2000 HB is far above any steel (a file-hard surface is ~ 700 HB).
    // 1 HB is far below any engineering polymer's indentation hardness.
    {"wear.hardness.surface", {QuantityKind::kHardness, {1 * kPaPerHB, 2000 * kPaPerHB, false, false}}},
    {"wear.hardness.core", {QuantityKind::kHardness, {1 * kPaPerHB, 2000 * kPaPerHB, false, false}}},
    {"wear.hardness.limit", {QuantityKind::kHardness, {1 * kPaPerHB, 2000 * kPaPerHB, false, false}}},
    {"wear.hardness.case_depth", {QuantityKind::kLength, {0.01e-3, 1.0, false, false}}},
    {"wear.hardness.exponent", {QuantityKind::kDimensionless, {0.5, 20, false, false}}},
    {"wear.hardness.valid_depth", {QuantityKind::kLength, {0.01e-3, 1.0, false, false}}},
    {"wear.hardness.depths[]", {QuantityKind::kLength, {0, 1.0, false, false}}},
    {"wear.hardness.values[]", {QuantityKind::kHardness, {1 * kPaPerHB, 2000 * kPaPerHB, false, false}}},
    // 1e-3/yr (once a millennium) .. 1e12/yr (30 kHz day and night).
    {"duty.rack_meshes_per_year",
     {QuantityKind::kRate, {1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false}}},
    {"duty.pinion_meshes_per_year",
     {QuantityKind::kRate, {1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false}, true}},
    // 1e9 m/yr is a drive running day and night at 30 m/s; a bare number is m/s.
    {"duty.travel_per_year", {QuantityKind::kSpeed, {1.0 / kSecondsPerYear, 1e9 / kSecondsPerYear, false, false}}},
    {"duty.strokes_per_year", {QuantityKind::kRate, {1e-3 / kSecondsPerYear, 1e12 / kSecondsPerYear, false, false}}},
    {"duty.stroke", {QuantityKind::kLength, {1e-3, 1e5, false, false}}},
    // Dynamics (docs/models/dynamics.md). The moving mass per pinion: a
    // gram-scale instrument slide to ten times a ship lift chamber's share.
    {"dynamics.moving_mass", {QuantityKind::kMass, {1e-3, 1e9, false, false}}},
    // Motor + gearbox reduced to the pinion shaft, J_motor i^2: a small servo
    // (1e-5 kg m^2) without gearbox up to a ship lift's motor through i ~ 200;
    // 0 = none (the pinion's own inertia only).
    {"dynamics.drive_inertia", {QuantityKind::kInertia, {1e-9, 1e7, false, false}, true}},
    // Torsional stiffness from the drive to the pinion; 0 = rigid drive train.
    {"dynamics.drive_stiffness", {QuantityKind::kTorsionalStiffness, {1e-3, 1e12, false, false}, true}},
    // Of critical damping: 0 (undamped) up to, not including, critical.
    {"dynamics.damping_ratio", {QuantityKind::kDimensionless, {0, 1, false, true}}},
    // Sweep speeds are positive (the travel direction of the load): a range
    // that reaches 0 would excite nothing there. 50 m/s as load.speed.
    {"dynamics.speed_range.from", {QuantityKind::kSpeed, {0, 50, true, false}}},
    {"dynamics.speed_range.to", {QuantityKind::kSpeed, {0, 50, true, false}}},
    {"dynamics.speed_range.points", {QuantityKind::kCount, {1, 1000, false, false}}},
    {"reliability.samples", {QuantityKind::kCount, {kSamplesLimit.lo, kSamplesLimit.hi, false, false}}},
    {"reliability.seed", {QuantityKind::kCount, {kSeedLimit.lo, kSeedLimit.hi, false, false}}},
    {"reliability.ks_level", {QuantityKind::kDimensionless, {0.001, 0.5, false, false}}},
    {"reliability.bootstrap_replicates",
     {QuantityKind::kCount, {statistics::kMinBootstrapReplicates, 100000, false, false}}},
    {"reliability.life_table_tolerance", {QuantityKind::kDimensionless, {1e-6, 0.05, false, false}}},
    {"reliability.R[]", {QuantityKind::kDimensionless, {0, 1, true, true}}},
    // 1e-6 yr (32 s) .. a million years.
    {"reliability.times[]", {QuantityKind::kTime, {1e-6 * kSecondsPerYear, 1e6 * kSecondsPerYear, false, false}}},
};

}  // namespace

const NumberRule* find_problem_key_rule(std::string_view schema_path) {
  // Every number a design's Drive reads looks its rule up here: a hash map
  // built once instead of a scan of the whole table by string comparison.
  static const auto by_pattern = [] {
    std::unordered_map<std::string_view, const NumberRule*> map;
    for (const auto& s : kKeySpecs) map.emplace(s.pattern, &s.rule);  // the first of a pattern wins, as in a scan
    return map;
  }();
  const auto it = by_pattern.find(schema_path);
  return it == by_pattern.end() ? nullptr : it->second;
}

ReaderStyle problem_reader_style(std::string schema_path) {
  ReaderStyle style;
  style.schema = find_problem_key_rule;
  style.schema_path = std::move(schema_path);
  return style;
}

SectionReader problem_section(const MarkedNode* node, std::string path, std::string schema_path,
                              const SourceMark& fallback, std::vector<std::string> allowed) {
  return SectionReader(node, std::move(path), fallback, std::move(allowed),
                       problem_reader_style(std::move(schema_path)));
}

std::vector<ListValue> schema_quantity_list(const SectionReader& section, const std::string& key,
                                            const std::string& item_schema_path, std::string_view bare_unit) {
  const NumberRule* rule = find_problem_key_rule(item_schema_path);
  if (rule == nullptr) throw std::logic_error("problem loader: no rule for " + item_schema_path);
  return section.quantity_list(key, rule->kind, rule->range, bare_unit);
}

std::optional<QuantityKind> problem_key_kind(std::string_view key_path) {
  std::string path(key_path);
  // Variant contents follow the same schema.
  if (path.rfind("variants.", 0) == 0) {
    const std::size_t dot = path.find('.', 9);
    if (dot == std::string::npos) return std::nullopt;
    path = path.substr(dot + 1);
  }
  if (path.rfind("materials.", 0) == 0) {
    const std::size_t dot = path.find('.', 10);
    if (dot == std::string::npos) return std::nullopt;
    path = "materials.*" + path.substr(dot);
  }
  // List indices: "faults[3].depth" -> "faults[]", "reliability.times[0]" -> "reliability.times[]".
  for (std::size_t open = path.find('['); open != std::string::npos; open = path.find('[', open + 1)) {
    const std::size_t close = path.find(']', open);
    if (close == std::string::npos) return std::nullopt;
    path.erase(open + 1, close - open - 1);
  }
  // The three hardness maps share one schema; a single value is a constant profile.
  for (const char* member : {"wear.pinion_hardness", "wear.rack_hardness"}) {
    const std::string prefix(member);
    if (path.rfind(prefix, 0) == 0 && (path.size() == prefix.size() || path[prefix.size()] == '.')) {
      path = "wear.hardness" + path.substr(prefix.size());
    }
  }
  if (path == "wear.hardness") return QuantityKind::kHardness;
  const NumberRule* r = find_problem_key_rule(path);
  if (r == nullptr) return std::nullopt;
  return r->kind;
}

}  // namespace rackopt
