#pragma once
// One run of the event method, in layers (after GSL's odeiv2):
//   step     the exact stepper's modes (linear/span_modes.hpp) or one Dormand-Prince trial
//            (step/dopri5.hpp) with its control (step_control.hpp);
//   evolve   advance to the next step end, event, sample or end of run, and switch there: a
//            quiet phase (QuietEvolve), an exact step (ExactEvolve), a Dormand-Prince step
//            (SteppedEvolve), or a jump when nothing is stepped (EventCore::jump). What they
//            share, and the operations they all need (the next stop and the closed-form event
//            due there, a switch, a sample), is EventCore;
//   driver   EventRun::run: the loop that chooses which evolve applies (EventDriven::run picks
//            the kernel variant for the chain's effects).
// The switching rules (events/switching.hpp), the classification of runs and their exact
// events (events/active_set.hpp), and the exact propagators (linear/) are the pieces the
// evolve steps combine; when an observation is due comes from the shared SampleSchedule.
#include <cstdint>
#include <memory>

#include "springblock/integrate/methods/event_core.hpp"
#include "springblock/integrate/methods/event_exact.hpp"
#include "springblock/integrate/methods/event_quiet.hpp"
#include "springblock/integrate/methods/event_stepped.hpp"

namespace sb::event_detail {

class EventRun {
 public:
  EventRun(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, const EventOptions& opt);
  // Integrate to t_end (or until the observer stops it). Coupled / Damped select the kernel.
  template <bool Coupled, bool Damped>
  void run();

 private:
  // Whether the exact stepper moves the stepped runs, decided once per epoch: while no stepped
  // run is longer than exact_max_run.
  bool exact_now();
  // The first turn with nothing sliding after something slid closes a slip event (the work
  // profile's unit), whether or not a quiet phase begins there.
  void close_slip_event();

  EventCore core_;
  std::unique_ptr<QuietEvolve> quiet_;  // with fast-forward
  std::unique_ptr<ExactEvolve> exact_;  // with the exact stepper
  SteppedEvolve stepped_;
  std::int64_t mode_at_ = -1;  // the epoch exact_mode_ was decided in
  bool exact_mode_ = false;
  std::int64_t slip_starts_seen_ = 0;  // s.work.slip_starts at the last turn with nothing sliding
};

}  // namespace sb::event_detail
