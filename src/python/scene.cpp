// springblock.Scene: a validated scene built from field names and values exactly as a scene file
// is (sb::apply_scene_json over the library's field table, then sb::validate), so Python accepts,
// converts and refuses every field as the command line does, with the same defaults and messages.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "springblock/errors.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/scene_state.hpp"
#include "springblock/surface_mask.hpp"

namespace sb::python {
namespace {

// `value` as a scene file would hold it, for apply_scene_json to turn into the command line's text
// as it does for a scene file (a whole float such as 30.0 becomes "30", so a count such as N
// accepts it). Integers go as text: apply_scene_json reads JSON integers as signed 64-bit, and a
// seed may be any unsigned 64-bit value. Anything else becomes null, which that check refuses
// naming the field.
nlohmann::json field_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (PyIndex_Check(value.ptr())) return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  if (py::isinstance<py::float_>(value) || py::hasattr(value, "__float__"))
    return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  return nullptr;
}

}  // namespace

sb::Scene with_fields(sb::Scene scene, const py::dict& fields) {
  nlohmann::json j = nlohmann::json::object();
  py::dict arrays;
  for (auto [key, value] : fields) {
    if (!py::isinstance<py::str>(key))
      throw sb::InputError(py::repr(key).cast<std::string>(), "a field name must be a string");
    const auto name = key.cast<std::string>();
    if (name == "materials" && py::isinstance<py::dict>(value)) arrays = py::reinterpret_borrow<py::dict>(value);
    else if (name == "materials" && py::hasattr(value, "__fspath__"))  // a pathlib.Path
      j[name] = py::module_::import("os").attr("fspath")(value).cast<std::string>();
    else if (name == "segments") j[name] = segments_json(value);
    else if (name == "pattern") j[name] = pattern_value(value);
    else j[name] = field_text(value);
  }
  sb::apply_scene_json(scene, j);
  if (!arrays.empty()) set_materials_arrays(scene, arrays);
  sb::validate(scene);
  return scene;
}

namespace {

sb::Scene make_scene(const py::object& fields, const py::kwargs& more) {
  py::dict all;
  if (!fields.is_none()) {
    if (!py::isinstance<py::dict>(fields))
      throw sb::InputError("scene", "Scene() takes a dict of fields and/or keyword arguments");
    all.attr("update")(fields);
  }
  all.attr("update")(more);  // keywords override the dict, as options override a scene file
  return with_fields(sb::Scene{}, all);
}

std::string scene_repr(const sb::Scene& s) {
  char text[256];
  std::snprintf(text, sizeof text, "springblock.Scene(N=%d, length=%gm, pattern='%s', method='%s', reps=%d, seed=%llu)",
                s.geometry.N, s.geometry.L_x_m, sb::pattern_label(s.pattern).c_str(), sb::method_name(s.run.method).c_str(),
                s.reps, static_cast<unsigned long long>(s.seed));
  return text;
}

std::string scene_state_text(const sb::Scene& s) { return sb::scene_state(s).dump(); }

sb::Scene scene_from_state_text(const std::string& text) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  return sb::scene_from_state(j);  // refuses a discarded (malformed) value, naming `state`
}

py::list field_table() {
  py::list rows;
  for (const auto& f : sb::scene_fields())
    rows.append(py::dict(py::arg("key") = f.key, py::arg("help") = f.help, py::arg("example") = f.example));
  return rows;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<sb::Scene>(m, "Scene",
                        "A validated scene. Fields are the command line's options with '_' (N, length, pattern,\n"
                        "mu_s, reps, seed, ...; see scene_fields()), given as keyword arguments and/or a dict,\n"
                        "with the same defaults and unit strings ('7.2cm', '10/ms'); plain numbers are SI.\n"
                        "pattern may also be the blocks themselves: a 1-D numpy array, list or tuple of 0/1 or\n"
                        "bool (1 = pawl), N entries, taken as the mask 'mask:0110...'.\n"
                        "Bad input raises InputError (a ValueError) naming the field and its allowed range.")
      .def(py::init(&make_scene), py::arg("fields") = py::none())
      .def("replace", [](const sb::Scene& s, const py::kwargs& kw) { return with_fields(s, kw); },
           "A copy with the given fields changed (validated again).")
      .def("to_dict", [](const sb::Scene& s) { return to_python(nlohmann::json(s)); },
           "The scene as every results file records it (SI units, derived parameters, t0, duration).")
      .def_property_readonly("N", [](const sb::Scene& s) { return s.geometry.N; })
      .def_property_readonly("reps", [](const sb::Scene& s) { return s.reps; })
      .def_property_readonly("seed", [](const sb::Scene& s) { return s.seed; })
      .def_property_readonly("t0_s", &sb::Scene::t0_s, "loading time t0 [s]")
      .def_property_readonly("duration_s", &sb::Scene::duration, "simulated time [s]")
      .def("__repr__", &scene_repr)
      .def(py::pickle([](const sb::Scene& s) { return scene_state_text(s); },
                      [](const std::string& state) { return scene_from_state_text(state); }),
           "Pickled as its complete state (every field, the mask's blocks, the materials' columns),\n"
           "so an unpickled scene, in this process or another, runs bit-identically.")
      .def("__eq__", [](const sb::Scene& a, const sb::Scene& b) { return scene_state_text(a) == scene_state_text(b); },
           py::is_operator(), "Equal when every field is: the same state, hence the same numbers when run.")
      .def("__hash__", [](const sb::Scene& s) { return py::hash(py::str(scene_state_text(s))); });
  m.def("pattern_text", [](const py::handle& v) { return pattern_value(v).get<std::string>(); }, py::arg("pattern"),
        "A pattern as the command line writes it: a string as it is, the blocks of a 1-D array, list or tuple of\n"
        "0/1 or bool as 'mask:0110...'. Bad input raises InputError naming the pattern.");
  m.def("scene_fields", &field_table,
        "Every scene field: key (the keyword), help (meaning, default, units) and an example value.");
}

}  // namespace sb::python
