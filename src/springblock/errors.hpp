#pragma once
// The project's error types, in one header that depends on nothing else of the project, so that
// any layer (parsers, scene, integrators, drivers) can throw them without pulling in the layer
// that happens to parse units.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace sb {

// Thrown for any invalid user input. `field` names the option or scene-file key,
// `message` says what was wrong and the allowed range. The CLI maps it to exit code 2.
struct InputError : std::runtime_error {
  std::string field;
  InputError(std::string field_, const std::string& message)
      : std::runtime_error(field_ + ": " + message), field(std::move(field_)) {}
};

// Throw InputError(field, message) unless ok: the one-line checks of input validation.
inline void require(bool ok, const std::string& field, const std::string& message) {
  if (!ok) throw InputError(field, message);
}

// A number as an error message prints it (printf's %g): short, and the same everywhere.
inline std::string printed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

}  // namespace sb
