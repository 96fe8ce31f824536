#pragma once
// Event-driven integrator: switching times located to the integration accuracy.
//
//  * Active phase (some contact block slides): only the pieces of the chain that move are
//    stepped (active_set.hpp: runs holding a sliding block, and grooves still ringing; settled
//    grooves are affine in t and stuck blocks with no stepped neighbour have closed-form
//    threshold times, which end the step exactly when they are due; runs of at most
//    modal_max_run blocks that keep moving, and grooves-only runs of at most modal_max_groove,
//    are propagated exactly by their modes and take no step at all, see modal_runs.hpp and
//    ActiveSet::promote_runs; with nothing left to
//    step the loop jumps from event to event). Dormand-Prince 5(4) with error control
//    (rtol = tol, atol = tol times the natural scales F_n/K_s and omega_s F_n/K_s). A switch
//    brings only the exact runs it reads to its time (ActiveSet::materialise_near). After each
//    accepted trial step the continuous extension is searched for switching events (a sliding
//    block's v dir falls to 0; a stuck block's |F| rises to f_static), sampled at the middle and
//    end of the step and refined to round-off in t (first_root.hpp). The step is then redone to
//    exactly the earliest event time, every block whose event lies within 1e-12 of the step from
//    it is switched at that instant (in block order), and integration restarts (the right-hand
//    side has jumped).
//  * Quiet phase (every contact block stuck): propagated exactly (quiet_phase.hpp); the next
//    threshold crossing is found without stepping. Samples inside it are exact, except that an
//    observer of contact forces only gets groove modes below the settle scales dropped
//    (QuietPhase::set_sample_scales); once every groove has rung down, the observer may take the
//    samples as one affine stretch (sample_affine).
// Samples in the active phase are hit exactly by shortening the step that would pass them.
// A chain without internal springs (K_int = 0) is solved exactly block by block instead
// (uncoupled.hpp), unless fast-forward is off.
#include <string>
#include <vector>

#include "springblock/integrate/integrator.hpp"
#include "springblock/integrate/methods/clock_audit.hpp"
#include "springblock/run_control.hpp"

namespace sb {

class EventDriven final : public Integrator {
 public:
  // fast_forward = false integrates quiet phases with Dormand-Prince too (for testing the
  // exact propagator against the stepper).
  explicit EventDriven(double tol, bool fast_forward = true) : tol_(tol), fast_forward_(fast_forward) {}
  void run(const Chain& chain, State& state, double t_end, double sample_dt, Observer& obs) override;
  std::string name() const override { return "event"; }
  // Diagnostics: when set, the time of every instant at which a switch happened is appended.
  void set_switch_log(std::vector<double>* log) { switch_log_ = log; }
  // Mobile runs up to this many blocks are propagated exactly by their modes instead of being
  // stepped (active_set.hpp, modal_runs.hpp); 0 steps every run. Only with fast-forward on.
  void set_modal_max_run(int n) { modal_max_run_ = n; }
  // Ringing groove-only runs up to this many blocks are modal too (they have no stops to search).
  void set_modal_max_groove(int n) { modal_max_groove_ = n; }
  // The stepped runs move by their modes (exact) instead of Dormand-Prince steps while none is
  // longer than max_run blocks (only with fast-forward on).
  void set_exact_stepper(bool on, int max_run = kDefaultExactMaxRun) { exact_stepper_ = on, exact_max_run_ = max_run; }
  // For the tests: the exact stepper's groups that keep their clocks are checked (ClockAudit).
  void set_clock_audit(ClockAudit* audit) { audit_ = audit; }

 private:
  double tol_;
  bool fast_forward_;
  int modal_max_run_ = kDefaultModalMaxRun;
  int modal_max_groove_ = kDefaultModalMaxGroove;
  bool exact_stepper_ = true;
  int exact_max_run_ = kDefaultExactMaxRun;
  std::vector<double>* switch_log_ = nullptr;
  ClockAudit* audit_ = nullptr;
};

}  // namespace sb
