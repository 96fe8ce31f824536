#pragma once
// The event method's exact stepper (an evolve step): the stepped runs move by their modes
// (linear/span_modes.hpp) and their events are found by the span screen
// (events/span_screen.hpp). A step ends at the grid step H, the next sample, the next
// closed-form event or the end of the run, whichever is first, or at an event found inside it;
// nothing is approximated, so there is no error control. At an event the runs are moved there by
// their closed form (no step is redone), written into the state, switched, and projected afresh
// before the next step, keeping the runs the switch did not touch.
#include <cstdint>

#include "springblock/integrate/events/span_screen.hpp"
#include "springblock/integrate/linear/span_modes.hpp"
#include "springblock/integrate/methods/event_core.hpp"

namespace sb::event_detail {

class ExactEvolve {
 public:
  explicit ExactEvolve(EventCore& core);
  // One step of the stepped runs (projected first if the stepped set changed since).
  void step();
  // The runs' modes are those of the current stepped set (projected in this epoch).
  bool valid() const { return valid_at_ == core_.epochs.now(); }
  // Their blocks' u, v at s.t written into the state (ends_only: the end rows of each run).
  void write(bool ends_only) { spans_.write(core_.s.u.data(), core_.s.v.data(), ends_only); }
  // The stepped runs pass to Dormand-Prince at s.t: the runs no switch touched since the last
  // projection were not written before it (write_for_switch) and are written now; the others
  // were, and have switched since. The next projection keeps none.
  void leave();
  double now() const { return spans_.now(); }

 private:
  // The runs projected afresh from the state at s.t.
  void project();
  // What a switch of the flagged blocks reads written (or everything, when it may stop every
  // sliding block: a quiet phase starts from the whole state); then the switch.
  void switch_now();
  // After a step: grooves-only runs whose modes have rung down leave the stepped set.
  void retire();

  EventCore& core_;
  SpanModes spans_;
  SpanScreen screen_;
  std::int64_t projected_at_ = -1;  // the epoch of the last projection
  std::int64_t valid_at_ = -1;      // the epoch the runs' modes are valid in (-1: none)
  double settle_ = 0;               // earliest time a grooves-only run among them has rung down
};

}  // namespace sb::event_detail
