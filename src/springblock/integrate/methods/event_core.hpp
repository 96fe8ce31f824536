#pragma once
// What the evolve steps of one event-method run share (the layers are in event_run.hpp): the
// chain and its state, the observer and its sample clock, the switching rules, the exact runs
// (their store and the active set's classification) and which blocks switched when. And the
// operations every evolve step needs, written once: the next stop and the closed-form event due
// there, a switch of the flagged blocks, a sample, a promotion of short runs.
#include <cstdint>
#include <vector>

#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/events/switching.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/integrate/methods/event_options.hpp"
#include "springblock/model.hpp"
#include "springblock/observe/observer.hpp"
#include "springblock/sample_schedule.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

// When the stepped runs changed, and which blocks switched since. Every change to the stepped
// runs that a stepper did not make itself (a reclassification, a promotion, time moved past
// them) starts a new epoch; a block that switches takes the epoch of its switch. A stepper keeps
// what it built in epoch k (a projection, a Dormand-Prince stage) while the epoch is still k, and
// a run of it while nothing in or beside the run has switched after k.
class Epochs {
 public:
  explicit Epochs(int N) : switched_(N, 0) {}
  std::int64_t now() const { return now_; }
  void next() { ++now_; }
  void switched(const std::vector<int>& blocks) {
    ++now_;
    for (int i : blocks) switched_[i] = now_;
  }
  // Per block, the epoch of its last switch (0: none).
  const std::int64_t* switched() const { return switched_.data(); }

 private:
  std::vector<std::int64_t> switched_;
  std::int64_t now_ = 0;
};

class EventCore {
 public:
  EventCore(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, const EventOptions& opt);

  // The end of the next evolve step: the next sample, the end of the run or the next
  // closed-form event, whichever is first (t), and that event.
  struct Stop {
    double t;
    ActiveSet::Next event;
    // A step clipped to t ends at the event.
    bool reached(bool clipped) const { return clipped && t == event.t; }
  };
  Stop next_stop() const;
  // At the closed-form event e, due now: a cut-off modal search is continued (returns false), a
  // switch is flagged (returns true: the caller brings what the switch reads to s.t and switches).
  bool take_event(const ActiveSet::Next& e);

  // The first classification, the first sample (the start of the run), and the end.
  void begin();
  void finish();
  // Apply the switching rules to the flagged blocks at s.t, after the exact runs the switch reads
  // are brought to s.t (bring_runs: a quiet phase has brought every block there itself); then
  // classify the runs again.
  void switch_now(bool bring_runs = true);
  // Every sliding block is flagged: the switch may leave nothing sliding (only flagged blocks
  // switch, and one that starts stops none).
  bool may_go_quiet() const;
  // A sample at s.t if one is due; write_runs() first brings the stepped runs to s.t.
  template <class Write>
  void sample_if_due(Write&& write_runs);
  void sample_if_due() {
    sample_if_due([] {});
  }
  // After a step that switched nothing: short runs that have moved long enough become modal
  // (ActiveSet::promote_runs), from the state at s.t, which write_runs() brings there first.
  template <class Write>
  void promote(Write&& write_runs);
  // Nothing to step (every mobile run is exact): to the next event or sample.
  void jump();

  const Chain& c;
  State& s;
  Observer& obs;
  const EventOptions opt;
  const double t_end;
  SampleSchedule clock;
  Switching sw;
  RunStore store;
  ActiveSet active;
  Epochs epochs;

 private:
  void reclassify(bool from_scratch);
};

template <class Write>
void EventCore::sample_if_due(Write&& write_runs) {
  if (!clock.due(s.t)) return;
  WorkTimer timer(s.work, s.work.sampling_s);
  ++s.work.samples;
  write_runs();
  if (!opt.active_forces || obs.needs_positions_at(s.t))
    active.materialise(s.t, s.u.data(), s.v.data(), true, opt.ends_only);
  else
    active.materialise_live(s.t, s.u.data(), s.v.data());
  if (opt.active_forces) {
    // The forces known at the sample serve it whether or not the positions are written too, so a
    // sample's value does not depend on whether some observer needs the positions there.
    obs.sample_active(c, s, active.forces().view());
    active.forces_delivered();
  } else {
    obs.sample(c, s);
  }
  clock.advance();
}

template <class Write>
void EventCore::promote(Write&& write_runs) {
  if (!(s.t >= active.next_promotion())) return;
  WorkTimer timer(s.work, s.work.switching_s);
  // The promoted runs are projected from the state: the exact stepper writes its runs first (the
  // others are kept by its next projection: nothing beside them switched).
  write_runs();
  if (active.promote_runs(c, s)) epochs.next();
}

}  // namespace sb::event_detail
