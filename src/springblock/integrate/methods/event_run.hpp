#pragma once
// One run of the event method, in layers (after GSL's odeiv2):
//   step     Dopri5 (step/dopri5.hpp): one trial step of the stepped runs, its error, its dense
//            output;
//   control  StepControl (step_control.hpp): the next step size;
//   evolve   EventRun::evolve_stepped / jump_exact / quiet_phase below: advance to the next
//            step end, event, sample or end of run, and switch there;
//   driver   EventRun::run: the loop that chooses which evolve applies (EventDriven::run picks
//            the kernel variant for the chain's effects).
// The switching rules (events/switching.hpp), the classification of runs and their exact
// events (events/active_set.hpp), and the exact propagators (linear/) are the pieces the
// evolve layer combines; when an observation is due comes from the shared SampleSchedule.
#include <cstdint>
#include <memory>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/events/event_search.hpp"
#include "springblock/integrate/events/span_screen.hpp"
#include "springblock/integrate/events/switching.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/integrate/linear/span_modes.hpp"
#include "springblock/integrate/methods/step_control.hpp"
#include "springblock/integrate/step/dopri5.hpp"
#include "springblock/model.hpp"
#include "springblock/observe/observer.hpp"
#include "springblock/sample_schedule.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

struct EventOptions {
  double tol;
  bool fast_forward;     // exact quiet phases, settled and modal runs (off: the tests' reference)
  int modal_max_run;     // see EventDriven::set_modal_max_run
  int modal_max_groove;  // see EventDriven::set_modal_max_groove
  bool exact_stepper;    // the stepped runs move by their modes (span_modes.hpp), not Dormand-Prince
  int exact_max_run;     // ... while no stepped run is longer than this (Dormand-Prince otherwise)
  std::vector<double>* switch_log;  // times of the instants with a switch (nullptr: none)
};

class EventRun {
 public:
  // All workspaces are allocated here, once per run.
  EventRun(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, const EventOptions& opt);
  // Integrate to t_end (or until the observer stops it). Coupled / Damped select the kernel.
  template <bool Coupled, bool Damped>
  void run();

 private:
  // Evolve: a quiet phase, exact to its first threshold crossing (event_quiet.cpp). Returns
  // false when the observer stopped the run inside it.
  bool quiet_phase();
  bool serve_quiet_samples(double t_next);
  void serve_quiet_sample();
  // Evolve: nothing to step (every mobile run is exact): jump to the next event or sample.
  void jump_exact();
  // Evolve: one trial step of the stepped runs, to its end or to the first event inside it.
  template <bool Coupled, bool Damped>
  void evolve_stepped();
  // Evolve, exact stepper: every stepped run advanced by its modes over one grid step (or to the
  // next event, sample or end), its events found by the span screen (event_exact.cpp).
  void evolve_exact();
  // Whether the exact stepper moves the stepped runs (decided after each classification); on a
  // change to Dormand-Prince the runs' blocks not yet written are written first.
  bool exact_now();
  // The exact stepper's runs projected afresh from the state at s.t, when a switch changed them.
  void project_spans();
  // Their blocks' u, v at s.t written into the state (all rows, or the end rows only).
  void write_spans(bool ends_only);
  void write_for_switch();
  // After a step: grooves-only runs whose modes have rung down leave the stepped set.
  void retire_spans();
  // After a step that switched nothing: short runs that have moved long enough become modal
  // (ActiveSet::promote_runs), from the state at s.t.
  void promote_runs();
  // The step layer: one Dormand-Prince trial of size h from s.t; returns its error (units of
  // the tolerance).
  template <bool Coupled, bool Damped>
  double attempt(const std::vector<BlockRange>& spans, double h);
  template <bool Coupled, bool Damped>
  void step_to_event(const std::vector<BlockRange>& spans, double h_event, bool at_stop, double t_stop);

  // After every switch: which runs are stepped, which stuck blocks are watched (from scratch at
  // the start of the run).
  void reclassify(bool from_scratch = false);
  // Apply the switching rules to the blocks flagged at s.t (see event_run.cpp).
  void switch_now();
  // Every sliding block is flagged: the switch may leave nothing sliding.
  bool may_go_quiet() const;
  // The stepped blocks take the end of the last attempted step.
  void take_step_end(const std::vector<BlockRange>& spans);
  void sample_if_due();
  // A sample served from the quiet-phase solution carries the run's counters too.
  void stamp_sample();
  // Quiet-phase samples once every groove has rung down: one affine stretch (returns false when
  // the observer took none, so the caller samples one by one).
  bool sample_affine_stretch(double t_next, bool& stopped);
  // A block of quiet-phase samples taken as sums over the modes (event_quiet.cpp).
  bool offer_block(double t_stop, bool& stopped, long long& next_offer);
  void took_samples(long used, bool& stopped);

  const Chain& c_;
  State& s_;
  const double t_end_;
  Observer& obs_;
  const EventOptions opt_;
  const bool ends_only_;  // the observer reads no groove interior
  StepControl control_;
  Dopri5 dp_;
  EventSearch search_;
  Switching sw_;
  // The exact runs' shapes and records, shared by the active set, the exact stepper and the
  // quiet phase (run_store.hpp).
  RunShapes shapes_;
  RunStore store_;
  ActiveSet active_;
  std::unique_ptr<QuietPhase> quiet_;
  // The exact stepper (opt.exact_stepper): the stepped runs' modes and their event screen, valid
  // while the stepped set is the one they were projected for.
  std::unique_ptr<SpanModes> spans_;
  std::unique_ptr<SpanScreen> screen_;
  bool spans_valid_ = false;
  bool mode_valid_ = false;  // exact_mode_ is decided for the current classification
  bool exact_mode_ = false;
  bool spans_friction_only_ = false;  // the observer reads friction forces only: end rows suffice
  double spans_settle_ = 0;           // earliest time a grooves-only run among them has rung down
  std::vector<std::uint8_t> spans_switched_;  // per block: switched since the last projection
  std::vector<int> spans_switched_list_;
  SampleSchedule clock_;
  State sample_;                  // buffer for samples served from the exact quiet-phase solution
  std::vector<double> fa_, fb_;   // affine contact forces a + b t once a quiet phase's modes died
  bool affine_ready_ = false;
  bool stage1_valid_ = false;
  std::int64_t slip_starts_seen_ = 0;  // s.work.slip_starts at the last quiet phase
};

}  // namespace sb::event_detail
