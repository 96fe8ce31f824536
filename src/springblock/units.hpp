#pragma once
// Parsing of physical quantities given on the command line or in scene files.
// Everything inside the simulator is SI; units exist only at this boundary.
#include <stdexcept>
#include <string>
#include <string_view>

#include "springblock/errors.hpp"  // InputError, thrown by the parsers below

namespace sb {

// Physical dimension a quantity is expected to have.
enum class Dimension { Length, Time, Rate, Pressure, Density, Velocity, Dimensionless };

// Parse "7.2cm", "1e-4ms", "10/ms", "5MPa", "1.2g/cm3", "0.05cm/s", or a bare number (SI).
// Whitespace between number and unit is allowed. Throws InputError naming `field` when the
// text is not a finite number, has an unknown unit, or a unit of the wrong dimension.
double parse_quantity(std::string_view text, Dimension dim, const std::string& field);

// Human-readable list of the units accepted for a dimension, used in --help and errors.
std::string accepted_units(Dimension dim);

}  // namespace sb
