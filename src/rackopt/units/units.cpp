#include "rackopt/units/units.hpp"

#include "rackopt/core/drive.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace rackopt {
namespace {

struct UnitDef {
  const char* name;  // canonical spelling (after normalize_unit)
  QuantityKind kind;
  double si_per_unit;
};

// First entry of each kind is its default unit (a bare number means it).
constexpr UnitDef kUnits[] = {
    {"mm", QuantityKind::kLength, 1e-3},
    {"m", QuantityKind::kLength, 1.0},
    {"cm", QuantityKind::kLength, 1e-2},
    {"um", QuantityKind::kLength, 1e-6},
    {"in", QuantityKind::kLength, 0.0254},
    {"deg", QuantityKind::kAngle, 3.14159265358979323846 / 180.0},
    {"rad", QuantityKind::kAngle, 1.0},
    {"mrad", QuantityKind::kAngle, 1e-3},
    {"GPa", QuantityKind::kModulus, 1e9},
    {"MPa", QuantityKind::kModulus, 1e6},
    {"kPa", QuantityKind::kModulus, 1e3},
    {"Pa", QuantityKind::kModulus, 1.0},
    {"N/mm^2", QuantityKind::kModulus, 1e6},
    {"N/m^2", QuantityKind::kModulus, 1.0},
    {"N", QuantityKind::kForce, 1.0},
    {"kN", QuantityKind::kForce, 1e3},
    {"MN", QuantityKind::kForce, 1e6},
    {"N*m", QuantityKind::kTorque, 1.0},
    {"N*mm", QuantityKind::kTorque, 1e-3},
    {"kN*m", QuantityKind::kTorque, 1e3},
    {"MN*m", QuantityKind::kTorque, 1e6},
    {"N/m", QuantityKind::kStiffness, 1.0},
    {"N/mm", QuantityKind::kStiffness, 1e3},
    {"N/um", QuantityKind::kStiffness, 1e6},
    {"kN/mm", QuantityKind::kStiffness, 1e6},
    {"MN/m", QuantityKind::kStiffness, 1e6},
    {"GN/m", QuantityKind::kStiffness, 1e9},
    {"mm^2", QuantityKind::kArea, 1e-6},
    {"cm^2", QuantityKind::kArea, 1e-4},
    {"m^2", QuantityKind::kArea, 1.0},
    {"mm^4", QuantityKind::kSecondMoment, 1e-12},
    {"cm^4", QuantityKind::kSecondMoment, 1e-8},
    {"m^4", QuantityKind::kSecondMoment, 1.0},
    {"yr", QuantityKind::kTime, kSecondsPerYear},
    {"d", QuantityKind::kTime, 86400.0},
    {"h", QuantityKind::kTime, 3600.0},
    {"min", QuantityKind::kTime, 60.0},
    {"s", QuantityKind::kTime, 1.0},
    // Brinell and Vickers numbers are kgf per mm^2 of indentation area:
    // 1 kgf/mm^2 = 9.80665 N / 1e-6 m^2. HV = HB is an approximation (units.hpp).
    {"HB", QuantityKind::kHardness, kPaPerHB},
    {"HV", QuantityKind::kHardness, kPaPerHB},
    {"MPa", QuantityKind::kHardness, 1e6},
    {"GPa", QuantityKind::kHardness, 1e9},
    {"Pa", QuantityKind::kHardness, 1.0},
    {"N/mm^2", QuantityKind::kHardness, 1e6},
    {"1/yr", QuantityKind::kRate, 1.0 / kSecondsPerYear},
    {"1/d", QuantityKind::kRate, 1.0 / 86400.0},
    {"1/h", QuantityKind::kRate, 1.0 / 3600.0},
    {"1/min", QuantityKind::kRate, 1.0 / 60.0},
    {"1/s", QuantityKind::kRate, 1.0},
    {"Hz", QuantityKind::kRate, 1.0},
    {"kg", QuantityKind::kMass, 1.0},
    {"t", QuantityKind::kMass, 1e3},
    {"g", QuantityKind::kMass, 1e-3},
    {"kg/m^3", QuantityKind::kDensity, 1.0},
    {"g/cm^3", QuantityKind::kDensity, 1e3},
    {"t/m^3", QuantityKind::kDensity, 1e3},
    {"m/s", QuantityKind::kSpeed, 1.0},
    {"mm/s", QuantityKind::kSpeed, 1e-3},
    {"m/min", QuantityKind::kSpeed, 1.0 / 60.0},
    {"km/h", QuantityKind::kSpeed, 1.0 / 3.6},
    {"m/yr", QuantityKind::kSpeed, 1.0 / kSecondsPerYear},
    {"km/yr", QuantityKind::kSpeed, 1e3 / kSecondsPerYear},
    {"W", QuantityKind::kPower, 1.0},
    {"kW", QuantityKind::kPower, 1e3},
    {"MW", QuantityKind::kPower, 1e6},
    // Motor catalogues give rotor inertias in kg*m^2, small servo motors in
    // kg*cm^2; a ship lift's drum or counterweight sheave reaches t*m^2.
    {"kg*m^2", QuantityKind::kInertia, 1.0},
    {"kg*cm^2", QuantityKind::kInertia, 1e-4},
    {"t*m^2", QuantityKind::kInertia, 1e3},
    // Torque per radian of twist (a shaft, coupling or gearbox); N*m/deg is
    // how some gearbox catalogues state it (Nm/arcmin is not accepted).
    {"N*m/rad", QuantityKind::kTorsionalStiffness, 1.0},
    {"kN*m/rad", QuantityKind::kTorsionalStiffness, 1e3},
    {"MN*m/rad", QuantityKind::kTorsionalStiffness, 1e6},
    {"N*m/deg", QuantityKind::kTorsionalStiffness, 180.0 / 3.14159265358979323846},
};

// Word spellings of the canonical names above, after normalize_unit.
struct UnitAlias {
  const char* spelling;
  const char* canonical;
};
constexpr UnitAlias kAliases[] = {
    {"year", "yr"}, {"years", "yr"}, {"day", "d"}, {"days", "d"}, {"hour", "h"}, {"hours", "h"}, {"HBW", "HB"},
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

// Maps the accepted spellings onto the canonical names of kUnits:
// "kN.m", "kN m", "kN·m", "kN * m" -> "kN*m"; "µm", "μm" -> "um"; "°" -> "deg";
// "mm²" -> "mm^2"; "mm⁴" -> "mm^4". Other text is kept so that the error
// message can quote it.
std::string normalize_unit(std::string_view unit) {
  std::string out;
  bool pending_space = false;
  auto emit = [&](std::string_view piece) {
    if (pending_space && !out.empty() && out.back() != '*' && out.back() != '/' &&
        piece.front() != '*' && piece.front() != '/') {
      out += '*';
    }
    pending_space = false;
    out += piece;
  };
  for (std::size_t i = 0; i < unit.size();) {
    std::string_view rest = unit.substr(i);
    if (is_blank(rest.front())) {
      pending_space = true;
      ++i;
    } else if (starts_with(rest, "\xC2\xB7") || starts_with(rest, "\xE2\x8B\x85")) {  // · or ⋅
      emit("*");
      i += starts_with(rest, "\xC2\xB7") ? 2 : 3;
    } else if (rest.front() == '.') {
      emit("*");
      ++i;
    } else if (starts_with(rest, "\xC2\xB5") || starts_with(rest, "\xCE\xBC")) {  // µ (micro) or μ (mu)
      emit("u");
      i += 2;
    } else if (starts_with(rest, "\xC2\xB0")) {  // °
      emit("deg");
      i += 2;
    } else if (starts_with(rest, "\xC2\xB2")) {  // ²
      emit("^2");
      i += 2;
    } else if (starts_with(rest, "\xE2\x81\xB4")) {  // ⁴
      emit("^4");
      i += 3;
    } else {
      emit(rest.substr(0, 1));
      ++i;
    }
  }
  return out;
}

// normalize_unit plus the word spellings: "years" -> "yr", and a rate
// written "/yr", "per year", "1/year" -> "1/yr".
std::string canonical_unit(std::string_view unit) {
  std::string u = normalize_unit(unit);
  std::string prefix;
  if (starts_with(u, "per*")) {
    prefix = "1/";
    u = u.substr(4);
  } else if (starts_with(u, "1/")) {
    prefix = "1/";
    u = u.substr(2);
  } else if (starts_with(u, "/")) {
    prefix = "1/";
    u = u.substr(1);
  }
  for (const auto& a : kAliases) {
    if (u == a.spelling) u = a.canonical;
  }
  return prefix + u;
}

std::string join_units(QuantityKind kind) {
  std::string out;
  for (const auto& name : unit_names(kind)) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

std::string allowed_text(QuantityKind kind) {
  if (kind == QuantityKind::kDimensionless) return "a plain number without unit";
  if (kind == QuantityKind::kCount) return "a whole number without unit";
  return "allowed units: " + join_units(kind) + " (a bare number means " +
         std::string(default_unit(kind)) + ")";
}

std::string example(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kDimensionless: return "'0.3'";
    case QuantityKind::kCount: return "'22'";
    case QuantityKind::kLength: return "'60 mm'";
    case QuantityKind::kAngle: return "'20 deg'";
    case QuantityKind::kModulus: return "'210 GPa'";
    case QuantityKind::kForce: return "'50 kN'";
    case QuantityKind::kTorque: return "'453 kN*m'";
    case QuantityKind::kStiffness: return "'200 MN/m'";
    case QuantityKind::kArea: return "'3600 mm^2'";
    case QuantityKind::kSecondMoment: return "'2.15e6 mm^4'";
    case QuantityKind::kTime: return "'60 yr'";
    case QuantityKind::kHardness: return "'596 HB'";
    case QuantityKind::kRate: return "'3000 1/yr'";
    case QuantityKind::kMass: return "'120 kg'";
    case QuantityKind::kDensity: return "'7850 kg/m^3'";
    case QuantityKind::kSpeed: return "'0.5 m/s'";
    case QuantityKind::kPower: return "'15 kW'";
    case QuantityKind::kInertia: return "'2.4 kg*m^2'";
    case QuantityKind::kTorsionalStiffness: return "'5 MN*m/rad'";
  }
  return "";
}

std::string article(QuantityKind kind) {
  const std::string_view n = kind_name(kind);
  const bool vowel = !n.empty() && std::string_view("aeiou").find(n.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(n);
}

// Splits "<number><rest>"; returns false if no number starts the text.
struct NumberSplit {
  double value = 0.0;
  std::string_view rest;
};

NumberSplit split_number(std::string_view text, QuantityKind kind, const SourceMark& where,
                         const std::string& key_path) {
  std::string_view s = trim(text);
  if (s.empty()) {
    throw InputError(where, key_path, "empty value; expected " + article(kind) + ", e.g. " + example(kind));
  }
  std::string_view digits = s;
  bool negative = false;
  if (digits.front() == '+' || digits.front() == '-') {
    negative = digits.front() == '-';
    digits.remove_prefix(1);
    if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) digits = {};  // "+-5"
  }
  // from_chars accepts "inf"/"nan" spelled out: the isfinite check below rejects them.
  double value = 0.0;
  const char* first = digits.data();
  const char* last = digits.data() + digits.size();
  const auto result = std::from_chars(first, last, value, std::chars_format::general);
  if (digits.empty() || result.ec == std::errc::invalid_argument || result.ptr == first) {
    throw InputError(where, key_path,
                     "'" + std::string(s) + "' is not a number; expected " + article(kind) + ", e.g. " +
                         example(kind));
  }
  if (result.ec == std::errc::result_out_of_range) {
    throw InputError(where, key_path,
                     "'" + std::string(s) + "' is outside the range of a double precision number");
  }
  if (!std::isfinite(value)) {
    throw InputError(where, key_path, "'" + std::string(s) + "' is not a finite number");
  }
  NumberSplit out;
  out.value = negative ? -value : value;
  out.rest = trim(std::string_view(result.ptr, static_cast<std::size_t>(last - result.ptr)));
  return out;
}

}  // namespace

std::string_view kind_name(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kDimensionless: return "dimensionless number";
    case QuantityKind::kCount: return "count";
    case QuantityKind::kLength: return "length";
    case QuantityKind::kAngle: return "angle";
    case QuantityKind::kModulus: return "modulus";
    case QuantityKind::kForce: return "force";
    case QuantityKind::kTorque: return "torque";
    case QuantityKind::kStiffness: return "stiffness";
    case QuantityKind::kArea: return "area";
    case QuantityKind::kSecondMoment: return "second moment of area";
    case QuantityKind::kTime: return "time";
    case QuantityKind::kHardness: return "hardness";
    case QuantityKind::kRate: return "rate (events per time)";
    case QuantityKind::kMass: return "mass";
    case QuantityKind::kDensity: return "density";
    case QuantityKind::kSpeed: return "speed (length per time)";
    case QuantityKind::kPower: return "power";
    case QuantityKind::kInertia: return "moment of inertia";
    case QuantityKind::kTorsionalStiffness: return "torsional stiffness";
  }
  return "quantity";
}

std::string_view default_unit(QuantityKind kind) {
  for (const auto& u : kUnits) {
    if (u.kind == kind) return u.name;
  }
  return "";
}

std::string unit_suffix(const std::string& unit) {
  if (unit.empty() || unit == "-") return "";
  std::string u = unit;
  if (u.rfind("1/", 0) == 0) u = u.substr(1);
  std::string out;
  for (char c : u) {
    if (c == '/') {
      out += out.empty() ? "per_" : "_per_";
    } else if (c == '*' || c == '.' || c == ' ') {
      out += '_';
    } else if (c == '^') {
      continue;
    } else {
      out += c;
    }
  }
  return out;
}

std::string with_suffix(const std::string& name, const std::string& unit) {
  const std::string s = unit_suffix(unit);
  return s.empty() ? name : name + "_" + s;
}

std::string_view si_unit(QuantityKind kind) {
  for (const auto& u : kUnits) {
    if (u.kind == kind && u.si_per_unit == 1.0) return u.name;
  }
  return "";
}

std::vector<std::string> unit_names(QuantityKind kind) {
  std::vector<std::string> out;
  for (const auto& u : kUnits) {
    if (u.kind == kind) out.emplace_back(u.name);
  }
  return out;
}

double unit_factor(std::string_view unit, QuantityKind kind, const SourceMark& where,
                   const std::string& key_path) {
  const std::string canonical = canonical_unit(trim(unit));
  if (canonical.empty()) {
    if (kind == QuantityKind::kDimensionless || kind == QuantityKind::kCount) return 1.0;
    return unit_factor(default_unit(kind), kind, where, key_path);
  }
  const UnitDef* other_kind = nullptr;
  for (const auto& u : kUnits) {
    if (canonical != u.name) continue;
    if (u.kind == kind) return u.si_per_unit;
    // MPa is a modulus and a hardness: name the first (the commoner) kind.
    if (other_kind == nullptr) other_kind = &u;
  }
  const std::string quoted = "'" + std::string(trim(unit)) + "'";
  if (other_kind != nullptr) {
    throw InputError(where, key_path,
                     quoted + " is a unit of " + article(other_kind->kind) + " but " + article(kind) +
                         " is expected; " + allowed_text(kind));
  }
  if (kind == QuantityKind::kDimensionless || kind == QuantityKind::kCount) {
    throw InputError(where, key_path,
                     "unexpected text " + quoted + " after the number; expected " + allowed_text(kind));
  }
  std::string hint;
  if (kind == QuantityKind::kHardness && starts_with(canonical, "HR")) {
    // Rockwell numbers are depths, not loads per area: no factor maps them to Pa.
    hint = " (a Rockwell number is not proportional to a pressure: convert it to HV or HB with ISO 18265 first)";
  }
  throw InputError(where, key_path,
                   "unknown unit " + quoted + " for " + article(kind) + "; " + allowed_text(kind) + hint);
}

double parse_quantity(std::string_view text, QuantityKind kind, const SourceMark& where,
                      const std::string& key_path, std::string_view bare_unit) {
  if (kind == QuantityKind::kCount) return parse_count(text, where, key_path);
  const NumberSplit split = split_number(text, kind, where, key_path);
  const std::string_view unit = split.rest.empty() ? bare_unit : split.rest;
  const double si = split.value * unit_factor(unit, kind, where, key_path);
  if (!std::isfinite(si)) {
    throw InputError(where, key_path, "'" + std::string(trim(text)) + "' overflows when converted to SI units");
  }
  return si;
}

double parse_whole_number(std::string_view text, const SourceMark& where, const std::string& key_path) {
  const NumberSplit split = split_number(text, QuantityKind::kCount, where, key_path);
  unit_factor(split.rest, QuantityKind::kCount, where, key_path);  // throws on any trailing text
  if (split.value != std::floor(split.value)) {
    throw InputError(where, key_path,
                     "'" + std::string(trim(text)) + "' is not a whole number; expected " +
                         allowed_text(QuantityKind::kCount));
  }
  return split.value;
}

int parse_count(std::string_view text, const SourceMark& where, const std::string& key_path) {
  constexpr double kLimit = 2e9;  // inside int's +-2147483647
  const double v = parse_whole_number(text, where, key_path);
  if (std::fabs(v) > kLimit) {
    throw InputError(where, key_path,
                     "'" + std::string(trim(text)) + "' is out of range; allowed: -2000000000 .. 2000000000");
  }
  return static_cast<int>(v);
}

std::string format_number(double value, int significant_digits) {
  if (significant_digits < 1) significant_digits = 1;
  if (significant_digits > 17) significant_digits = 17;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant_digits, value);
  return buffer;
}

std::string format_quantity(double value_si, QuantityKind kind, std::string_view unit, int significant_digits) {
  if (kind == QuantityKind::kDimensionless || kind == QuantityKind::kCount) {
    return format_number(value_si, significant_digits);
  }
  const std::string wanted = canonical_unit(unit.empty() ? default_unit(kind) : unit);
  // An unknown output unit is a programming error: print in the kind's SI
  // unit (factor 1) rather than mislabel the number.
  const UnitDef* chosen = nullptr;
  for (const auto& u : kUnits) {
    if (u.kind == kind && wanted == u.name) chosen = &u;
  }
  if (chosen == nullptr) {
    for (const auto& u : kUnits) {
      if (u.kind == kind && u.si_per_unit == 1.0 && chosen == nullptr) chosen = &u;
    }
  }
  const double factor = chosen->si_per_unit;
  const std::string canonical = chosen->name;
  const double in_unit = value_si / factor;
  if (std::isfinite(value_si) && value_si != 0 && !std::isnormal(in_unit)) {
    // 1e308 m is 1e311 mm, beyond a double, and 5e-324 Pa is 5e-333 GPa,
    // below one: divide in long double (x86-64 and AArch64 Linux: exponent
    // range to 1e+-4932) rather than print "inf mm" or "0 GPa".
    if (significant_digits < 1) significant_digits = 1;
    if (significant_digits > 17) significant_digits = 17;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*Lg", significant_digits,
                  static_cast<long double>(value_si) / static_cast<long double>(factor));
    return std::string(buffer) + " " + canonical;
  }
  return format_number(in_unit, significant_digits) + " " + canonical;
}

std::string format_length_mm(double metres, int significant_digits) {
  return format_quantity(metres, QuantityKind::kLength, "mm", significant_digits);
}
std::string format_angle_deg(double radians, int significant_digits) {
  return format_quantity(radians, QuantityKind::kAngle, "deg", significant_digits);
}
std::string format_force_kN(double newtons, int significant_digits) {
  return format_quantity(newtons, QuantityKind::kForce, "kN", significant_digits);
}
std::string format_stiffness_MN_per_m(double n_per_m, int significant_digits) {
  return format_quantity(n_per_m, QuantityKind::kStiffness, "MN/m", significant_digits);
}

}  // namespace rackopt
