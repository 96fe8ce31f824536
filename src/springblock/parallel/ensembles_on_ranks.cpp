#include "springblock/parallel/ensembles_on_ranks.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "springblock/ensemble/jobs.hpp"
#include "springblock/ensemble_state.hpp"
#include "springblock/scene_state.hpp"

namespace sb::parallel {
namespace {

using ensemble_detail::EnsembleJobs;

// The coordinator's scenes on every rank, read back field for field (scene_state.hpp).
std::vector<Scene> shared_scenes(Scheduler& sched, const std::vector<Scene>& scenes) {
  std::string text;
  if (sched.coordinator()) {
    auto states = nlohmann::json::array();
    for (const auto& s : scenes) states.push_back(scene_state(s));
    text = states.dump();
  }
  text = sched.share(text);
  if (sched.coordinator()) return scenes;
  std::vector<Scene> out;
  for (const auto& s : nlohmann::json::parse(text)) out.push_back(scene_from_state(s));
  return out;
}

// Job ids, the dearest repetition first (duration x N of the scene that runs it), so that no long
// one starts last; equal costs keep their order.
std::vector<int> dearest_first(const std::vector<Scene>& scenes, const EnsembleJobs& plan) {
  std::vector<int> ids(plan.jobs.size());
  std::iota(ids.begin(), ids.end(), 0);
  auto cost = [&](int j) { return scenes[plan.jobs[j].scene].duration() * scenes[plan.jobs[j].scene].geometry.N; };
  std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) { return cost(a) > cost(b); });
  return ids;
}

}  // namespace

std::optional<std::vector<EnsembleResult>> run_ensembles_on(Scheduler& sched, const std::vector<Scene>& given,
                                                           const std::atomic<bool>* interrupt,
                                                           std::function<void(double, double)> progress,
                                                           const std::vector<double>& weights) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::vector<Scene> scenes = shared_scenes(sched, given);
  std::vector<EnsembleResult> out(scenes.size());
  const EnsembleJobs plan = ensemble_detail::plan_jobs(scenes, out);  // the same jobs on every rank
  // A job's record: its runs' states, one per member of its group.
  auto unit = [&](int j, const std::atomic<bool>* stop) -> nlohmann::json {
    auto runs = ensemble_detail::run_job(scenes, plan, j, stop, nullptr);
    if (stop && stop->load()) return nullptr;  // cut short: not a result
    auto states = nlohmann::json::array();
    for (const auto& r : runs) states.push_back(repetition_state(r));
    return states;
  };
  if (!sched.coordinator()) {
    sched.run({}, unit, {}, interrupt);
    return std::nullopt;
  }
  std::vector<char> finished(plan.jobs.size(), 0);
  const auto share = ensemble_detail::job_shares(scenes, plan, weights);
  double done = 0;
  Hooks hooks;
  hooks.finished = [&](int j, int, nlohmann::json record) {
    std::vector<RunResult> runs;
    for (const auto& s : record) runs.push_back(repetition_from_state(s));
    ensemble_detail::store_job(plan, j, std::move(runs), out);
    finished[j] = 1;
    done += share[j];
  };
  if (progress)
    hooks.tick = [&] { progress(done, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count()); };
  const Outcome outcome = sched.run(dearest_first(scenes, plan), unit, hooks, interrupt);
  const int workers = std::max(1, std::min(sched.ranks() * sched.threads(), static_cast<int>(plan.jobs.size())));
  ensemble_detail::finish_ensembles(scenes, plan, finished, workers, out);
  if (outcome.interrupted)
    for (auto& e : out) e.interrupted = true;
  if (scenes.size() == 1)  // a scene alone has a wall time of its own, as from run_ensembles
    out[0].wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return out;
}

}  // namespace sb::parallel
