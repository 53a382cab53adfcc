// Unit parsing and formatting. Expected SI values are the textbook unit
// definitions (1 mm = 1e-3 m, 1 deg = pi/180 rad, 1 in = 25.4 mm exactly,
// 1 N/mm^2 = 1 MPa), written out by hand here, not taken from the code.
#include "rackopt/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/input_error_expectations.hpp"

namespace rackopt {
namespace {

constexpr double kPi = 3.14159265358979323846;
using K = QuantityKind;

TEST(ParseQuantity, LengthsInEveryUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity("60 mm", K::kLength), 0.060);
  EXPECT_DOUBLE_EQ(parse_quantity("2.4 m", K::kLength), 2.4);
  EXPECT_DOUBLE_EQ(parse_quantity("3 cm", K::kLength), 0.03);
  EXPECT_DOUBLE_EQ(parse_quantity("1 um", K::kLength), 1e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("1 \xC2\xB5m", K::kLength), 1e-6);  // micro sign
  EXPECT_DOUBLE_EQ(parse_quantity("1 \xCE\xBCm", K::kLength), 1e-6);  // greek mu
  EXPECT_DOUBLE_EQ(parse_quantity("1 in", K::kLength), 0.0254);
  EXPECT_DOUBLE_EQ(parse_quantity("60mm", K::kLength), 0.060);       // no space
  EXPECT_DOUBLE_EQ(parse_quantity("  31.831 mm  ", K::kLength), 0.031831);
  EXPECT_DOUBLE_EQ(parse_quantity("-2 mm", K::kLength), -0.002);
  EXPECT_DOUBLE_EQ(parse_quantity("+2 mm", K::kLength), 0.002);
}

TEST(ParseQuantity, BareNumberTakesTheKindDefaultUnit) {
  // The documented defaults: length mm, angle deg, modulus GPa, force N,
  // torque N*m, stiffness N/m, area mm^2, second moment mm^4.
  EXPECT_DOUBLE_EQ(parse_quantity("60", K::kLength), 0.060);
  EXPECT_DOUBLE_EQ(parse_quantity("14", K::kAngle), 14.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("210", K::kModulus), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("50", K::kForce), 50.0);
  EXPECT_DOUBLE_EQ(parse_quantity("453", K::kTorque), 453.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7", K::kStiffness), 7.0);
  EXPECT_DOUBLE_EQ(parse_quantity("3600", K::kArea), 3600e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("2", K::kSecondMoment), 2e-12);
  EXPECT_DOUBLE_EQ(parse_quantity("0.3", K::kDimensionless), 0.3);
  EXPECT_EQ(default_unit(K::kLength), "mm");
  EXPECT_EQ(default_unit(K::kAngle), "deg");
  EXPECT_EQ(default_unit(K::kModulus), "GPa");
  EXPECT_EQ(default_unit(K::kForce), "N");
  EXPECT_EQ(default_unit(K::kTorque), "N*m");
  EXPECT_EQ(default_unit(K::kDimensionless), "");
}

// Each kind's SI unit is one of its own units worth exactly 1 (the record's
// columns name it).
TEST(SiUnit, IsTheKindsUnitOfFactorOne) {
  EXPECT_EQ(si_unit(K::kLength), "m");
  EXPECT_EQ(si_unit(K::kAngle), "rad");
  EXPECT_EQ(si_unit(K::kModulus), "Pa");
  EXPECT_EQ(si_unit(K::kForce), "N");
  EXPECT_EQ(si_unit(K::kTorque), "N*m");
  EXPECT_EQ(si_unit(K::kStiffness), "N/m");
  EXPECT_EQ(si_unit(K::kArea), "m^2");
  EXPECT_EQ(si_unit(K::kSecondMoment), "m^4");
  EXPECT_EQ(si_unit(K::kTime), "s");
  EXPECT_EQ(si_unit(K::kHardness), "Pa");
  EXPECT_EQ(si_unit(K::kRate), "1/s");
  EXPECT_EQ(si_unit(K::kMass), "kg");
  EXPECT_EQ(si_unit(K::kDensity), "kg/m^3");
  EXPECT_EQ(si_unit(K::kSpeed), "m/s");
  EXPECT_EQ(si_unit(K::kPower), "W");
  EXPECT_EQ(si_unit(K::kInertia), "kg*m^2");
  EXPECT_EQ(si_unit(K::kTorsionalStiffness), "N*m/rad");
  EXPECT_EQ(si_unit(K::kDimensionless), "");
  EXPECT_EQ(si_unit(K::kCount), "");
  for (K k : {K::kLength, K::kAngle, K::kModulus, K::kForce, K::kTorque, K::kStiffness, K::kArea, K::kSecondMoment,
              K::kTime, K::kHardness, K::kRate, K::kMass, K::kDensity, K::kSpeed, K::kPower,
              K::kInertia, K::kTorsionalStiffness}) {
    EXPECT_EQ(unit_factor(si_unit(k), k), 1.0) << kind_name(k);
  }
}

TEST(ParseQuantity, OtherKinds) {
  EXPECT_DOUBLE_EQ(parse_quantity("14 deg", K::kAngle), 14.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("14\xC2\xB0", K::kAngle), 14.0 * kPi / 180.0);  // 14°
  EXPECT_DOUBLE_EQ(parse_quantity("0.25 rad", K::kAngle), 0.25);
  EXPECT_DOUBLE_EQ(parse_quantity("210 GPa", K::kModulus), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("2.11e5 MPa", K::kModulus), 211e9);  // the spalling paper's 40Cr
  EXPECT_DOUBLE_EQ(parse_quantity("2.11e5 N/mm^2", K::kModulus), 211e9);
  EXPECT_DOUBLE_EQ(parse_quantity("50 kN", K::kForce), 50e3);
  EXPECT_DOUBLE_EQ(parse_quantity("1.2e3 N", K::kForce), 1200.0);
  EXPECT_DOUBLE_EQ(parse_quantity("200 MN/m", K::kStiffness), 200e6);
  EXPECT_DOUBLE_EQ(parse_quantity("1 N/um", K::kStiffness), 1e6);
  EXPECT_DOUBLE_EQ(parse_quantity("3600 mm^2", K::kArea), 3600e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("3600 mm\xC2\xB2", K::kArea), 3600e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("2.15e6 mm^4", K::kSecondMoment), 2.15e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("1 cm\xE2\x81\xB4", K::kSecondMoment), 1e-8);
}

TEST(ParseQuantity, TorqueSpellings) {
  // All the ways people write kilonewton-metres mean 1e3 N*m.
  for (const char* text : {"453 kN*m", "453 kN.m", "453 kN m", "453 kN\xC2\xB7m", "453 kN * m", "453kN*m"}) {
    EXPECT_DOUBLE_EQ(parse_quantity(text, K::kTorque), 453e3) << text;
  }
  EXPECT_DOUBLE_EQ(parse_quantity("5 N*mm", K::kTorque), 5e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("1 MN m", K::kTorque), 1e6);
}

TEST(ParseCount, WholeNumbersOnly) {
  EXPECT_EQ(parse_count("22"), 22);
  EXPECT_EQ(parse_count(" 17 "), 17);
  EXPECT_EQ(parse_count("-3"), -3);
  EXPECT_THROW(parse_count("22.5"), InputError);
  EXPECT_THROW(parse_count("22 teeth"), InputError);
  EXPECT_THROW(parse_count("1e12"), InputError);  // does not fit an int
  EXPECT_DOUBLE_EQ(parse_quantity("22", K::kCount), 22.0);
}

// Asserts that parsing throws an InputError whose message contains `needle`,
// and that the mark and key given by the caller are carried through.
void expect_error(const std::string& text, K kind, const std::string& needle) {
  SCOPED_TRACE("parsing '" + text + "'");
  test_support::expect_input_error(
      [&] { parse_quantity(text, kind, SourceMark{"f.yaml", 7, 12}, "pinion.pressure_angle"); },
      {.file = "f.yaml",
       .line = 7,
       .column = 12,
       .key = "pinion.pressure_angle",
       .in_message = {needle},
       .in_what = {"f.yaml:7:12: pinion.pressure_angle: "}});
}

TEST(ParseQuantity, ErrorsNameTheProblemAndTheAllowedUnits) {
  // Unknown unit: the allowed ones are listed.
  expect_error("14 kg", K::kAngle, "'kg' is a unit of a mass but an angle is expected; allowed units: deg, rad, mrad");
  expect_error("14 furlong", K::kAngle, "unknown unit 'furlong' for an angle; allowed units: deg, rad, mrad");
  // A unit that exists, but for another kind.
  expect_error("14 mm", K::kAngle, "'mm' is a unit of a length but an angle is expected");
  expect_error("50 GPa", K::kForce, "'GPa' is a unit of a modulus but a force is expected");
  // Trailing garbage after a valid unit.
  expect_error("60 mm x", K::kLength, "unknown unit 'mm x' for a length");
  // Not a number at all.
  expect_error("sixty mm", K::kLength, "is not a number");
  expect_error("", K::kLength, "empty value");
  expect_error("+-5 mm", K::kLength, "is not a number");
  // Non-finite and overflowing numbers never get through.
  expect_error("inf mm", K::kLength, "not a finite number");
  expect_error("nan", K::kLength, "not a finite number");
  expect_error("1e400 mm", K::kLength, "outside the range");
  expect_error("1e308 MN*m", K::kTorque, "overflows");
  // A unit on a dimensionless value.
  expect_error("0.3 mm", K::kDimensionless, "is a unit of a length but a dimensionless number is expected");
  expect_error("0.3 abc", K::kDimensionless, "unexpected text 'abc'");
}

TEST(UnitNames, DefaultFirstAndKindsDisjoint) {
  for (K kind : {K::kLength, K::kAngle, K::kModulus, K::kForce, K::kTorque, K::kStiffness, K::kArea,
                 K::kSecondMoment}) {
    const auto names = unit_names(kind);
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.front(), default_unit(kind));
    for (const auto& n : names) {
      // Each unit parses as its own kind with a factor > 0 ...
      EXPECT_GT(unit_factor(n, kind), 0.0) << n;
      // ... and is rejected by every other kind (no unit is ambiguous).
      for (K other : {K::kLength, K::kAngle, K::kModulus, K::kForce, K::kTorque, K::kStiffness, K::kArea,
                      K::kSecondMoment}) {
        if (other != kind) {
          EXPECT_THROW(unit_factor(n, other), InputError) << n;
        }
      }
    }
  }
  EXPECT_TRUE(unit_names(K::kDimensionless).empty());
}

TEST(Format, PrintsInTheRequestedUnit) {
  EXPECT_EQ(format_length_mm(0.060), "60 mm");
  EXPECT_EQ(format_length_mm(0.031831), "31.831 mm");
  EXPECT_EQ(format_angle_deg(14.0 * kPi / 180.0), "14 deg");
  EXPECT_EQ(format_force_kN(956.5e3), "956.5 kN");
  EXPECT_EQ(format_stiffness_MN_per_m(26.095e6), "26.095 MN/m");
  EXPECT_EQ(format_quantity(453e3, K::kTorque, "kN.m"), "453 kN*m");
  EXPECT_EQ(format_quantity(2.4, K::kLength, "m"), "2.4 m");
  EXPECT_EQ(format_quantity(0.3, K::kDimensionless), "0.3");
  EXPECT_EQ(format_quantity(210e9, K::kModulus), "210 GPa");
  EXPECT_EQ(format_length_mm(1.0 / 3.0, 3), "333 mm");
}

TEST(Format, RoundTripsThroughTheParserInEveryUnit) {
  // Values spanning many decades; 15 significant digits must survive the trip
  // to within 1e-14 relative (the limit of %.15g).
  const double values[] = {1.0, 0.031831, 123456.789, 2.5e-7, 9.87654321e8, -0.0042};
  for (K kind : {K::kLength, K::kAngle, K::kModulus, K::kForce, K::kTorque, K::kStiffness, K::kArea,
                 K::kSecondMoment, K::kDimensionless}) {
    std::vector<std::string> units = unit_names(kind);
    if (units.empty()) units.push_back("");
    for (const auto& unit : units) {
      for (double v : values) {
        const std::string text = format_quantity(v, kind, unit, 15);
        const double back = parse_quantity(text, kind);
        EXPECT_NEAR(back, v, 1e-14 * std::fabs(v)) << text;
      }
    }
  }
}

// ------------------------------------------------------------ time, hardness, rate
// Expected values: 1 yr = 365.25 d (Julian year) = 31 557 600 s, 1 d = 86 400 s;
// 1 HB = 1 kgf/mm^2 = 9.80665 N / 1e-6 m^2 = 9.80665e6 Pa (docs/models/wear.md),
// HV taken equal to HB (documented approximation). Written out by hand here,
// not read from kSecondsPerYear / kPaPerHB.
constexpr double kYear = 365.25 * 86400.0;  // 31 557 600 s
constexpr double kHB = 9.80665e6;

TEST(ParseQuantity, TimesInEveryUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity("60 yr", K::kTime), 60 * 31557600.0);
  EXPECT_DOUBLE_EQ(parse_quantity("60", K::kTime), 60 * 31557600.0);  // bare number: years
  EXPECT_DOUBLE_EQ(parse_quantity("1 year", K::kTime), 31557600.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2 years", K::kTime), 2 * 31557600.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1 d", K::kTime), 86400.0);
  EXPECT_DOUBLE_EQ(parse_quantity("3 days", K::kTime), 3 * 86400.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2 h", K::kTime), 7200.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1 hour", K::kTime), 3600.0);
  EXPECT_DOUBLE_EQ(parse_quantity("5 min", K::kTime), 300.0);
  EXPECT_DOUBLE_EQ(parse_quantity("42 s", K::kTime), 42.0);
  EXPECT_DOUBLE_EQ(parse_quantity("365.25 d", K::kTime), parse_quantity("1 yr", K::kTime));
  EXPECT_EQ(default_unit(K::kTime), "yr");
}

TEST(ParseQuantity, HardnessInEveryUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity("596 HB", K::kHardness), 596 * 9.80665e6);
  EXPECT_DOUBLE_EQ(parse_quantity("596", K::kHardness), 596 * 9.80665e6);  // bare number: HB
  EXPECT_DOUBLE_EQ(parse_quantity("596 HBW", K::kHardness), 596 * 9.80665e6);
  EXPECT_DOUBLE_EQ(parse_quantity("650 HV", K::kHardness), 650 * 9.80665e6);
  EXPECT_DOUBLE_EQ(parse_quantity("5845 MPa", K::kHardness), 5.845e9);
  EXPECT_DOUBLE_EQ(parse_quantity("5.845 GPa", K::kHardness), 5.845e9);
  EXPECT_DOUBLE_EQ(parse_quantity("5845 N/mm^2", K::kHardness), 5.845e9);
  EXPECT_DOUBLE_EQ(parse_quantity("1e9 Pa", K::kHardness), 1e9);
  EXPECT_EQ(default_unit(K::kHardness), "HB");
}

TEST(ParseQuantity, RatesInEveryUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity("4300 1/yr", K::kRate), 4300 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("4300", K::kRate), 4300 / kYear);  // bare number: per year
  EXPECT_DOUBLE_EQ(parse_quantity("4300 /yr", K::kRate), 4300 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("4300/year", K::kRate), 4300 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("4300 per year", K::kRate), 4300 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("12 per day", K::kRate), 12 / 86400.0);
  EXPECT_DOUBLE_EQ(parse_quantity("12 1/d", K::kRate), 12 / 86400.0);
  EXPECT_DOUBLE_EQ(parse_quantity("3 /h", K::kRate), 3 / 3600.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2 1/min", K::kRate), 2 / 60.0);
  EXPECT_DOUBLE_EQ(parse_quantity("5 Hz", K::kRate), 5.0);
  EXPECT_DOUBLE_EQ(parse_quantity("5 1/s", K::kRate), 5.0);
  EXPECT_EQ(default_unit(K::kRate), "1/yr");
}

TEST(ParseQuantity, MassDensitySpeedPower) {
  EXPECT_DOUBLE_EQ(parse_quantity("120 kg", K::kMass), 120.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1.2 t", K::kMass), 1200.0);
  EXPECT_DOUBLE_EQ(parse_quantity("500 g", K::kMass), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity("7850", K::kDensity), 7850.0);  // bare number: kg/m^3
  EXPECT_DOUBLE_EQ(parse_quantity("7.85 g/cm^3", K::kDensity), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7.85 t/m^3", K::kDensity), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.5", K::kSpeed), 0.5);  // bare number: m/s
  EXPECT_DOUBLE_EQ(parse_quantity("90 m/min", K::kSpeed), 1.5);
  EXPECT_DOUBLE_EQ(parse_quantity("36 km/h", K::kSpeed), 10.0);
  EXPECT_DOUBLE_EQ(parse_quantity("250 mm/s", K::kSpeed), 0.25);
  EXPECT_DOUBLE_EQ(parse_quantity("2000 km/yr", K::kSpeed), 2e6 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("2000 m/yr", K::kSpeed), 2e3 / kYear);
  EXPECT_DOUBLE_EQ(parse_quantity("15 kW", K::kPower), 15e3);
  EXPECT_DOUBLE_EQ(parse_quantity("1.5 MW", K::kPower), 1.5e6);
  EXPECT_EQ(format_quantity(1.5, K::kSpeed, "m/min", 4), "90 m/min");
  EXPECT_THROW(parse_quantity("5 kg", K::kSpeed), InputError);
}

TEST(ParseQuantity, BareUnitOverridesTheKindDefault) {
  // A map that states depth_unit: m makes its bare numbers metres; a number
  // with its own unit keeps it.
  EXPECT_DOUBLE_EQ(parse_quantity("2", K::kLength, {}, "", "m"), 2.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2 mm", K::kLength, {}, "", "m"), 2e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("600", K::kHardness, {}, "", "HV"), 600 * kHB);
  EXPECT_DOUBLE_EQ(parse_quantity("600", K::kHardness, {}, "", "MPa"), 600e6);
}

void expect_kind_error(const std::string& text, K kind, const std::string& needle) {
  SCOPED_TRACE("parsing '" + text + "'");
  test_support::expect_input_error(
      [&] { parse_quantity(text, kind, SourceMark{"f.yaml", 3, 5}, "wear.hardness.surface"); },
      {.line = 3, .column = 5, .key = "wear.hardness.surface", .in_message = {needle}});
}

TEST(ParseQuantity, NewKindErrorsListTheAllowedUnits) {
  expect_kind_error("55 HRC", K::kHardness, "unknown unit 'HRC' for a hardness; allowed units: HB, HV, MPa, GPa, Pa");
  expect_kind_error("55 HRC", K::kHardness, "Rockwell");
  expect_kind_error("60 mm", K::kHardness, "'mm' is a unit of a length but a hardness is expected");
  expect_kind_error("60 weeks", K::kTime, "unknown unit 'weeks' for a time; allowed units: yr, d, h, min, s");
  expect_kind_error("60 yr", K::kLength, "'yr' is a unit of a time but a length is expected");
  expect_kind_error("3 HB", K::kModulus, "'HB' is a unit of a hardness but a modulus is expected");
  expect_kind_error("3 /yr", K::kTime, "'/yr' is a unit of a rate");
  expect_kind_error("3 yr", K::kRate, "'yr' is a unit of a time but a rate");
  // MPa belongs to modulus and hardness: a force names the first.
  expect_kind_error("3 MPa", K::kForce, "'MPa' is a unit of a modulus but a force is expected");
}

TEST(ParseQuantity, InertiaAndTorsionalStiffness) {
  EXPECT_DOUBLE_EQ(parse_quantity("12 t", K::kMass), 12e3);
  EXPECT_DOUBLE_EQ(parse_quantity("1500 kg", K::kMass), 1500.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2.4", K::kInertia), 2.4);  // bare number: kg*m^2
  EXPECT_DOUBLE_EQ(parse_quantity("2.4 kg*m^2", K::kInertia), 2.4);
  EXPECT_DOUBLE_EQ(parse_quantity("2.4 kg m^2", K::kInertia), 2.4);
  EXPECT_DOUBLE_EQ(parse_quantity("2.4 kg\xC2\xB7m\xC2\xB2", K::kInertia), 2.4);  // kg·m²
  EXPECT_DOUBLE_EQ(parse_quantity("35 kg*cm^2", K::kInertia), 35e-4);
  EXPECT_DOUBLE_EQ(parse_quantity("3 t*m^2", K::kInertia), 3e3);
  EXPECT_DOUBLE_EQ(parse_quantity("5e6", K::kTorsionalStiffness), 5e6);  // bare number: N*m/rad
  EXPECT_DOUBLE_EQ(parse_quantity("5e6 N*m/rad", K::kTorsionalStiffness), 5e6);
  EXPECT_DOUBLE_EQ(parse_quantity("5e6 N m/rad", K::kTorsionalStiffness), 5e6);
  EXPECT_DOUBLE_EQ(parse_quantity("5000 kN m/rad", K::kTorsionalStiffness), 5e6);
  EXPECT_DOUBLE_EQ(parse_quantity("5 MN*m/rad", K::kTorsionalStiffness), 5e6);
  // Per degree: 1 N*m/deg is 180/pi N*m/rad (a twist of 1 deg is pi/180 rad).
  EXPECT_NEAR(parse_quantity("100 N*m/deg", K::kTorsionalStiffness), 100 * 180 / 3.14159265358979323846, 1e-9);
  EXPECT_EQ(format_quantity(2.4, K::kInertia), "2.4 kg*m^2");
  EXPECT_EQ(format_quantity(5e6, K::kTorsionalStiffness, "MN*m/rad"), "5 MN*m/rad");
  // A linear stiffness or a torque is not a torsional stiffness, and back.
  expect_kind_error("5 N/m", K::kTorsionalStiffness, "'N/m' is a unit of a stiffness but a torsional stiffness is expected");
  expect_kind_error("5 N*m", K::kTorsionalStiffness, "'N*m' is a unit of a torque");
  expect_kind_error("5 N*m/rad", K::kStiffness, "'N*m/rad' is a unit of a torsional stiffness");
  expect_kind_error("5 kg*m", K::kInertia, "unknown unit 'kg*m' for a moment of inertia; allowed units: kg*m^2, kg*cm^2, t*m^2");
}

TEST(UnitNames, NewKindsDefaultFirstAndOnlyPressureUnitsShared) {
  const std::vector<K> all = {K::kLength, K::kAngle, K::kModulus, K::kForce, K::kTorque, K::kStiffness,
                              K::kArea, K::kSecondMoment, K::kTime, K::kHardness, K::kRate};
  for (K kind : {K::kTime, K::kHardness, K::kRate}) {
    const auto names = unit_names(kind);
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.front(), default_unit(kind));
    for (const auto& n : names) {
      EXPECT_GT(unit_factor(n, kind), 0.0) << n;
      for (K other : all) {
        if (other == kind) continue;
        // A hardness is a pressure: its Pa-based units are also moduli, with
        // the same factor. Every other unit belongs to one kind only.
        const bool pressure = kind == K::kHardness && other == K::kModulus && n != "HB" && n != "HV";
        if (pressure) {
          EXPECT_DOUBLE_EQ(unit_factor(n, other), unit_factor(n, kind)) << n;
        } else {
          EXPECT_THROW(unit_factor(n, other), InputError) << n << " as " << kind_name(other);
        }
      }
    }
  }
}

TEST(Format, NewKindsPrintInTheirDefaultUnit) {
  EXPECT_EQ(format_quantity(60 * kYear, K::kTime), "60 yr");
  EXPECT_EQ(format_quantity(86400.0, K::kTime, "d"), "1 d");
  EXPECT_EQ(format_quantity(2 * kYear, K::kTime, "years"), "2 yr");  // spelling -> canonical name
  EXPECT_EQ(format_quantity(596 * kHB, K::kHardness), "596 HB");
  EXPECT_EQ(format_quantity(476.8 * kHB, K::kHardness, "HV"), "476.8 HV");
  EXPECT_EQ(format_quantity(1e9, K::kHardness, "MPa"), "1000 MPa");
  EXPECT_EQ(format_quantity(4300 / kYear, K::kRate), "4300 1/yr");
  EXPECT_EQ(format_quantity(4300 / kYear, K::kRate, "per year"), "4300 1/yr");
  EXPECT_EQ(format_quantity(5.0, K::kRate, "Hz"), "5 Hz");
}

TEST(Format, NewKindsRoundTripThroughTheParserInEveryUnit) {
  const double values[] = {1.0, 0.031831, 123456.789, 2.5e-7, 9.87654321e8, 5845e6};
  for (K kind : {K::kTime, K::kHardness, K::kRate}) {
    for (const auto& unit : unit_names(kind)) {
      for (double v : values) {
        const std::string text = format_quantity(v, kind, unit, 15);
        EXPECT_NE(text.find(unit), std::string::npos) << text;
        EXPECT_NEAR(parse_quantity(text, kind), v, 1e-14 * std::fabs(v)) << text;
      }
    }
  }
}

}  // namespace
}  // namespace rackopt
