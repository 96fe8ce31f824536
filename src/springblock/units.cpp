#include "springblock/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace sb {
namespace {

struct UnitEntry {
  std::string_view symbol;
  Dimension dim;
  double to_si;  // multiply the number by this to get SI
};

// One flat table for every dimension. Keeping all units together (rather than one table per
// dimension) is what lets us tell "unknown unit" apart from "unit of the wrong dimension":
// a user who types 5cm for a time deserves to hear that cm is a length, not that it is unknown.
// Symbols are case-sensitive on purpose: mPa and MPa differ by nine orders of magnitude.
// The UTF-8 micro sign (U+00B5) and Greek mu (U+03BC) are aliases of "u" because both show up
// when values are copied from papers; they are not listed in accepted_units() to keep --help ASCII.
constexpr std::array kUnits = {
    // Length
    UnitEntry{"m", Dimension::Length, 1.0},
    UnitEntry{"cm", Dimension::Length, 1e-2},
    UnitEntry{"mm", Dimension::Length, 1e-3},
    UnitEntry{"um", Dimension::Length, 1e-6},
    UnitEntry{"\xC2\xB5m", Dimension::Length, 1e-6},
    UnitEntry{"\xCE\xBCm", Dimension::Length, 1e-6},
    UnitEntry{"nm", Dimension::Length, 1e-9},
    // Time
    UnitEntry{"s", Dimension::Time, 1.0},
    UnitEntry{"ms", Dimension::Time, 1e-3},
    UnitEntry{"us", Dimension::Time, 1e-6},
    UnitEntry{"\xC2\xB5s", Dimension::Time, 1e-6},
    UnitEntry{"\xCE\xBCs", Dimension::Time, 1e-6},
    // Rate (inverse time)
    UnitEntry{"/s", Dimension::Rate, 1.0},
    UnitEntry{"/ms", Dimension::Rate, 1e3},
    UnitEntry{"/us", Dimension::Rate, 1e6},
    UnitEntry{"1/s", Dimension::Rate, 1.0},
    UnitEntry{"1/ms", Dimension::Rate, 1e3},
    UnitEntry{"1/us", Dimension::Rate, 1e6},
    UnitEntry{"s^-1", Dimension::Rate, 1.0},
    UnitEntry{"ms^-1", Dimension::Rate, 1e3},
    UnitEntry{"us^-1", Dimension::Rate, 1e6},
    UnitEntry{"Hz", Dimension::Rate, 1.0},
    UnitEntry{"kHz", Dimension::Rate, 1e3},
    // Pressure
    UnitEntry{"Pa", Dimension::Pressure, 1.0},
    UnitEntry{"kPa", Dimension::Pressure, 1e3},
    UnitEntry{"MPa", Dimension::Pressure, 1e6},
    UnitEntry{"GPa", Dimension::Pressure, 1e9},
    // Density
    UnitEntry{"kg/m3", Dimension::Density, 1.0},
    UnitEntry{"kg/m^3", Dimension::Density, 1.0},
    UnitEntry{"g/cm3", Dimension::Density, 1e3},
    UnitEntry{"g/cm^3", Dimension::Density, 1e3},
    // Velocity
    UnitEntry{"m/s", Dimension::Velocity, 1.0},
    UnitEntry{"cm/s", Dimension::Velocity, 1e-2},
    UnitEntry{"mm/s", Dimension::Velocity, 1e-3},
    UnitEntry{"um/s", Dimension::Velocity, 1e-6},
    UnitEntry{"\xC2\xB5m/s", Dimension::Velocity, 1e-6},
    UnitEntry{"\xCE\xBCm/s", Dimension::Velocity, 1e-6},
};

const UnitEntry* find_unit(std::string_view symbol) {
  for (const auto& u : kUnits)
    if (u.symbol == symbol) return &u;
  return nullptr;
}

// "a length", "a time", ... so error messages read as English sentences.
std::string describe(Dimension dim) {
  switch (dim) {
    case Dimension::Length: return "a length";
    case Dimension::Time: return "a time";
    case Dimension::Rate: return "a rate";
    case Dimension::Pressure: return "a pressure";
    case Dimension::Density: return "a density";
    case Dimension::Velocity: return "a velocity";
    case Dimension::Dimensionless: return "a dimensionless number";
  }
  return "an unknown quantity";
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

[[noreturn]] void fail(const std::string& field, const std::string& what, Dimension dim) {
  throw InputError(field, what + "; accepted units: " + accepted_units(dim));
}

}  // namespace

std::string accepted_units(Dimension dim) {
  if (dim == Dimension::Dimensionless) return "none (a bare number)";
  std::string out;
  for (const auto& u : kUnits) {
    if (u.dim != dim) continue;
    // Keep --help plain ASCII; the micro-sign aliases still parse.
    if (static_cast<unsigned char>(u.symbol.front()) >= 0x80) continue;
    if (!out.empty()) out += ", ";
    out += u.symbol;
  }
  out += " (a bare number is SI)";
  return out;
}

double parse_quantity(std::string_view text, Dimension dim, const std::string& field) {
  const std::string quoted = std::string("'").append(text).append("'");  // not "'" + string: GCC 12 -Wrestrict
  const std::string_view s = trim(text);
  if (s.empty()) fail(field, "empty value, expected " + describe(dim), dim);

  // std::from_chars is locale-independent (a German locale must not turn "7,2" into 7.2 or
  // reject "7.2") and reports exactly how much it consumed, which is what splits number and unit.
  // It rejects a leading '+', which users do type, so skip one explicitly.
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (*first == '+' && first + 1 != last && *(first + 1) != '-') ++first;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range)
    fail(field, quoted + " is out of the representable range", dim);
  if (ec != std::errc()) fail(field, quoted + " does not start with a number", dim);
  // from_chars accepts "nan" and "inf"; neither is a physical value.
  if (!std::isfinite(value)) fail(field, quoted + " is not a finite number", dim);

  const std::string_view unit = trim(std::string_view(ptr, static_cast<std::size_t>(last - ptr)));
  if (unit.empty()) return value;  // bare numbers are SI by convention

  const UnitEntry* u = find_unit(unit);
  if (u == nullptr) {
    // Distinguish "5 cm x" (a known unit followed by junk) from a plain unknown symbol, because
    // the fix the user needs is different.
    const auto sp = unit.find_first_of(" \t");
    if (sp != std::string_view::npos && find_unit(unit.substr(0, sp)) != nullptr)
      fail(field, "trailing characters after the unit in " + quoted, dim);
    if (dim == Dimension::Dimensionless)
      fail(field, quoted + " has unknown unit '" + std::string(unit) + "', expected a bare number",
           dim);
    fail(field,
         quoted + " has unknown unit '" + std::string(unit) + "', expected " + describe(dim), dim);
  }
  if (u->dim != dim)
    fail(field, quoted + " is " + describe(u->dim) + ", expected " + describe(dim), dim);

  const double si = value * u->to_si;
  if (!std::isfinite(si)) fail(field, quoted + " overflows when converted to SI", dim);
  return si;
}

}  // namespace sb
