#pragma once
// The event method's exact stepper (an evolve step): the stepped runs move by their modes
// (linear/span_modes.hpp) and their events are found by the span screen
// (events/span_screen.hpp). Nothing is approximated, so there is no error control, and the runs
// keep their own clocks: the runs that share a stuck border (whose force reads both) step on one
// clock, a group, and a group steps by H from its own time whenever the chain's time reaches the
// end of what its screen has looked over. The chain's time s.t moves to the earliest of: a
// group's event, the end of a group's clean step, the next sample, closed-form event or end of
// the run. So a run is cut only by its own events, not by those of every run sliding elsewhere
// in a long chain. At an event the group is moved there by its closed form, written into the
// state, switched, and projected afresh; a group whose runs and surroundings the switch did not
// touch keeps its clock and what its screen has found ahead. Every write into the state (a
// sample, a switch) evaluates the runs at s.t without moving their clocks.
#include <cstdint>
#include <vector>

#include "springblock/integrate/events/span_screen.hpp"
#include "springblock/integrate/linear/span_modes.hpp"
#include "springblock/integrate/methods/event_core.hpp"

namespace sb::event_detail {

class ExactEvolve {
 public:
  explicit ExactEvolve(EventCore& core);
  // One step of the earliest group, or the chain's time moved to the next thing due (projected
  // first if the stepped set changed since).
  void step();
  // The runs' modes are those of the current stepped set (projected in this epoch).
  bool valid() const { return valid_at_ == core_.epochs.now(); }
  // Their blocks' u, v at s.t written into the state (ends_only: the end rows of each run).
  void write(bool ends_only) { spans_.write(core_.s.t, core_.s.u.data(), core_.s.v.data(), ends_only); }
  // Another evolve step moves the chain next: the runs' clocks no longer follow it, so the next
  // projection keeps none of them.
  void pause() { in_step_ = false; }
  // The runs are the exact stepper's at s.t (nothing else has moved the chain since).
  bool in_step() const { return in_step_ && spans_.live(); }
  // The stepped runs pass to Dormand-Prince at s.t: the runs no switch touched since the last
  // projection were not written before it (write_for_switch) and are written now; the others
  // were, and have switched since. The next projection keeps none.
  void leave();

 private:
  // Runs k0 .. k1 - 1 of spans_ on one clock: at their time t0 (SpanModes::t0), their screen
  // clean over (t0, t1] or holding an event at t1 (the step of length h, 0 before the first; the
  // event at t0 + tau, +inf if none).
  struct Group {
    int k0, k1;
    int lo, hi;  // the blocks whose kind, run or switch its screen reads: its runs and borders
    double t1;
    double h = 0, tau = 0;
    bool event() const { return h > 0 && tau <= h; }
    SpanScreen::Watch watch{};
  };
  // The runs projected afresh from the state at s.t where they changed, and grouped; a group
  // whose runs were all kept and whose surroundings the last classification did not renew keeps
  // its clock and screen, every other is brought to s.t and screened afresh.
  void project();
  // Group g, at s.t with nothing screened ahead, steps by H.
  void step_group(Group& g);
  // Group g's event, the earliest in the chain, at s.t = g.t1 (with a closed-form event due at
  // the same instant, stop).
  void take_event(Group& g, const EventCore::Stop& stop);
  // What a switch of the flagged blocks reads written (or everything, when it may stop every
  // sliding block: a quiet phase starts from the whole state); then the switch.
  void switch_now();
  // After the chain's time moved with nothing switching: grooves-only runs whose modes have rung
  // down leave the stepped set, short runs become modal, a sample is taken if due.
  void moved_on();
  void retire();
  // A sample's rows: every run at s.t, or right after a switch the runs of the last projection
  // it did not write.
  void write_for_sample();

  EventCore& core_;
  SpanModes spans_;
  SpanScreen screen_;
  std::vector<Group> groups_, old_;  // in block order; old_: those of the previous projection
  std::int64_t projected_at_ = -1;   // the epoch of the last projection
  std::int64_t valid_at_ = -1;       // the epoch the runs' modes are valid in (-1: none)
  std::int64_t seen_ = 0;            // ActiveSet::classifications() at the last projection
  double settle_ = 0;                // earliest time a grooves-only run among them has rung down
  bool in_step_ = false;             // see in_step()
};

}  // namespace sb::event_detail
