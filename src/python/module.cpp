// The Python module `springblock`: the library's scenes, ensembles, results and theory.
#include <nlohmann/json.hpp>

#include "bindings.hpp"

namespace sb::python {

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace sb::python

PYBIND11_MODULE(springblock, m) {
  m.doc() =
      "1-D spring-block friction model (Costagliola, Bosia & Pugno, PRE 2016).\n\n"
      "Scene(**fields) configures a simulation with the command line's field names, defaults and\n"
      "units; run(scene) runs its repetitions and returns a Result; theory holds the closed forms.";
  m.attr("__version__") = SPRINGBLOCK_PYTHON_VERSION;
  sb::python::bind_errors(m);
  sb::python::bind_scene(m);
  sb::python::bind_result(m);
  sb::python::bind_run(m);
  sb::python::bind_theory(m);
}
