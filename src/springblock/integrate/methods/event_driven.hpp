#pragma once
// Event-driven integrator: switching times located to the integration accuracy (the layers of
// one run are in event_run.hpp).
//  * Active phase (some contact block slides): only the runs that move are stepped; settled and
//    modal runs and the stuck blocks' crossings are exact (active_set.hpp). The stepped runs move
//    by their modes, the exact stepper (event_exact.hpp, the default), or by Dormand-Prince 5(4)
//    steps under the tolerance (event_stepped.hpp, step_control.hpp); with nothing stepped the
//    loop jumps from event to event. Events are located to round-off in t (event_search.hpp,
//    span_screen.hpp) and the blocks whose events meet switch together; a switch brings only the
//    exact runs it reads to its time.
//  * Quiet phase (every contact block stuck): propagated exactly to the next threshold crossing,
//    the samples inside served from the closed form (event_quiet.hpp).
// Samples are hit exactly: a step that would pass one ends there. A chain without internal springs
// (K_int = 0) is solved exactly block by block instead (uncoupled.hpp), unless fast-forward is off.
#include <string>
#include <vector>

#include "springblock/integrate/integrator.hpp"
#include "springblock/integrate/methods/event_options.hpp"
#include "springblock/run_control.hpp"

namespace sb {

class EventDriven final : public Integrator {
 public:
  // fast_forward = false integrates quiet phases with Dormand-Prince too (for testing the
  // exact propagator against the stepper).
  explicit EventDriven(double tol, bool fast_forward = true) : opt_{.tol = tol, .fast_forward = fast_forward} {}
  void run(const Chain& chain, State& state, double t_end, double sample_dt, Observer& obs) override;
  std::string name() const override { return "event"; }
  // Diagnostics: when set, the time of every instant at which a switch happened is appended.
  void set_switch_log(std::vector<double>* log) { opt_.diag.switch_log = log; }
  // Mobile runs up to this many blocks are propagated exactly by their modes instead of being
  // stepped (active_set.hpp, modal_runs.hpp); 0 steps every run. Only with fast-forward on.
  void set_modal_max_run(int n) { opt_.modal_max_run = n; }
  // Ringing groove-only runs up to this many blocks are modal too (they have no stops to search).
  void set_modal_max_groove(int n) { opt_.modal_max_groove = n; }
  // The stepped runs move by their modes (exact) instead of Dormand-Prince steps while none is
  // longer than max_run blocks (only with fast-forward on).
  void set_exact_stepper(bool on, int max_run = kDefaultExactMaxRun) {
    opt_.exact_stepper = on, opt_.exact_max_run = max_run;
  }
  // For the tests: the exact stepper's groups that keep their clocks are checked (ClockAudit).
  void set_clock_audit(ClockAudit* audit) { opt_.diag.audit = audit; }

 private:
  event_detail::EventOptions opt_;  // the observer's part is set by run()
};

}  // namespace sb
