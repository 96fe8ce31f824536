#include "springblock/integrate/methods/event_driven.hpp"

#include "springblock/integrate/methods/event_run.hpp"
#include "springblock/integrate/methods/uncoupled.hpp"

namespace sb {

void EventDriven::run(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs) {
  const auto e = c.effects();
  // Without internal springs every block is its own system: solved exactly, block by block
  // (uncoupled.hpp). With fast-forward off the stepper runs instead (the tests' reference).
  if (!e.coupled && opt_.fast_forward) {
    event_detail::run_uncoupled(c, s, t_end, sample_dt, obs, opt_.diag.switch_log);
    return;
  }
  event_detail::EventOptions opt = opt_;
  opt.exact_stepper = opt.exact_stepper && opt.fast_forward;
  opt.ends_only = !obs.reads_groove_interiors();
  opt.friction_only = obs.reads_only_friction();
  opt.active_forces = opt.fast_forward && obs.takes_active_forces();
  event_detail::EventRun run(c, s, t_end, sample_dt, obs, opt);
  if (e.coupled && e.damped) run.run<true, true>();
  else if (e.coupled) run.run<true, false>();
  else if (e.damped) run.run<false, true>();
  else run.run<false, false>();
}

}  // namespace sb
