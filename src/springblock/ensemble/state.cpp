#include "springblock/ensemble_state.hpp"

#include <nlohmann/json.hpp>

#include "springblock/errors.hpp"
#include "springblock/exact_json.hpp"

namespace sb {
// Named, not anonymous: in a unity batch an anonymous helper would meet another file's.
namespace ensemble_state_parts {

constexpr int kStateVersion = 1;  // bumped with any field added to RunResult or EnsembleResult

using exact_json::num;
using exact_json::nums;

nlohmann::json run_state(const RunResult& r) {
  nlohmann::json j = r;  // the results JSON: its values as null where not finite, restored below
  auto values = nlohmann::json::array();
  for (const auto& o : observables()) values.push_back(num(r.*o.value));
  j["exact_values"] = values;
  j["contact_fraction"] = num(r.contact_fraction);
  auto series = nlohmann::json::array();
  for (const auto& s : r.series) series.push_back({num(s.t), num(s.mu), num(s.mu_signed), s.n_sliding});
  j["series"] = series;
  auto stress = nlohmann::json::array();
  for (const auto& s : r.stress) stress.push_back({num(s.t), nums(s.f_over_Fn), nums(s.sigma_over_P)});
  j["stress"] = stress;
  return j;
}

RunResult run_from(nlohmann::json j) {
  const double contact = num(j.at("contact_fraction"));
  j.erase("contact_fraction");
  RunResult r = j.get<RunResult>();
  r.contact_fraction = contact;
  const auto& values = j.at("exact_values");
  for (std::size_t i = 0; i < observables().size(); ++i) r.*observables()[i].value = num(values.at(i));
  for (const auto& s : j.at("series"))
    r.series.push_back({num(s.at(0)), num(s.at(1)), num(s.at(2)), s.at(3).get<int>()});
  for (const auto& s : j.at("stress")) r.stress.push_back({num(s.at(0)), nums(s.at(1)), nums(s.at(2))});
  return r;
}

nlohmann::json statistic_state(const Statistic& s) { return {num(s.mean), num(s.std), num(s.sem), s.n}; }
Statistic statistic_from(const nlohmann::json& j) {
  return {num(j.at(0)), num(j.at(1)), num(j.at(2)), j.at(3).get<int>()};
}

}  // namespace ensemble_state_parts

nlohmann::json repetition_state(const RunResult& r) { return ensemble_state_parts::run_state(r); }

RunResult repetition_from_state(const nlohmann::json& j) { return ensemble_state_parts::run_from(j); }

nlohmann::json ensemble_state(const EnsembleResult& e) {
  using namespace ensemble_state_parts;
  auto runs = nlohmann::json::array();
  for (const auto& r : e.runs) runs.push_back(run_state(r));
  auto statistics = nlohmann::json::array();
  for (const auto& o : observables()) statistics.push_back(statistic_state(e.*o.statistic));
  return {{"springblock_ensemble_state", kStateVersion},
          {"runs", runs},
          {"statistics", statistics},
          {"contact_fraction", num(e.contact_fraction)},
          {"wall_s", num(e.wall_s)},
          {"threads", e.threads},
          {"interrupted", e.interrupted},
          {"finished_reps", e.finished_reps},
          {"trajectory_from", e.trajectory_from}};
}

EnsembleResult ensemble_from_state(const nlohmann::json& j) {
  using namespace ensemble_state_parts;
  if (!j.is_object() || j.value("springblock_ensemble_state", 0) != kStateVersion)
    throw InputError("state", "not a result state of this springblock (state version " + std::to_string(kStateVersion) +
                                  "): pickle the result again with this version");
  try {
    EnsembleResult e;
    for (const auto& r : j.at("runs")) e.runs.push_back(run_from(r));
    const auto& statistics = j.at("statistics");
    for (std::size_t i = 0; i < observables().size(); ++i)
      e.*observables()[i].statistic = statistic_from(statistics.at(i));
    e.contact_fraction = num(j.at("contact_fraction"));
    e.wall_s = num(j.at("wall_s"));
    e.threads = j.at("threads").get<int>();
    e.interrupted = j.at("interrupted").get<bool>();
    e.finished_reps = j.at("finished_reps").get<int>();
    e.trajectory_from = j.at("trajectory_from").get<int>();
    return e;
  } catch (const nlohmann::json::exception& ex) {
    throw InputError("state", std::string("a result state with a missing or malformed entry: ") + ex.what());
  }
}

}  // namespace sb
