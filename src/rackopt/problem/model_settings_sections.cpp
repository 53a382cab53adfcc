#include "rackopt/problem/drive_sections.hpp"

#include "rackopt/problem/problem_key_schema.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {

void read_effects(const SectionReader& top, Drive& drive) {
  const SectionReader fx =
      problem_section(top.get("effects"), "effects", "effects", top.mark(),
                      {"pinion_tooth", "root_segment", "fillet_foundation", "fillet_calibration", "rack_tooth",
                       "rack_foundation", "hertz", "pair_coupling", "rack_span", "supported_rack", "couple_term",
                       "body_axial", "body_shear", "interference_limit", "spalling", "dynamics"});
  Effects& e = drive.effects;
  const Effects defaults;
  e.pinion_tooth = fx.flag("pinion_tooth", defaults.pinion_tooth);
  e.root_segment = fx.flag("root_segment", defaults.root_segment);
  e.fillet_foundation = fx.flag("fillet_foundation", defaults.fillet_foundation);
  e.fillet_calibration = fx.flag("fillet_calibration", defaults.fillet_calibration);
  e.rack_tooth = fx.flag("rack_tooth", defaults.rack_tooth);
  e.rack_foundation = fx.flag("rack_foundation", defaults.rack_foundation);
  e.pair_coupling = fx.flag("pair_coupling", defaults.pair_coupling);
  e.supported_rack = fx.flag("supported_rack", defaults.supported_rack);
  {
    const std::string h = fx.choice("hertz", {"off", "linear", "weber_banaschek"})
                              .value_or(defaults.hertz == HertzModel::kOff      ? "off"
                                        : defaults.hertz == HertzModel::kLinear ? "linear"
                                                                                : "weber_banaschek");
    e.hertz = h == "off" ? HertzModel::kOff : h == "linear" ? HertzModel::kLinear : HertzModel::kWeberBanaschek;
  }
  {
    const std::string s = fx.choice("rack_span", {"off", "rigid", "coupled", "per_pair"})
                              .value_or(defaults.rack_span == RackSpanModel::kRigid     ? "rigid"
                                        : defaults.rack_span == RackSpanModel::kCoupled ? "coupled"
                                                                                        : "per_pair");
    e.rack_span = (s == "off" || s == "rigid") ? RackSpanModel::kRigid
                  : s == "coupled"             ? RackSpanModel::kCoupled
                                               : RackSpanModel::kPerPair;
  }
  e.couple_term = fx.flag("couple_term", defaults.couple_term);
  e.body_axial = fx.flag("body_axial", defaults.body_axial);
  e.body_shear = fx.flag("body_shear", defaults.body_shear);
  e.interference_limit = fx.flag("interference_limit", defaults.interference_limit);
  e.spalling = fx.flag("spalling", defaults.spalling);
  e.dynamics = fx.flag("dynamics", defaults.dynamics);  // read_dynamics checks what it needs
  if (!e.any_compliance()) {
    throw InputError(top.key_mark("effects"), "effects",
                     "every compliance is switched off (pinion_tooth, fillet_foundation, rack_tooth, hertz: off, "
                     "rack_span: rigid): the mesh would be rigid, with infinite stiffness and no load sharing; "
                     "keep at least one on");
  }
}

void read_numerics(const SectionReader& top, Drive& drive) {
  const SectionReader num = problem_section(top.get("numerics"), "numerics", "numerics", top.mark(),
                                            {"quadrature_order", "adaptive_quadrature", "positions_per_period"});
  const Numerics nd;
  drive.numerics.quadrature_order = num.whole("quadrature_order", nd.quadrature_order);
  drive.numerics.adaptive_quadrature = num.flag("adaptive_quadrature", nd.adaptive_quadrature);
  drive.numerics.positions_per_period = num.whole("positions_per_period", nd.positions_per_period);
}

}  // namespace rackopt
