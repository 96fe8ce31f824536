// Bad input raises springblock.InputError, a ValueError whose message names the field and its
// allowed range exactly as the command line's does ("invalid N: N = 0 is outside [1, 1000000]"),
// and whose `field` attribute is the field's name.
#include "springblock/errors.hpp"

#include "bindings.hpp"

namespace sb::python {

void bind_errors(py::module_& m) {
  // Never destroyed: its reference must outlive the interpreter's own teardown.
  static auto& type = *new py::exception<sb::InputError>(m, "InputError", PyExc_ValueError);
  type.doc() = "Invalid scene input; a ValueError. `field` names the scene field.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const sb::InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(type)(std::string("invalid ") + e.what());
      error.attr("field") = e.field;
      PyErr_SetObject(type.ptr(), error.ptr());
    }
  });
}

}  // namespace sb::python
