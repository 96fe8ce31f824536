// springblock.run and run_many: the ensemble runs with the GIL released (other Python threads go
// on; the repetitions use the scene's threads) and stops cleanly on Ctrl-C.
#include <pybind11/stl.h>

#include "background.hpp"

namespace sb::python {
namespace {

sb::Scene observed(sb::Scene scene, bool series) {
  scene.observe.series = series;
  return scene;
}

Result run(const sb::Scene& scene, bool series) {
  Result r{observed(scene, series), {}};
  r.ensemble = in_background([&](const std::atomic<bool>* stop) { return sb::run_ensemble(r.scene, stop); });
  return r;
}

std::vector<Result> run_many(const std::vector<sb::Scene>& scenes, bool series) {
  std::vector<sb::Scene> observed_scenes;
  for (const auto& s : scenes) observed_scenes.push_back(observed(s, series));
  auto ensembles = in_background([&](const std::atomic<bool>* stop) { return sb::run_ensembles(observed_scenes, stop); });
  std::vector<Result> results;
  for (std::size_t i = 0; i < scenes.size(); ++i) results.push_back({observed_scenes[i], std::move(ensembles[i])});
  return results;
}

}  // namespace

void bind_run(py::module_& m) {
  // series defaults to off as on the command line (mu(t) costs memory); keeping it changes no
  // statistic (FrictionObserver.KeepingTheSeriesChangesNoStatistic*).
  m.def("run", &run, py::arg("scene"), py::arg("series") = false,
        "Run the scene's repetitions (in parallel over its `threads`) and return a Result. The same\n"
        "scene and seed give the numbers `springblock run` gives (with series=True, those of\n"
        "`springblock run --series FILE`). series=True keeps mu(t) of repetition 0 (Result.series).");
  m.def("run_many", &run_many, py::arg("scenes"), py::arg("series") = false,
        "Run several scenes in one pool of threads (every scene-repetition is one job); each\n"
        "result is what run() gives that scene.");
}

}  // namespace sb::python
