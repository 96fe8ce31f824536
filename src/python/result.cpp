// springblock.Result and what it holds. Its statistics are generated from the library's list of
// observables (observables.hpp, via sb::observables()), so an observable added there appears here
// as result.<name> with mean, std, sem, n, and the per-repetition values as a numpy array.
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "springblock/ensemble_state.hpp"
#include "springblock/errors.hpp"
#include "springblock/io.hpp"
#include "springblock/scene_state.hpp"

namespace sb::python {
namespace {

template <class T>
py::array_t<T> array(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

// One observable's statistic over the repetitions, with each repetition's value (NaN where it
// is undefined) and, when it has no value, why (as the results JSON's not_measured says).
struct Statistic {
  std::string name, unit;
  sb::Statistic value;
  py::array_t<double> values;
  std::string not_measured;
};

Statistic statistic(const Result& r, const sb::Observable& o) {
  std::vector<double> values;
  for (const auto& run : r.ensemble.runs) values.push_back(run.*o.value);
  return {o.name, o.unit, r.ensemble.*o.statistic, array(values), sb::not_measured(r.scene, r.ensemble, o)};
}

// mu(t), its signed sum and the sliding count of repetition 0 (empty unless run(series=True)).
struct Series {
  py::array_t<double> t, mu, mu_signed;
  py::array_t<int> n_sliding;
};

Series series(const Result& r) {
  std::vector<double> t, mu, mu_signed;
  std::vector<int> n_sliding;
  if (!r.ensemble.runs.empty())
    for (const auto& s : r.ensemble.runs.front().series)
      t.push_back(s.t), mu.push_back(s.mu), mu_signed.push_back(s.mu_signed), n_sliding.push_back(s.n_sliding);
  return {array(t), array(mu), array(mu_signed), array(n_sliding)};
}

py::list stress(const Result& r) {
  py::list snapshots;
  if (!r.ensemble.runs.empty())
    for (const auto& s : r.ensemble.runs.front().stress)
      snapshots.append(py::dict(py::arg("t") = s.t, py::arg("f_over_Fn") = array(s.f_over_Fn),
                                py::arg("sigma_over_P") = array(s.sigma_over_P)));
  return snapshots;
}

// The event under way at the end of a repetition (start, blocks and episodes so far, slip of its
// finished episodes), or None.
py::object under_way(const SlipEventRecord& rec) {
  if (!rec.unfinished) return py::none();
  const SlipEvent& e = rec.under_way;
  return py::dict(py::arg("t_start_s") = e.t_start_s, py::arg("blocks") = e.blocks, py::arg("episodes") = e.episodes,
                  py::arg("slip_m") = e.slip_m);
}

// Each repetition's slip events (scene slip_events=True): a dict of numpy columns, one entry per
// event, and whether an event was under way at the end; None when the scene did not record them.
py::object slip_events(const Result& r) {
  if (!r.scene.observe.slip_events) return py::none();
  py::list runs;
  for (const auto& run : r.ensemble.runs) {
    if (!run.slip_events) {  // a repetition that did not finish
      runs.append(py::none());
      continue;
    }
    std::vector<double> t, duration, slip;
    std::vector<int> blocks, episodes;
    const SlipEventRecord& rec = *run.slip_events;
    for (const SlipEvent& e : rec.events) {
      t.push_back(e.t_start_s), duration.push_back(e.duration_s), slip.push_back(e.slip_m);
      blocks.push_back(e.blocks), episodes.push_back(e.episodes);
    }
    runs.append(py::dict(py::arg("t_start_s") = array(t), py::arg("duration_s") = array(duration),
                         py::arg("blocks") = array(blocks), py::arg("episodes") = array(episodes),
                         py::arg("slip_m") = array(slip), py::arg("unfinished") = rec.unfinished,
                         py::arg("under_way") = under_way(rec)));
  }
  return runs;
}

std::string statistic_repr(const Statistic& s) {
  if (s.value.n == 0) return s.name + ": not measured (" + (s.not_measured.empty() ? "no value" : s.not_measured) + ")";
  char text[160];
  std::snprintf(text, sizeof text, "%s = %.6g +- %.2g%s%s (sd %.2g, n=%d)", s.name.c_str(), s.value.mean, s.value.sem,
                s.unit.empty() ? "" : " ", s.unit.c_str(), s.value.std, s.value.n);
  return text;
}

void bind_statistic(py::module_& m) {
  py::class_<Statistic>(m, "Statistic", "An observable over the repetitions that define it.")
      .def_readonly("name", &Statistic::name)
      .def_readonly("unit", &Statistic::unit, "'' for a friction coefficient")
      .def_property_readonly("mean", [](const Statistic& s) { return s.value.mean; })
      .def_property_readonly("std", [](const Statistic& s) { return s.value.std; }, "sample standard deviation")
      .def_property_readonly("sem", [](const Statistic& s) { return s.value.sem; }, "standard error of the mean")
      .def_property_readonly("n", [](const Statistic& s) { return s.value.n; }, "repetitions with a value")
      .def_readonly("values", &Statistic::values, "per repetition, NaN where undefined")
      .def_readonly("not_measured", &Statistic::not_measured, "why n is 0, else ''")
      .def("__repr__", &statistic_repr);
  py::class_<Series>(m, "Series", "mu(t) of repetition 0, one entry per sample.")
      .def_readonly("t", &Series::t, "time [s]")
      .def_readonly("mu", &Series::mu, "sum of |friction| / load")
      .def_readonly("mu_signed", &Series::mu_signed, "sum of signed friction / load")
      .def_readonly("n_sliding", &Series::n_sliding, "blocks sliding");
}

std::string result_repr(const Result& r) {
  std::string text = "springblock.Result(";
  for (const auto& o : sb::observables())
    if (std::string(o.name) == "mu_s" || std::string(o.name) == "mu_d")
      text += (text.back() == '(' ? "" : ", ") + statistic_repr(statistic(r, o));
  return text + ")";
}

}  // namespace

void bind_result(py::module_& m) {
  bind_statistic(m);
  py::class_<Result> result(m, "Result", "What run(scene) returns.");
  for (const auto& o : sb::observables())
    result.def_property_readonly(o.name, [o](const Result& r) { return statistic(r, o); });
  result.def_property_readonly("scene", [](const Result& r) { return r.scene; })
      .def_property_readonly("contact_fraction", [](const Result& r) { return r.ensemble.contact_fraction; })
      .def_property_readonly("wall_s", [](const Result& r) { return r.ensemble.wall_s; })
      .def_property_readonly("threads", [](const Result& r) { return r.ensemble.threads; })
      .def_property_readonly("series", &series, "mu(t) of repetition 0 (empty unless run(scene, series=True))")
      .def_property_readonly("stress", &stress,
                             "repetition 0's stress snapshots at the scene's stress_times: dicts of t, f_over_Fn, "
                             "sigma_over_P")
      .def_property_readonly("slip_events", &slip_events,
                             "each repetition's slip events when the scene records them (slip_events=True): dicts "
                             "of t_start_s, duration_s, blocks, episodes, slip_m (numpy, one entry per event) and "
                             "unfinished (an event was under way at the end, not recorded) with under_way (its start, "
                             "blocks and episodes so far) or None; None when not recorded")
      .def_property_readonly("runs", [](const Result& r) { return to_python(nlohmann::json(r.ensemble.runs)); },
                             "each repetition's values and work counters, as in the results JSON")
      .def("to_json", [](const Result& r, const std::string& cmd) { return to_python(sb::ensemble_json(r.scene, r.ensemble, cmd)); },
           py::arg("command_line") = "python",
           "The results object `springblock run --json` prints, as a dict.")
      .def("__repr__", &result_repr)
      .def(py::pickle(
               [](const Result& r) {
                 return py::make_tuple(sb::scene_state(r.scene).dump(), sb::ensemble_state(r.ensemble).dump());
               },
               [](const py::tuple& state) {
                 if (state.size() != 2) throw sb::InputError("state", "a Result pickles as (scene, ensemble) states");
                 auto parse = [](const py::handle& text) {
                   return nlohmann::json::parse(text.cast<std::string>(), nullptr, false);
                 };
                 return Result{sb::scene_from_state(parse(state[0])), sb::ensemble_from_state(parse(state[1]))};
               }),
           "Pickled as its scene's and its repetitions' complete state: every number reads back the same.");
  m.def("observables", [] {
    py::list names;
    for (const auto& o : sb::observables()) names.append(py::make_tuple(o.name, o.unit));
    return names;
  }, "The observables a Result carries, as (name, unit).");
}

}  // namespace sb::python
