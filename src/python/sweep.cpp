// springblock._core.sweep: the library's whole sweep (sweep/driver.hpp) on this process's threads,
// writing the files `springblock sweep` writes (results, checkpoint, partial results, per-unit
// records) with the same numbers; springblock.sweep (the package's Python) reads them back.
#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "background.hpp"
#include "springblock/errors.hpp"
#include "springblock/sweep/driver.hpp"

namespace sb::python {
namespace {

py::dict progress_dict(const sweep::Progress& p) {
  return py::dict(py::arg("done") = p.done, py::arg("total") = p.total, py::arg("computed") = p.computed,
                  py::arg("fraction") = p.fraction, py::arg("elapsed_s") = p.elapsed_s,
                  py::arg("eta_s") = p.eta_s >= 0 ? py::object(py::float_(p.eta_s)) : py::object(py::none()),
                  py::arg("ranks") = p.ranks, py::arg("threads") = p.threads);
}

py::dict report_dict(const sweep::Report& r, const sweep::Resumed& resumed) {
  return py::dict(py::arg("interrupted") = r.interrupted, py::arg("scenes") = r.scenes, py::arg("units") = r.units,
                  py::arg("computed") = r.computed, py::arg("resumed") = r.resumed, py::arg("threads") = r.threads,
                  py::arg("wall_s") = r.wall_s, py::arg("out") = r.out, py::arg("partial") = r.partial,
                  py::arg("checkpoint") = r.checkpoint, py::arg("scenes_complete") = r.scenes_complete,
                  py::arg("in_flight") = r.in_flight, py::arg("notes") = r.notes, py::arg("summary") = r.summary,
                  py::arg("lost") = resumed.lost, py::arg("lost_units") = resumed.lost_units);
}

// `file`: a sweep file's path; or `text`, the JSON of a sweep given as a dict, recorded as `label`.
py::dict sweep(const std::string& file, const std::string& text, const std::string& label, const std::string& out,
               const std::string& units, int threads, bool resume, const py::object& progress,
               const std::string& command_line) {
  // The command line's range for sweep --threads.
  require(threads >= 0 && threads <= 4096, "threads", "threads = " + std::to_string(threads) + " is outside [0, 4096]");
  if (file.empty() && out.empty())
    throw InputError("out", "a sweep given as a dict needs out=PATH: its results go there, its checkpoint beside them");
  const sweep::Spec spec = file.empty() ? sweep::parse_json(text, label) : sweep::read_spec(file);
  const sweep::OutputOptions outputs{file.empty() ? label : file, out, units, resume};
  auto scheduler = parallel::make_thread_scheduler(threads);
  Latest<sweep::Progress> latest;
  sweep::Resumed resumed;
  sweep::Events events;
  events.resumed = [&](const sweep::Resumed& r) { resumed = r; };
  if (!progress.is_none()) events.progress = [&](const sweep::Progress& p) { latest.post(p); };
  auto poll = [&] {
    if (auto p = latest.take()) progress(progress_dict(*p));
  };
  const auto report = in_background(
      [&](const std::atomic<bool>* stop) {
        return sweep::run_sweep(spec, outputs, *scheduler, stop, events, command_line);
      },
      poll);
  if (!progress.is_none() && !report.interrupted) {  // the end, which no tick may have reported
    sweep::Progress end;
    end.done = end.total = report.units;
    end.computed = report.computed;
    end.threads = report.threads;
    end.fraction = 1;
    end.elapsed_s = report.wall_s;
    end.eta_s = 0;
    progress(progress_dict(end));
  }
  return report_dict(report, resumed);
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("file"), py::arg("text"), py::arg("label"), py::arg("out"), py::arg("units"),
        py::arg("threads"), py::arg("resume"), py::arg("progress"), py::arg("command_line"),
        "The library's sweep with the GIL released; springblock.sweep is the documented entry point.");
}

}  // namespace sb::python
