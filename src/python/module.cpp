// springblock._core, the compiled part of the package springblock: the library's scenes,
// ensembles, results, theory, sweeps and design queries. The package (src/python/springblock/)
// re-exports it and adds what is plain Python: the results of studies as tables.
#include <nlohmann/json.hpp>

#include "bindings.hpp"

namespace sb::python {

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace sb::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "The compiled part of the package springblock (import springblock, not this module).";
  m.attr("__version__") = SPRINGBLOCK_PYTHON_VERSION;
  // Defined under the package's name, so classes, signatures and the submodule read
  // springblock.Scene and springblock.theory: where users, pickle and the documentation find them.
  m.attr("__name__") = "springblock";
  sb::python::bind_errors(m);
  sb::python::bind_scene(m);
  sb::python::bind_result(m);
  sb::python::bind_run(m);
  sb::python::bind_theory(m);
  sb::python::bind_sweep(m);
  sb::python::bind_design(m);
  m.attr("__name__") = "springblock._core";
}
