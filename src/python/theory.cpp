// springblock.theory: the closed-form single-block theory (theory.hpp), and its prediction for a
// scene (scene_theory.hpp: what `springblock theory --json` prints). Positions and velocities
// take a time or an array of times, for plotting.
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "springblock/scene_theory.hpp"

namespace sb::python {
namespace {

using sb::theory::SingleBlock;
using sb::theory::SingleBlockCycle;

// f(b, mu_s, mu_d, t) for each element of `t`, in its shape.
using Times = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <double (*f)(const SingleBlock&, double, double, double)>
Times over_times(const SingleBlock& b, double mu_s, double mu_d, const Times& t) {
  Times out(t.request().shape);
  double* o = out.mutable_data();
  const double* x = t.data();
  for (py::ssize_t i = 0; i < t.size(); ++i) o[i] = f(b, mu_s, mu_d, x[i]);
  return out;
}

void bind_block(py::module_& t) {
  py::class_<SingleBlock>(t, "SingleBlock", "One block of mass m on a spring k to a slider at v, normal force F_n.")
      .def(py::init([](double m, double k, double v, double F) { return SingleBlock{m, k, v, F}; }),
           py::arg("m_kg"), py::arg("k_N_per_m"), py::arg("v_m_per_s"), py::arg("F_n_N"))
      .def_readwrite("m_kg", &SingleBlock::m_kg)
      .def_readwrite("k_N_per_m", &SingleBlock::k_N_per_m)
      .def_readwrite("v_m_per_s", &SingleBlock::v_m_per_s)
      .def_readwrite("F_n_N", &SingleBlock::F_n_N);
  py::class_<SingleBlockCycle>(t, "SingleBlockCycle", "One stick-slip cycle of a single block.")
      .def_readonly("omega", &SingleBlockCycle::omega, "sqrt(k/m) [rad/s]")
      .def_readonly("r0_m", &SingleBlockCycle::r0_m, "slider-block distance at slip onset")
      .def_readonly("T_d_s", &SingleBlockCycle::T_d_s, "duration of the sliding phase")
      .def_readonly("delta_r_m", &SingleBlockCycle::delta_r_m, "rest offset at the end of sliding")
      .def_readonly("T_s_s", &SingleBlockCycle::T_s_s, "duration of the static phase")
      .def_readonly("F_stat_mean_over_Fn", &SingleBlockCycle::F_stat_mean_over_Fn)
      .def_readonly("mu_d_macro", &SingleBlockCycle::mu_d_macro, "(mu_d)_M: time-averaged |friction| / F_n");
}

}  // namespace

void bind_theory(py::module_& m) {
  auto t = m.def_submodule("theory", "Closed-form single-block theory (the K_int = 0 limit).");
  bind_block(t);
  t.def("cycle", &sb::theory::cycle, py::arg("block"), py::arg("mu_s"), py::arg("mu_d"),
        "The cycle for 0 <= mu_d <= mu_s, mu_s > 0 (ValueError otherwise).");
  t.def("x_sliding", &sb::theory::x_sliding, py::arg("block"), py::arg("mu_s"), py::arg("mu_d"), py::arg("t_s"),
        "Block position during sliding, t from slip onset.");
  t.def("x_sliding", &over_times<&sb::theory::x_sliding>, py::arg("block"), py::arg("mu_s"), py::arg("mu_d"),
        py::arg("t_s"));
  t.def("xdot_sliding", &sb::theory::xdot_sliding, py::arg("block"), py::arg("mu_s"), py::arg("mu_d"),
        py::arg("t_s"), "Block velocity during sliding, t from slip onset.");
  t.def("xdot_sliding", &over_times<&sb::theory::xdot_sliding>, py::arg("block"), py::arg("mu_s"),
        py::arg("mu_d"), py::arg("t_s"));
  t.def("mu_d_macro_gaussian", &sb::theory::mu_d_macro_gaussian, py::arg("block"), py::arg("mean_s"),
        py::arg("sd_s"), py::arg("mean_d"), py::arg("sd_d"), py::arg("rel_tol") = 1e-9,
        "(mu_d)_M averaged over Gaussian micro coefficients (mu_d clipped to mu_s).");
  t.def("single_block", &sb::theory::single_block, py::arg("scene"),
        "The single block of a scene's K_int = 0 limit.");
  t.def("of_scene", [](const sb::Scene& s) { return to_python(nlohmann::json(sb::theory::predict(s))); },
        py::arg("scene"), "The prediction `springblock theory --json` prints for the scene, as a dict.");
  // `import springblock.theory` finds the submodule too.
  py::module_::import("sys").attr("modules")["springblock.theory"] = t;
}

}  // namespace sb::python
