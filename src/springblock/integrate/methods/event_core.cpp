#include "springblock/integrate/methods/event_core.hpp"

#include <algorithm>

#include "springblock/integrate/methods/step_control.hpp"

namespace sb::event_detail {

EventCore::EventCore(const Chain& c_, State& s_, double t_end_, double sample_dt, Observer& obs_,
                     const EventOptions& opt_)
    : c(c_),
      s(s_),
      obs(obs_),
      opt(opt_),
      t_end(t_end_),
      clock(sample_dt, s_.t),
      sw(c_.N),
      store(c_),
      // Settled grooves are a form of fast-forward (they drop a transient below the tolerance),
      // so they follow the same switch; the closed-form crossings of stuck blocks are exact
      // either way. Their scales are the Dormand-Prince stepper's tolerances, whichever stepper
      // runs.
      active(c_, store, opt_.fast_forward, StepControl(c_, opt_.tol).atol_u(), StepControl(c_, opt_.tol).atol_v(),
             opt_.modal_max_run, opt_.modal_max_groove, t_end_),
      epochs(c_.N) {
  store.shapes().set_sample_dt(sample_dt);
}

EventCore::Stop EventCore::next_stop() const {
  const ActiveSet::Next e = active.next_crossing();
  return {std::min({clock.next(), t_end, e.t}), e};
}

bool EventCore::take_event(const ActiveSet::Next& e) {
  if (e.recheck) {
    WorkTimer timer(s.work, s.work.switching_s);
    active.recheck(c, s);  // nothing switched: every step's state stays as it is
    return false;
  }
  sw.flag(e.block);
  return true;
}

void EventCore::begin() {
  sw.sync(c, s);
  sw.apply(c, s, true);
  reclassify(true);
  obs.sample(c, s);
}

void EventCore::finish() { active.materialise(s.t, s.u.data(), s.v.data()); }

void EventCore::reclassify(bool from_scratch) {
  if (!sw.touched_list().empty()) obs.switched(c, s, sw.touched_list());
  if (from_scratch) active.rebuild(c, s);
  else active.update(c, s, sw.touched(), sw.touched_list());
  epochs.switched(sw.touched_list());
  sw.clear_touched();
}

bool EventCore::may_go_quiet() const {
  int stopping = 0;
  for (int i : sw.flagged()) stopping += s.dir[i] != 0;
  return stopping >= sw.n_sliding();
}

void EventCore::switch_now(bool bring_runs) {
  WorkTimer timer(s.work, s.work.switching_s);
  ++s.work.switch_instants;
  // Only the exact runs the switch reads or re-projects: a quiet phase that may follow brings the
  // rest itself (QuietEvolve::phase), and most switches that stop every sliding block are not
  // followed by one.
  if (bring_runs) active.materialise_near(s.t, s.u.data(), s.v.data(), sw.flagged());
  if (sw.apply(c, s) > 0 && opt.diag.switch_log) opt.diag.switch_log->push_back(s.t);
  reclassify(false);
}

void EventCore::jump() {
  const Stop stop = next_stop();
  if (stop.t > s.t) {
    s.t = stop.t;
    ++s.steps;  // one exact step (State::steps counts accepted steps, of any kind)
    ++s.work.exact_jumps;
  }
  if (stop.event.t <= s.t && take_event(stop.event)) switch_now();
  epochs.next();
  sample_if_due();
}

}  // namespace sb::event_detail
