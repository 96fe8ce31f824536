#include "springblock/integrate/methods/event_driven.hpp"

#include "springblock/integrate/methods/event_run.hpp"
#include "springblock/integrate/methods/uncoupled.hpp"

namespace sb {

void EventDriven::run(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs) {
  const auto e = c.effects();
  // Without internal springs every block is its own system: solved exactly, block by block
  // (uncoupled.hpp). With fast-forward off the stepper runs instead (the tests' reference).
  if (!e.coupled && fast_forward_) {
    event_detail::run_uncoupled(c, s, t_end, sample_dt, obs, switch_log_);
    return;
  }
  const event_detail::EventOptions opt{tol_,
                                       fast_forward_,
                                       modal_max_run_,
                                       modal_max_groove_,
                                       exact_stepper_ && fast_forward_,
                                       exact_max_run_,
                                       {switch_log_, audit_},
                                       !obs.reads_groove_interiors(),
                                       obs.reads_only_friction(),
                                       fast_forward_ && obs.takes_active_forces()};
  event_detail::EventRun run(c, s, t_end, sample_dt, obs, opt);
  if (e.coupled && e.damped) run.run<true, true>();
  else if (e.coupled) run.run<true, false>();
  else if (e.damped) run.run<false, true>();
  else run.run<false, false>();
}

}  // namespace sb
