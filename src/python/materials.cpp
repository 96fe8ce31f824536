// Per-block fields given from Python: arrays by field name, and segments as dicts, turned into
// what a materials file and a scene file give the library, so the checks and messages are theirs.
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "springblock/errors.hpp"

namespace sb::python {

void set_materials_arrays(sb::Scene& scene, const py::dict& arrays) {
  sb::BlockMaterials m;
  m.source = "python arrays";
  m.segments = std::move(scene.materials.segments);
  for (auto [key, value] : arrays) {
    if (!py::isinstance<py::str>(key)) throw sb::InputError("materials", "a field name must be a string");
    const auto field = sb::block_field(key.cast<std::string>(), "python arrays");
    py::array_t<double, py::array::c_style | py::array::forcecast> a;
    try {
      a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    } catch (const py::error_already_set&) {
    }
    if (!a || a.ndim() != 1)
      throw sb::InputError("materials", "python arrays: " + key.cast<std::string>() +
                                            " must be a 1-D array or list of numbers, one per block");
    m.columns[sb::index_of(field)].assign(a.data(), a.data() + a.size());
  }
  scene.materials = std::move(m);
}

nlohmann::json segments_json(const py::handle& segments) {
  // json.dumps gives the library's reader the same text a scene file would hold; numpy scalars
  // become plain numbers first.
  auto plain = [](const py::handle& v) -> py::object {
    if (py::hasattr(v, "item") && !py::isinstance<py::str>(v)) return v.attr("item")();
    return py::reinterpret_borrow<py::object>(v);
  };
  py::list out;
  if (!py::isinstance<py::list>(segments) && !py::isinstance<py::tuple>(segments))
    throw sb::InputError("segments", "must be a list of dicts {field, from, to, value} or {field, from, to, start, end}");
  for (auto g : segments) {
    if (!py::isinstance<py::dict>(g)) throw sb::InputError("segments", "each segment must be a dict");
    py::dict d;
    for (auto [k, v] : py::reinterpret_borrow<py::dict>(g)) d[k] = plain(v);
    out.append(d);
  }
  const auto text = py::module_::import("json").attr("dumps")(out).cast<std::string>();
  return nlohmann::json::parse(text);
}

}  // namespace sb::python
