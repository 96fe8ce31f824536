// Unit parsing at the input boundary: every accepted spelling maps to the right SI value,
// and every kind of bad input is rejected with an InputError that names the field.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <utility>
#include <string>

#include "springblock/units.hpp"

namespace {

using sb::Dimension;
using sb::InputError;
using sb::parse_quantity;

struct Case {
  const char* text;
  Dimension dim;
  double si;
};

// Relative comparison: the conversions multiply by powers of ten, which are not exact in
// binary, so a few ulps of difference from the literal are legitimate.
void expect_close(double got, double want, const char* text) {
  EXPECT_NEAR(got, want, 1e-12 * std::abs(want) + 1e-300) << "input: " << text;
}

TEST(Units, AcceptedSpellingsConvertToSI) {
  const Case cases[] = {
      // the examples from the header and the brief
      {"7.2cm", Dimension::Length, 0.072},
      {"7.2 cm", Dimension::Length, 0.072},
      {"1e-4ms", Dimension::Time, 1e-7},
      {"10/ms", Dimension::Rate, 1e4},
      {"10 ms^-1", Dimension::Rate, 1e4},
      {"5MPa", Dimension::Pressure, 5e6},
      {"1.2g/cm3", Dimension::Density, 1200.0},
      {"1.2 g/cm^3", Dimension::Density, 1200.0},
      {"0.05cm/s", Dimension::Velocity, 5e-4},
      {"1s", Dimension::Time, 1.0},
      {"100us", Dimension::Time, 1e-4},
      {"2mm", Dimension::Length, 2e-3},
      // every unit at least once
      {"3m", Dimension::Length, 3.0},
      {"3um", Dimension::Length, 3e-6},
      {"3nm", Dimension::Length, 3e-9},
      {"3ms", Dimension::Time, 3e-3},
      {"3/s", Dimension::Rate, 3.0},
      {"3/us", Dimension::Rate, 3e6},
      {"3 1/s", Dimension::Rate, 3.0},
      {"3 1/ms", Dimension::Rate, 3e3},
      {"3s^-1", Dimension::Rate, 3.0},
      {"3Hz", Dimension::Rate, 3.0},
      {"3kHz", Dimension::Rate, 3e3},
      {"3Pa", Dimension::Pressure, 3.0},
      {"3kPa", Dimension::Pressure, 3e3},
      {"3GPa", Dimension::Pressure, 3e9},
      {"3kg/m3", Dimension::Density, 3.0},
      {"3kg/m^3", Dimension::Density, 3.0},
      {"3m/s", Dimension::Velocity, 3.0},
      {"3mm/s", Dimension::Velocity, 3e-3},
      {"3um/s", Dimension::Velocity, 3e-6},
      // bare numbers are SI, for every dimension
      {"0.072", Dimension::Length, 0.072},
      {"2e6", Dimension::Pressure, 2e6},
      {"0.5", Dimension::Dimensionless, 0.5},
      {"12", Dimension::Dimensionless, 12.0},
      // signs and surrounding whitespace; negative values pass (range checks live elsewhere)
      {"  7.2cm  ", Dimension::Length, 0.072},
      {"+4ms", Dimension::Time, 4e-3},
      {"-1.5", Dimension::Dimensionless, -1.5},
      {"-2um", Dimension::Length, -2e-6},
  };
  for (const auto& c : cases) expect_close(parse_quantity(c.text, c.dim, "x"), c.si, c.text);
}

TEST(Units, MicroSignAliases) {
  expect_close(parse_quantity("5\xC2\xB5s", Dimension::Time, "t"), 5e-6, "micro sign");
  expect_close(parse_quantity("5\xCE\xBCm", Dimension::Length, "l"), 5e-6, "greek mu");
}

TEST(Units, RoundTripThroughEveryListedUnit) {
  // For each dimension, every unit printed by accepted_units() must parse back, and
  // "x unit" must equal x times "1 unit" — i.e. the help text and the parser agree.
  const Dimension dims[] = {Dimension::Length,   Dimension::Time,    Dimension::Rate,
                            Dimension::Pressure, Dimension::Density, Dimension::Velocity};
  for (auto d : dims) {
    std::string list = sb::accepted_units(d);
    list = list.substr(0, list.find(" ("));  // drop the "(a bare number is SI)" note
    std::size_t start = 0;
    int n = 0;
    while (start < list.size()) {
      auto end = list.find(", ", start);
      if (end == std::string::npos) end = list.size();
      const std::string unit = list.substr(start, end - start);
      start = end + 2;
      ++n;
      const double one = parse_quantity("1 " + unit, d, "f");
      const double x = parse_quantity("2.5 " + unit, d, "f");
      EXPECT_GT(one, 0.0) << unit;
      expect_close(x, 2.5 * one, unit.c_str());
    }
    EXPECT_GE(n, 2) << sb::accepted_units(d);
  }
}

TEST(Units, LocaleDoesNotChangeParsing) {
  // A comma-decimal locale must neither break "7.2" nor make "7,2" valid.
  const char* old = std::setlocale(LC_NUMERIC, nullptr);
  const std::string saved = old ? old : "C";
  if (std::setlocale(LC_NUMERIC, "de_DE.UTF-8") == nullptr) std::setlocale(LC_NUMERIC, "C");
  expect_close(parse_quantity("7.2cm", Dimension::Length, "L"), 0.072, "7.2cm");
  EXPECT_THROW(parse_quantity("7,2cm", Dimension::Length, "L"), InputError);
  std::setlocale(LC_NUMERIC, saved.c_str());
}

// Runs `text` through the parser, requires an InputError for `field`, and returns its message.
std::string error_of(const std::string& text, Dimension dim, const std::string& field = "Lx") {
  try {
    parse_quantity(text, dim, field);
  } catch (const InputError& e) {
    EXPECT_EQ(e.field, field) << text;
    return e.what();
  }
  ADD_FAILURE() << "no InputError for '" << text << "'";
  return {};
}

bool contains(const std::string& s, const std::string& sub) {
  return s.find(sub) != std::string::npos;
}

TEST(Units, EmptyTextIsRejected) {
  for (const char* t : {"", "   "}) {
    const auto msg = error_of(t, Dimension::Length);
    EXPECT_TRUE(contains(msg, "empty")) << msg;
    EXPECT_TRUE(contains(msg, sb::accepted_units(Dimension::Length))) << msg;
  }
}

TEST(Units, NonFiniteIsRejected) {
  for (const char* t : {"nan", "NaN", "inf", "-inf", "infinity", "nan cm", "inf ms", "1e999"}) {
    const auto msg = error_of(t, Dimension::Time, "dt");
    EXPECT_TRUE(contains(msg, std::string("'") + t + "'")) << msg;
  }
  // Finite input that overflows on conversion is as useless as inf.
  error_of("1e300GPa", Dimension::Pressure, "E");
}

TEST(Units, NotANumberIsRejected) {
  for (const char* t : {"cm", "abc", "--5", "++5", ".", "e5", "7,2"})
    error_of(t, Dimension::Length);
}

TEST(Units, TrailingGarbageIsRejected) {
  const std::pair<const char*, Dimension> cases[] = {
      {"7.2cm x", Dimension::Length},  {"7.2 cm cm", Dimension::Length},
      {"7.2cmx", Dimension::Length},   {"5 5", Dimension::Length},
      {"1s.", Dimension::Time},        {"10/ms/", Dimension::Rate},
      {"3 kHz z", Dimension::Rate},    {"0.05cm/s!", Dimension::Velocity},
  };
  for (const auto& [t, d] : cases) {
    const auto msg = error_of(t, d);
    EXPECT_TRUE(contains(msg, std::string("'") + t + "'")) << msg;
  }
}

TEST(Units, UnknownUnitIsRejectedWithAcceptedList) {
  const auto msg = error_of("5ft", Dimension::Length, "Lx");
  EXPECT_TRUE(contains(msg, "'5ft'")) << msg;
  EXPECT_TRUE(contains(msg, "unknown unit")) << msg;
  EXPECT_TRUE(contains(msg, sb::accepted_units(Dimension::Length))) << msg;
  EXPECT_TRUE(contains(msg, "Lx")) << msg;
  // Unit symbols are case-sensitive: mPa is not MPa.
  error_of("5mpa", Dimension::Pressure, "E");
  error_of("5CM", Dimension::Length);
  error_of("5 hz", Dimension::Rate);
}

TEST(Units, WrongDimensionNamesBoth) {
  auto msg = error_of("5cm", Dimension::Time, "dt");
  EXPECT_TRUE(contains(msg, "'5cm' is a length, expected a time")) << msg;
  EXPECT_TRUE(contains(msg, sb::accepted_units(Dimension::Time))) << msg;

  msg = error_of("10ms", Dimension::Rate, "k");
  EXPECT_TRUE(contains(msg, "is a time, expected a rate")) << msg;
  msg = error_of("5MPa", Dimension::Density, "rho");
  EXPECT_TRUE(contains(msg, "is a pressure, expected a density")) << msg;
  msg = error_of("1 m/s", Dimension::Length, "L");
  EXPECT_TRUE(contains(msg, "is a velocity, expected a length")) << msg;
  msg = error_of("1g/cm3", Dimension::Velocity, "v");
  EXPECT_TRUE(contains(msg, "is a density, expected a velocity")) << msg;
  msg = error_of("3 Hz", Dimension::Time, "t");
  EXPECT_TRUE(contains(msg, "is a rate, expected a time")) << msg;
}

TEST(Units, DimensionlessTakesBareNumbersOnly) {
  for (const char* t : {"0.5cm", "0.5 s", "1Hz", "0.5%"}) error_of(t, Dimension::Dimensionless, "mu");
}

TEST(Units, AcceptedUnitsListsTheBriefUnits) {
  const auto has = [](Dimension d, const char* u) {
    const auto l = sb::accepted_units(d);
    // Match whole list items so "m" is not "found" inside "cm".
    return contains(", " + l.substr(0, l.find(" (")) + ",", std::string(", ") + u + ",");
  };
  for (auto u : {"m", "cm", "mm", "um", "nm"}) EXPECT_TRUE(has(Dimension::Length, u)) << u;
  for (auto u : {"s", "ms", "us"}) EXPECT_TRUE(has(Dimension::Time, u)) << u;
  for (auto u : {"/s", "/ms", "/us", "1/s", "1/ms", "s^-1", "ms^-1", "Hz", "kHz"})
    EXPECT_TRUE(has(Dimension::Rate, u)) << u;
  for (auto u : {"Pa", "kPa", "MPa", "GPa"}) EXPECT_TRUE(has(Dimension::Pressure, u)) << u;
  for (auto u : {"kg/m3", "g/cm3", "g/cm^3"}) EXPECT_TRUE(has(Dimension::Density, u)) << u;
  for (auto u : {"m/s", "cm/s", "mm/s", "um/s"}) EXPECT_TRUE(has(Dimension::Velocity, u)) << u;
  EXPECT_FALSE(has(Dimension::Length, "s"));
}

}  // namespace
