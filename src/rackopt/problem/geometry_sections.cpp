#include "rackopt/problem/drive_sections.hpp"

#include <cmath>
#include <map>
#include <vector>

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kPi = 3.14159265358979323846;

Material find_material(const std::map<std::string, Material>& materials, const SectionReader& block,
                       const std::string& key) {
  const auto name = block.scalar(key, "a material name");
  const std::string wanted = name ? name->first : "steel";
  const auto it = materials.find(wanted);
  if (it != materials.end()) return it->second;
  std::vector<std::string> names;
  for (const auto& [n, m] : materials) names.push_back(n);
  throw InputError(name ? name->second : block.mark(), block.child_path(key),
                   "unknown material '" + wanted + "'; defined: " + join(names) + " (add it under materials: {" +
                       wanted + ": {E: ..., nu: ...}})");
}

}  // namespace

RackSection rectangular_rack_section(double width, double height) {
  RackSection s;
  s.area = width * height;
  s.second_moment = width * height * height * height / 12.0;
  s.shear_area = s.area / 1.2;
  s.neutral_axis_depth = 0.5 * height;
  return s;
}

std::map<std::string, Material> read_materials(const SectionReader& top) {
  std::map<std::string, Material> materials;
  materials["steel"] = Material{"steel", 210e9, 0.3};
  const SectionReader block =
      problem_section(top.get("materials"), "materials", "materials", top.key_mark("materials"), {});
  if (block.node() != nullptr) {
    for (const auto& e : block.node()->entries) {
      const SectionReader m = problem_section(&e.value, "materials." + e.key, "materials.*", e.key_mark,
                                              {"E", "nu", "allowable_bending", "allowable_contact", "density"});
      if (m.node() == nullptr) {
        throw InputError(e.key_mark, m.path(), "a material needs E (modulus) and nu (Poisson's ratio)");
      }
      Material material;
      material.name = e.key;
      material.youngs_modulus = m.number("E", std::nullopt);
      material.poisson_ratio = m.number("nu", std::nullopt);
      // A bare number is GPa (the modulus kind): "430" would be 430 GPa.
      const std::string hint = " (a permissible stress; a bare number means GPa: write e.g. 430 MPa)";
      material.allowable_bending = m.number("allowable_bending", 0.0, hint);
      material.allowable_contact = m.number("allowable_contact", 0.0, hint);
      material.density = m.number("density", material.density);
      materials[e.key] = material;
    }
  }
  return materials;
}

void read_pinion(const SectionReader& top, const std::map<std::string, Material>& materials, Drive& drive) {
  const SectionReader p =
      problem_section(top.get("pinion"), "pinion", "pinion", top.mark(),
                      {"teeth", "module", "pressure_angle", "face_width", "profile_shift", "addendum", "dedendum",
                       "tip_radius", "bore_radius", "material", "tip_relief", "root_relief"});
  PinionSpec& pin = drive.pinion;
  pin.teeth = p.whole("teeth", std::nullopt);
  pin.module = p.number("module", std::nullopt);
  pin.pressure_angle = p.number("pressure_angle", 20 * kDeg);
  pin.face_width = p.number("face_width", std::nullopt);
  pin.profile_shift = p.number("profile_shift", 0.0);
  pin.addendum_coef = p.number("addendum", 1.0);
  pin.dedendum_coef = p.number("dedendum", 1.25);
  pin.tip_radius_coef = p.number("tip_radius", 0.38);
  const double root_radius = pin.module * (0.5 * pin.teeth - pin.dedendum_coef + pin.profile_shift);
  if (p.has("bore_radius")) {
    pin.bore_radius = p.number("bore_radius", std::nullopt);
    if (root_radius > 0) {
      p.check_range(
          "bore_radius", pin.bore_radius, {0, root_radius, true, true},
          " (the root radius r_f = m (z/2 - dedendum + profile_shift) = " + format_length_mm(root_radius) + ")");
    }
  } else {
    // Half the root radius: h_f = r_f/r_int = 2, inside the range Sainsot's
    // fillet-foundation fit was made for (about 1.4..7, docs/models/tooth.md).
    pin.bore_radius = root_radius > 0 ? 0.5 * root_radius : 0.0;
  }
  pin.material = find_material(materials, p, "material");
  pin.tip_relief = read_relief(p, "tip_relief", "pinion.tip_relief", pin.module);
  pin.root_relief = read_relief(p, "root_relief", "pinion.root_relief", pin.module);
}

void read_rack(const SectionReader& top, const std::map<std::string, Material>& materials, Drive& drive) {
  const PinionSpec& pin = drive.pinion;
  const SectionReader r =
      problem_section(top.get("rack"), "rack", "rack", top.mark(),
                      {"addendum", "dedendum", "face_width", "body_height", "body_width", "section", "span", "supports",
                       "tooth_offset", "root_radius", "material", "tip_relief", "root_relief"});
  RackSpec& rack = drive.rack;
  rack.addendum_coef = r.number("addendum", 1.0);
  rack.dedendum_coef = r.number("dedendum", 1.25);
  rack.face_width = r.number("face_width", pin.face_width);
  const bool has_height = r.has("body_height");
  const bool has_section = r.has("section");
  if (has_height && has_section) {
    throw InputError(r.key_mark("section"), "rack.section",
                     "give either rack.body_height (rectangular body) or rack.section (explicit properties), not both");
  }
  if (!has_height && !has_section) {
    r.missing("body_height",
              "the rack body: rack.body_height (rectangular body, e.g. 75 mm) or rack.section "
              "{area, second_moment, shear_area, neutral_axis_depth}");
  }
  if (has_height) {
    rack.body_height = r.number("body_height", std::nullopt);
    rack.body_width = r.number("body_width", rack.face_width);
    rack.section = rectangular_rack_section(rack.body_width, rack.body_height);
  } else {
    if (r.has("body_width")) {
      throw InputError(r.key_mark("body_width"), "rack.body_width",
                       "rack.body_width belongs to a rectangular body (rack.body_height); with rack.section give "
                       "the section properties only");
    }
    const SectionReader s = problem_section(r.get("section"), "rack.section", "rack.section", r.key_mark("section"),
                                            {"area", "second_moment", "shear_area", "neutral_axis_depth"});
    rack.body_height = 0.0;
    rack.body_width = 0.0;
    rack.section.area = s.number("area", std::nullopt);
    rack.section.second_moment = s.number("second_moment", std::nullopt);
    rack.section.shear_area = s.number("shear_area", rack.section.area / 1.2);
    s.check_range("shear_area", rack.section.shear_area, {0, rack.section.area, true, false},
                  " (the shear area kappa*A cannot exceed the area A = " +
                      format_quantity(rack.section.area, QuantityKind::kArea) + ")");
    rack.section.neutral_axis_depth = s.number("neutral_axis_depth", std::nullopt);
  }
  rack.span = r.number("span", std::nullopt);
  rack.supports = r.choice("supports", {"pin-pin", "pin-roller"}).value_or("pin-pin") == "pin-roller"
                      ? Supports::kPinRoller
                      : Supports::kPinPin;
  const double pitch = kPi * pin.module;
  rack.tooth_offset = r.number("tooth_offset", 0.5 * pitch);
  r.check_range("tooth_offset", rack.tooth_offset, {0, rack.span, false, false}, " (within the span rack.span)");
  rack.root_radius = r.number("root_radius", 0.0, " (0 = the pinion cutter tip radius)");
  rack.material = find_material(materials, r, "material");
  rack.tip_relief = read_relief(r, "tip_relief", "rack.tip_relief", pin.module);
  rack.root_relief = read_relief(r, "root_relief", "rack.root_relief", pin.module);
}

void read_mounting(const SectionReader& top, Drive& drive) {
  const PinionSpec& pin = drive.pinion;
  const SectionReader mount = problem_section(top.get("mounting"), "mounting", "mounting", top.mark(), {"clearance"});
  const std::string clearance_why = " (0 = zero backlash, the teeth touch on both flanks; up to 1 x module)";
  drive.mounting.clearance = mount.number("clearance", 0.0, clearance_why);
  // 0 is the zero-backlash mesh: the pinion was generated by the rack's own
  // profile, so the teeth touch on both flanks (backlash 2 clearance tan a0).
  // Closer, the flanks would overlap: a negative clearance is impossible
  // (build_mesh_geometry refuses it too), not a deeper mesh. A module apart
  // leaves a contact ratio far below 1 for any practical tooth.
  mount.check_range("clearance", drive.mounting.clearance, {0, pin.module, false, false}, clearance_why);
}

}  // namespace rackopt
