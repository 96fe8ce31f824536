// One repetition of a scene on a run of its own: the chain drawn for it, the integrator, its
// observer (with the slip-event observer on the switches when the scene asks for them).
#include <chrono>

#include "springblock/ensemble/observation.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/switch_tap.hpp"

namespace sb {

using ensemble_detail::seconds_since;
using ensemble_detail::thread_cpu_s;

RunResult run_repetition(const Scene& scene, int rep, const std::atomic<bool>* interrupt,
                         std::atomic<std::int64_t>* progress_ns) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_s();
  const Chain chain = build_chain(scene, rep);
  State state = State::at_rest(chain);
  state.work.timed = scene.observe.timed_work;
  FrictionObserver obs(ensemble_detail::observer_config(scene, chain, rep, interrupt, progress_ns));
  SlipEventObserver slips;
  SwitchTap with_slips(obs, slips);
  auto integrator = make_integrator(scene.run);
  integrator->run(chain, state, scene.duration(), scene.run.sample_dt_s,
                  scene.observe.slip_events ? static_cast<Observer&>(with_slips) : obs);

  RunResult r = ensemble_detail::observed(obs, chain, rep);
  if (scene.observe.slip_events) r.slip_events = slips.record();
  r.steps = state.steps;
  r.rhs_evals = state.rhs_evals;
  r.switches = state.switches;
  r.work = state.work;
  r.t_end_s = state.t;
  r.wall_s = seconds_since(wall0);
  r.cpu_s = thread_cpu_s() - cpu0;
  return r;
}

}  // namespace sb
