// A scene's pattern as Python gives it: the command line's text, or the blocks themselves.
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "springblock/errors.hpp"

namespace sb::python {
namespace {

constexpr const char* kForms =
    "a pattern is a string (as on the command line) or the blocks themselves: a one-dimensional numpy array, "
    "list or tuple of 0/1 or False/True, 1 = pawl (contact), one entry per block";

// An entry as 0 or 1: numbers and booleans of any kind (numpy's too) that equal 0 or 1, nothing
// else (a string "1" is a spelling, not a number: refused rather than guessed).
char block_digit(const py::handle& item, std::size_t index) {
  double x = -1;
  if (!py::isinstance<py::str>(item) && !py::isinstance<py::bytes>(item)) {
    try {
      x = py::float_(py::reinterpret_borrow<py::object>(item)).cast<double>();
    } catch (const py::error_already_set&) {
      x = -1;
    }
  }
  if (x == 0) return '0';
  if (x == 1) return '1';
  throw sb::InputError("pattern", "mask entry at index " + std::to_string(index) + " is " +
                                      py::repr(item).cast<std::string>() + "; " + kForms);
}

}  // namespace

nlohmann::json pattern_value(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "ndim") && py::int_(value.attr("ndim")).cast<long>() != 1)
    throw sb::InputError("pattern", "a mask array must have one dimension, got ndim = " +
                                        py::str(value.attr("ndim")).cast<std::string>() + "; " + kForms);
  if (!py::isinstance<py::iterable>(value) || py::isinstance<py::bytes>(value) || py::isinstance<py::dict>(value))
    throw sb::InputError("pattern", "got " + py::repr(value).cast<std::string>() + "; " + kForms);
  // The text a mask has on the command line, so it is checked (and recorded) exactly as there.
  std::string text = "mask:";
  std::size_t index = 0;
  for (auto item : value) text += block_digit(item, index++);
  return text;
}

}  // namespace sb::python
