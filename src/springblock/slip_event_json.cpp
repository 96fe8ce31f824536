// Slip events in the results JSON: each repetition's as columns (compact, and what a plot reads),
// and the ensemble's distribution of event sizes in blocks.
#include <map>
#include <nlohmann/json.hpp>

#include "springblock/ensemble.hpp"

namespace sb {

void to_json(nlohmann::json& j, const SlipEventRecord& r) {
  nlohmann::json t = nlohmann::json::array(), d = nlohmann::json::array(), b = nlohmann::json::array(),
                 e = nlohmann::json::array(), x = nlohmann::json::array();
  for (const SlipEvent& ev : r.events) {
    t.push_back(ev.t_start_s), d.push_back(ev.duration_s), b.push_back(ev.blocks);
    e.push_back(ev.episodes), x.push_back(ev.slip_m);
  }
  j = {{"t_start_s", t}, {"duration_s", d}, {"blocks", b}, {"episodes", e}, {"slip_m", x},
       {"unfinished", r.unfinished}};
  if (r.unfinished)
    j["under_way"] = {{"t_start_s", r.under_way.t_start_s}, {"blocks", r.under_way.blocks},
                      {"episodes", r.under_way.episodes}, {"slip_m", r.under_way.slip_m}};
}

void from_json(const nlohmann::json& j, SlipEventRecord& r) {
  const auto& t = j.at("t_start_s");
  r.events.assign(t.size(), SlipEvent{});
  for (std::size_t k = 0; k < t.size(); ++k) {
    SlipEvent& ev = r.events[k];
    ev.t_start_s = t.at(k).get<double>();
    ev.duration_s = j.at("duration_s").at(k).get<double>();
    ev.blocks = j.at("blocks").at(k).get<int>();
    ev.episodes = j.at("episodes").at(k).get<int>();
    ev.slip_m = j.at("slip_m").at(k).get<double>();
  }
  r.unfinished = j.at("unfinished").get<bool>();
  r.under_way = SlipEvent{};
  if (!r.unfinished) return;
  const auto& u = j.at("under_way");
  r.under_way.t_start_s = u.at("t_start_s").get<double>();
  r.under_way.blocks = u.at("blocks").get<int>();
  r.under_way.episodes = u.at("episodes").get<int>();
  r.under_way.slip_m = u.at("slip_m").get<double>();
}

nlohmann::json slip_event_summary(const EnsembleResult& e) {
  std::vector<double> per_run;
  std::map<int, long long> by_blocks;
  int unfinished = 0;
  for (const RunResult& run : e.runs) {
    if (!run.slip_events) continue;
    per_run.push_back(static_cast<double>(run.slip_events->events.size()));
    for (const SlipEvent& ev : run.slip_events->events) ++by_blocks[ev.blocks];
    unfinished += run.slip_events->unfinished;
  }
  if (per_run.empty()) return nullptr;
  nlohmann::json sizes = nlohmann::json::array(), counts = nlohmann::json::array();
  for (const auto& [blocks, count] : by_blocks) sizes.push_back(blocks), counts.push_back(count);
  return {{"events_per_run", summarize(per_run)},
          {"counts_by_blocks", {{"blocks", sizes}, {"events", counts}}},
          {"unfinished_runs", unfinished}};
}

}  // namespace sb
