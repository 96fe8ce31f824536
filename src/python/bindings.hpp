#pragma once
// The parts of the Python module, one file each, registered by module.cpp.
#include <nlohmann/json_fwd.hpp>
#include <pybind11/pybind11.h>

#include "springblock/ensemble.hpp"
#include "springblock/scene.hpp"

namespace sb::python {

namespace py = pybind11;

// What springblock.run returns: the ensemble and the scene it ran (for the results JSON and the
// reasons a statistic was not measured).
struct Result {
  sb::Scene scene;
  sb::EnsembleResult ensemble;
};

void bind_errors(py::module_& m);  // errors.cpp: sb::InputError -> springblock.InputError (a ValueError)
void bind_scene(py::module_& m);   // scene.cpp: springblock.Scene, springblock.scene_fields
void bind_result(py::module_& m);  // result.cpp: springblock.Result, Statistic, Series, Stress
void bind_run(py::module_& m);     // run.cpp: springblock.run, springblock.run_many
void bind_theory(py::module_& m);  // theory.cpp: the submodule springblock.theory
void bind_sweep(py::module_& m);   // sweep.cpp: springblock._core.sweep (springblock.sweep wraps it)
void bind_design(py::module_& m);  // design.cpp: springblock._core.design (springblock.design wraps it)

// `base` with `fields` (field name -> value, as Scene() takes them) overlaid and validated
// (scene.cpp). Throws sb::InputError naming the field.
sb::Scene with_fields(sb::Scene base, const py::dict& fields);

// A scene's pattern field as a scene file would hold it (pattern_value.cpp): a string as it is,
// the blocks of a one-dimensional array, list or tuple of 0/1 or booleans as "mask:0110...".
// Throws sb::InputError("pattern") for anything else.
nlohmann::json pattern_value(const py::handle& value);
// materials.cpp: per-block fields from Python. set_materials_arrays fills the scene's columns from a
// dict of field name -> 1-D array (numpy or list; contact may be bool), source "python arrays";
// segments_json turns a list of dicts into the scene-file form of "segments".
void set_materials_arrays(sb::Scene& scene, const py::dict& arrays);
nlohmann::json segments_json(const py::handle& segments);

// A JSON value as the Python object json.loads would give: the library's JSON (scenes, results)
// reaches Python without a second serialiser.
py::object to_python(const nlohmann::json& j);

}  // namespace sb::python
