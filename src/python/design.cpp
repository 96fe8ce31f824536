// springblock._core.design: the query `springblock design` runs, from keywords named as its
// options (with '_'), through the library's checks (design/query_text.hpp) and search, giving the
// object `springblock design --json` prints. springblock.design (the package's Python) wraps it.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "background.hpp"
#include "springblock/design/query_text.hpp"
#include "springblock/design/report.hpp"
#include "springblock/errors.hpp"
#include "springblock/io.hpp"
#include "springblock/scene_fields.hpp"

namespace sb::python {
namespace {

using Setter = std::function<void(design::Query&, design::QueryText&, const py::handle&)>;

int int_of(const std::string& name, const py::handle& v) {
  if (py::isinstance<py::bool_>(v) || !PyIndex_Check(v.ptr())) throw InputError(name, "must be an integer");
  return py::int_(py::reinterpret_borrow<py::object>(v)).cast<int>();
}
double double_of(const std::string& name, const py::handle& v) {
  if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v) || !py::hasattr(v, "__float__"))
    throw InputError(name, "must be a number");
  return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
}
// A target interval as the command line writes it: "X", "LO:HI", ">=X", "<=X"; a number is X and
// a pair (LO, HI) is LO:HI.
std::string interval_of(const std::string& name, const py::handle& v) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v)) {
    const auto pair = py::reinterpret_borrow<py::sequence>(v);
    if (pair.size() != 2) throw InputError(name, "a pair (LO, HI) has two numbers");
    return py::repr(py::float_(double_of(name, pair[0]))).cast<std::string>() + ":" +
           py::repr(py::float_(double_of(name, pair[1]))).cast<std::string>();
  }
  return py::repr(py::float_(double_of(name, v))).cast<std::string>();
}
std::string word_of(const std::string& name, const py::handle& v) {
  if (!py::isinstance<py::str>(v)) throw InputError(name, "must be a string");
  return v.cast<std::string>();
}

// Every option of `springblock design` but the scene fields, --json, --out and --progress.
const std::map<std::string, Setter>& options() {
  using Q = design::Query;
  using T = design::QueryText;
  using H = const py::handle&;
  static const std::map<std::string, Setter> table = {
      {"family", [](Q&, T& t, H v) { t.family = word_of("family", v); }},
      {"candidates", [](Q&, T& t, H v) {
         t.candidates.clear();
         for (auto c : py::reinterpret_borrow<py::iterable>(v)) t.candidates.push_back(pattern_value(c).get<std::string>());
       }},
      {"target_mu_s", [](Q&, T& t, H v) { t.target_mu_s = interval_of("target_mu_s", v); }},
      {"target_mu_d", [](Q&, T& t, H v) { t.target_mu_d = interval_of("target_mu_d", v); }},
      {"target_ratio", [](Q&, T& t, H v) { t.target_ratio = interval_of("target_ratio", v); }},
      {"minimise", [](Q&, T& t, H v) { t.minimise = word_of("minimise", v); }},
      {"maximise", [](Q&, T& t, H v) { t.maximise = word_of("maximise", v); }},
      {"min_np", [](Q& q, T&, H v) { q.space.min_np = int_of("min_np", v); }},
      {"max_np", [](Q&, T& t, H v) { t.max_np = int_of("max_np", v); }},
      {"min_ng", [](Q& q, T&, H v) { q.space.min_ng = int_of("min_ng", v); }},
      {"max_ng", [](Q&, T& t, H v) { t.max_ng = int_of("max_ng", v); }},
      {"levels", [](Q& q, T&, H v) { q.space.levels = int_of("levels", v); }},
      {"factors", [](Q& q, T&, H v) {
         q.space.factors.clear();
         for (auto f : py::reinterpret_borrow<py::iterable>(v)) q.space.factors.push_back(int_of("factors", f));
       }},
      {"min_fraction", [](Q& q, T&, H v) { q.space.min_fraction = double_of("min_fraction", v); }},
      {"max_fraction", [](Q& q, T&, H v) { q.space.max_fraction = double_of("max_fraction", v); }},
      {"fraction_step", [](Q& q, T&, H v) { q.space.fraction_step = double_of("fraction_step", v); }},
      {"min_contact", [](Q& q, T&, H v) { q.space.min_contact = double_of("min_contact", v); }},
      {"max_contact", [](Q& q, T&, H v) { q.space.max_contact = double_of("max_contact", v); }},
      {"min_feature", [](Q& q, T&, H v) { q.space.min_feature = int_of("min_feature", v); }},
      {"top", [](Q& q, T&, H v) { q.top = int_of("top", v); }},
      {"verify_reps", [](Q& q, T&, H v) { q.verify.reps = int_of("verify_reps", v); }},
      {"verify_max_reps", [](Q& q, T&, H v) { q.verify.max_reps = int_of("verify_max_reps", v); }},
      {"resolution", [](Q& q, T&, H v) { q.verify.resolution = double_of("resolution", v); }},
      {"screen_reps", [](Q& q, T&, H v) { q.search.screen_reps = int_of("screen_reps", v); }},
      {"eta", [](Q& q, T&, H v) { q.search.eta = int_of("eta", v); }},
      {"growth", [](Q& q, T&, H v) { q.search.growth = int_of("growth", v); }},
      {"max_reps", [](Q& q, T&, H v) { q.search.max_reps = int_of("max_reps", v); }},
      {"final_pool", [](Q& q, T&, H v) { q.search.final_pool = int_of("final_pool", v); }},
      {"class_width", [](Q& q, T&, H v) { q.classes.bin_width = double_of("class_width", v); }},
      {"class_margin", [](Q& q, T&, H v) { q.classes.margin = double_of("class_margin", v); }},
      {"class_prune", [](Q& q, T&, H v) { q.class_prune = py::bool_(py::reinterpret_borrow<py::object>(v)); }},
  };
  return table;
}

bool scene_field(const std::string& key) {
  for (const auto& f : scene_fields())
    if (f.key == key) return true;
  return false;
}

// The query of `keywords`: scene fields to the base scene, the rest to the search. Throws
// InputError naming the keyword.
design::Query build_query(const py::dict& keywords) {
  design::Query q;
  design::QueryText text;
  py::dict fields;
  for (auto [key, value] : keywords) {
    const auto name = key.cast<std::string>();
    if (name == "pattern") design::refuse_pattern(py::str(value).cast<std::string>());
    const auto option = options().find(name);
    if (option != options().end()) option->second(q, text, value);
    else if (scene_field(name) && design::shared_scene_field(name)) fields[key] = value;
    else if (scene_field(name))
      throw InputError(name, "the design search chooses it (its rungs set the repetitions and the stop at the first slip)");
    else
      throw InputError(name, "not an option of design: give a scene field (see scene_fields()) or one of the search's "
                             "options (family, candidates, target_mu_s, ..., top, verify_reps; see help(springblock.design))");
  }
  q.base = with_fields(q.base, fields);
  design::complete_query(q, text);
  return q;
}

}  // namespace

py::object design(const py::dict& keywords, const std::string& out, const py::object& progress,
                  const std::string& command_line) {
  const design::Query q = build_query(keywords);
  if (!out.empty()) check_writable(out, "out");
  Latest<std::tuple<std::string, double, double>> latest;
  design::StageProgress stages;
  if (!progress.is_none())
    stages = [&](const std::string& stage, double f, double elapsed) { latest.post({stage, f, elapsed}); };
  auto poll = [&] {
    if (auto p = latest.take())
      progress(py::dict(py::arg("stage") = std::get<0>(*p), py::arg("fraction") = std::get<1>(*p),
                        py::arg("elapsed_s") = std::get<2>(*p)));
  };
  const auto outcome =
      in_background([&](const std::atomic<bool>* stop) { return design::run_design(q, stop, stages); }, poll);
  const auto j = design::design_json(q, outcome, command_line);
  if (!out.empty()) write_file_atomic(out, j.dump(2) + "\n");
  return to_python(j);
}

void bind_design(py::module_& m) {
  m.def("design", &design, py::arg("keywords"), py::arg("out"), py::arg("progress"), py::arg("command_line"),
        "The library's design query with the GIL released; springblock.design is the documented entry point.");
}

}  // namespace sb::python
