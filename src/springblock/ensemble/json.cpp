// The results JSON of a repetition and of a statistic. Doubles that are not finite are written as
// null (a results file never holds a NaN) and read back as NaN.
#include <cmath>
#include <nlohmann/json.hpp>

#include "springblock/ensemble.hpp"

namespace sb {

nlohmann::json json_number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

void to_json(nlohmann::json& j, const Statistic& s) {
  j = {{"mean", json_number(s.mean)}, {"std", json_number(s.std)}, {"sem", json_number(s.sem)}, {"n", s.n}};
}

void to_json(nlohmann::json& j, const WorkProfile& w) {
  j = nlohmann::json::object();
#define SB_COUNT(name, doc) j[#name] = w.name;
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
  if (!w.timed) return;  // no times rather than zeros
#define SB_TIME(name, doc) j[#name] = w.name;
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
}

void to_json(nlohmann::json& j, const RunResult& r) {
  j = {{"rep", r.rep},         {"slipped", r.slipped},     {"window_samples", r.window_samples},
       {"steps", r.steps},     {"rhs_evals", r.rhs_evals}, {"switches", r.switches},
       {"t_end_s", r.t_end_s}, {"wall_s", r.wall_s}, {"cpu_s", r.cpu_s}, {"work", r.work}};
  for (const auto& o : observables()) j[o.name] = json_number(r.*o.value);
  if (r.slip_events) j["slip_events"] = *r.slip_events;
}

namespace {

double json_double(const nlohmann::json& v) { return v.is_null() ? std::nan("") : v.get<double>(); }

}  // namespace

void from_json(const nlohmann::json& j, RunResult& r) {
  r.rep = j.at("rep").get<int>();
  r.slipped = j.at("slipped").get<bool>();
  r.window_samples = j.at("window_samples").get<std::int64_t>();
  r.steps = j.at("steps").get<std::int64_t>();
  r.rhs_evals = j.at("rhs_evals").get<std::int64_t>();
  r.switches = j.at("switches").get<std::int64_t>();
  r.t_end_s = j.at("t_end_s").get<double>();
  r.wall_s = j.at("wall_s").get<double>();
  r.cpu_s = j.at("cpu_s").get<double>();
  r.contact_fraction = json_double(j.value("contact_fraction", nlohmann::json()));
  for (const auto& o : observables()) r.*o.value = json_double(j.at(o.name));
  if (j.contains("slip_events")) r.slip_events = j.at("slip_events").get<SlipEventRecord>();
  const auto& w = j.at("work");
#define SB_COUNT(name, doc) r.work.name = w.at(#name).get<std::int64_t>();
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
  r.work.timed = w.contains("stepping_s");
  if (!r.work.timed) return;
#define SB_TIME(name, doc) r.work.name = w.at(#name).get<double>();
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
}

}  // namespace sb
