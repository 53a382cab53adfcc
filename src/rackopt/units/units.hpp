// Physical quantities written as text ("60 mm", "14 deg", "453 kN*m") and
// back. This is the only place in rackopt where unit strings are parsed.
//
// Every value is returned in SI (m, rad, Pa, N, N*m, N/m, m^2, m^4). A bare
// number means the default unit of its kind, ONE per kind so that a reader
// never has to remember a per-key convention:
//   length mm, angle deg, modulus GPa, force N, torque N*m, stiffness N/m,
//   area mm^2, second moment mm^4, time yr, hardness HB, rate 1/yr,
//   mass kg, inertia kg*m^2, torsional stiffness N*m/rad;
//   dimensionless and count take no unit.
// Time and rate are SI inside (s, 1/s) like everything else; years are only
// the default for writing, because lives and duty are thought of in years.
// docs/yaml.md lists the accepted unit names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rackopt/core/error.hpp"

namespace rackopt {

enum class QuantityKind {
  kDimensionless,  // plain number, no unit allowed ("0.3")
  kCount,          // whole number, no unit ("22")
  kLength,         // m, cm, mm, um (also µm, μm), in
  kAngle,          // deg (also °), rad, mrad
  kModulus,        // Pa, kPa, MPa, GPa, N/mm^2, N/m^2 (pressure, Young's modulus)
  kForce,          // N, kN, MN
  kTorque,         // N*m, N*mm, kN*m, MN*m (also written kN.m, kN m, kN·m)
  kStiffness,      // N/m, N/mm, N/um, kN/mm, MN/m, GN/m
  kArea,           // m^2, cm^2, mm^2 (also mm²)
  kSecondMoment,   // m^4, cm^4, mm^4 (also mm⁴)
  kTime,           // yr (also year, years; 1 yr = kSecondsPerYear, Julian), d (day, days), h (hour, hours), min, s
  kHardness,       // HB (also HBW), HV, MPa, GPa, Pa, N/mm^2; SI is Pa via 1 HB = kPaPerHB.
                   // HV is taken as 1 HV = 1 HB (both kgf/mm^2 of indentation area): an
                   // approximation, steels differ by ~5 % and more above 450 HB (ISO 18265).
  kRate,           // events per time: 1/yr (also /yr, per year), 1/d, 1/h, 1/min, 1/s (also Hz); SI 1/s
  kMass,           // kg, t, g
  kDensity,        // kg/m^3, g/cm^3, t/m^3
  kSpeed,          // m/s, mm/s, m/min, km/h, m/yr, km/yr (a travel per year is a speed); SI m/s
  kPower,          // W, kW, MW
  kInertia,        // mass moment of inertia: kg*m^2 (also kg m^2, kg·m²), kg*cm^2, t*m^2
  kTorsionalStiffness,  // N*m/rad (also N m/rad), kN*m/rad, MN*m/rad, N*m/deg
};

// "length", "angle", ... with an article-free noun used in messages.
std::string_view kind_name(QuantityKind kind);

// Unit assumed for a bare number ("" for dimensionless and count).
std::string_view default_unit(QuantityKind kind);

// The SI unit values of `kind` are in: "m", "rad", "Pa", "N*m", "1/s", ...;
// "" for dimensionless and count.
std::string_view si_unit(QuantityKind kind);
// A unit as a column-name suffix: "N/m" -> "N_per_m", "1/m" -> "per_m",
// "m^2" -> "m2", "N*m" -> "N_m", "-" and "" -> "".
std::string unit_suffix(const std::string& unit);

// `name` with unit_suffix(unit) appended after "_", `name` alone when the
// suffix is empty: "min_stiffness" + "N/m" -> "min_stiffness_N_per_m".
std::string with_suffix(const std::string& name, const std::string& unit);

// Canonical names of the units accepted for a kind, in a stable order
// (first = default unit). Empty for dimensionless and count.
std::vector<std::string> unit_names(QuantityKind kind);

// SI value of one `unit` of `kind` (e.g. ("mm", kLength) -> 1e-3). The unit
// may be written in any accepted spelling ("kN.m", "µm", "°").
// Throws InputError(where, key_path, ...) when the unit is unknown or belongs
// to another kind; the message lists the units allowed for `kind`.
double unit_factor(std::string_view unit, QuantityKind kind, const SourceMark& where = {},
                   const std::string& key_path = {});

// Parses "<number> [unit]" into SI. Leading/trailing blanks are ignored; the
// space between number and unit is optional ("60mm"). Throws InputError with
// `where` and `key_path` for: no number, trailing garbage / unknown unit
// (listing the allowed units), a unit of another kind ("14 kg" for an angle,
// "14 mm" for an angle), a non-finite or overflowing number, a fractional
// count. Never returns NaN or inf.
// `bare_unit`, when not empty, is the unit of a bare number instead of the
// kind's default (a problem map that states `depth_unit: mm` for its list).
double parse_quantity(std::string_view text, QuantityKind kind, const SourceMark& where = {},
                      const std::string& key_path = {}, std::string_view bare_unit = {});

// Parses a whole number without unit ("22", "-3", "+4", "1e12") of any
// magnitude, returned as a double so that the caller can check it against
// its own range before converting ("2147483648 is out of range; allowed:
// 5 <= teeth <= 1000" rather than an overflow). Same errors as
// parse_quantity; a fraction is "not a whole number".
double parse_whole_number(std::string_view text, const SourceMark& where = {}, const std::string& key_path = {});

// parse_whole_number limited to what an int holds safely: |n| <= 2e9 (else
// "out of range", naming that range).
int parse_count(std::string_view text, const SourceMark& where = {}, const std::string& key_path = {});

// "<value> <unit>" with `significant_digits` significant digits (%g style,
// no trailing zeros), the SI value converted into `unit` (default: the
// kind's default unit). parse_quantity(format_quantity(v, k), k) == v up to
// the printed precision. Non-finite values print as "nan"/"inf" (the formatter
// is for output; it never throws for a value); a finite value whose converted
// number leaves the range of a double prints exactly ("1e+311 mm" for 1e308 m,
// "5e-333 GPa" for 5e-324 Pa), never as inf or 0.
std::string format_quantity(double value_si, QuantityKind kind, std::string_view unit = {},
                            int significant_digits = 6);

// Shorthands used by the CLI for the common kinds.
std::string format_length_mm(double metres, int significant_digits = 6);      // "60 mm"
std::string format_angle_deg(double radians, int significant_digits = 6);     // "14 deg"
std::string format_force_kN(double newtons, int significant_digits = 6);      // "50 kN"
std::string format_stiffness_MN_per_m(double n_per_m, int significant_digits = 6);  // "26.1 MN/m"

// A plain number with `significant_digits` digits (%g), shared by the above.
std::string format_number(double value, int significant_digits = 6);

}  // namespace rackopt
