#include "springblock/ensemble/shared_trajectory.hpp"

#include <algorithm>
#include <map>

#include "springblock/ensemble/observation.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/fan_out.hpp"
#include "springblock/observe/switch_tap.hpp"
#include "springblock/trajectory_spec.hpp"

namespace sb::ensemble_detail {

std::vector<std::vector<int>> group_by_trajectory(const std::vector<Scene>& scenes, std::vector<EnsembleResult>& out) {
  const int n_scenes = static_cast<int>(scenes.size());
  std::map<TrajectorySpec, std::size_t> group_of;
  std::vector<std::vector<int>> groups;
  for (int k = 0; k < n_scenes; ++k) {
    const auto spec = trajectory_spec(scenes[k]);
    const auto it = spec ? group_of.find(*spec) : group_of.end();
    if (it != group_of.end()) {
      groups[it->second].push_back(k);
      continue;
    }
    if (spec) group_of.emplace(*spec, groups.size());
    groups.push_back({k});
  }
  std::vector<std::vector<int>> members(n_scenes);
  for (auto& g : groups) {
    std::stable_sort(g.begin(), g.end(), [&](int a, int b) { return scenes[a].duration() > scenes[b].duration(); });
    for (int m : g)
      if (m != g.front()) out[m].trajectory_from = g.front();
    members[g.front()] = std::move(g);
  }
  return members;
}

std::vector<RunResult> run_shared_repetition(const std::vector<const Scene*>& scenes, int rep,
                                             const std::atomic<bool>* interrupt,
                                             std::atomic<std::int64_t>* progress_ns) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_s();
  const Scene& longest = *scenes.front();
  const Chain chain = build_chain(longest, rep);
  State state = State::at_rest(chain);
  state.work.timed = longest.observe.timed_work;
  std::vector<FrictionObserver> observers;
  std::vector<SlipEventObserver> slips(scenes.size());
  std::vector<SwitchTap> with_slips;
  observers.reserve(scenes.size());  // the views below point into these vectors
  with_slips.reserve(scenes.size());
  std::vector<FanOut::View> views;
  for (std::size_t m = 0; m < scenes.size(); ++m) {
    observers.emplace_back(observer_config(*scenes[m], chain, rep, interrupt, m == 0 ? progress_ns : nullptr));
    with_slips.emplace_back(observers.back(), slips[m]);
    Observer* view = scenes[m]->observe.slip_events ? static_cast<Observer*>(&with_slips.back()) : &observers.back();
    views.push_back({view, scenes[m]->duration()});
  }
  auto integrator = make_integrator(longest.run);
  FanOut fan(std::move(views), longest.run.sample_dt_s,
             [&](double t, double t_end) { return integrator->samples_within(t, t_end); });
  integrator->run(chain, state, longest.duration(), longest.run.sample_dt_s, fan);

  std::vector<RunResult> out;
  for (std::size_t m = 0; m < scenes.size(); ++m) {
    RunResult r = observed(observers[m], chain, rep);
    const auto& v = fan.views()[m];
    r.steps = m == 0 ? state.steps : v.steps;
    r.rhs_evals = m == 0 ? state.rhs_evals : v.rhs_evals;
    r.switches = m == 0 ? state.switches : v.switches;
    r.t_end_s = m == 0 ? state.t : std::min(state.t, v.t_end);
    if (scenes[m]->observe.slip_events) r.slip_events = slips[m].record();
    out.push_back(std::move(r));
  }
  out[0].wall_s = seconds_since(wall0);
  out[0].cpu_s = thread_cpu_s() - cpu0;
  out[0].work = state.work;  // like the wall time: the others' work is in this run
  return out;
}

}  // namespace sb::ensemble_detail
