// The event method's stepped evolve and its driver loop, per kernel variant (Coupled: internal
// springs; Damped: viscous damping), instantiated for the four at the end.
#include <algorithm>

#include "springblock/integrate/methods/event_run.hpp"

namespace sb::event_detail {

template <bool Coupled, bool Damped>
void EventRun::run() {
  sw_.sync(c_, s_);
  sw_.apply(c_, s_, true);
  if (!sw_.touched_list().empty()) obs_.switched(c_, s_, sw_.touched_list());
  reclassify(true);
  obs_.sample(c_, s_);
  while (s_.t < t_end_ && !obs_.wants_stop()) {
    if (opt_.fast_forward && sw_.n_sliding() == 0) {
      if (!quiet_phase()) return;  // the observer stopped the run inside it; its state is exact
    } else if (active_.stepped().empty()) {
      jump_exact();
    } else if (exact_now()) {
      evolve_exact();
    } else {
      evolve_stepped<Coupled, Damped>();
    }
  }
  if (spans_valid_) write_spans(false);
  active_.materialise(s_.t, s_.u.data(), s_.v.data());
}

// A trial step is shortened to land exactly on the next sample, the next closed-form crossing of
// a stuck block, or the end of the run. After it is accepted its continuous extension is searched
// for events; if one lies inside, the step is redone to exactly the earliest event time, every
// block whose event lies within the search window is switched at that instant, and stage 1 is
// recomputed (the right-hand side has jumped).
template <bool Coupled, bool Damped>
void EventRun::evolve_stepped() {
  const auto& spans = active_.stepped();
  if (!stage1_valid_) {
    WorkTimer timer(s_.work, s_.work.stepping_s);
    dp_.first_stage<Coupled, Damped>(c_, spans, s_.u.data(), s_.v.data(), s_.t, sw_.mobile(), sw_.f_kin());
    ++s_.rhs_evals;
    stage1_valid_ = true;
  }
  const auto crossing = active_.next_crossing();
  if (crossing.t <= s_.t) {
    if (crossing.recheck) {
      WorkTimer timer(s_.work, s_.work.switching_s);
      active_.recheck(c_, s_);  // nothing switched: stage 1 stays valid
    } else {
      sw_.flag(crossing.block);
      switch_now();
      stage1_valid_ = false;
    }
    return;
  }
  const double t_stop = std::min({clock_.next(), t_end_, crossing.t});
  bool clipped = false;
  const double h_try = control_.trial(s_.t, t_stop, clipped);
  const double err = attempt<Coupled, Damped>(spans, h_try);
  if (!StepControl::acceptable(err)) {
    ++s_.work.rejected_steps;
    control_.rejected(h_try, err);
    return;
  }
  double theta;
  {
    WorkTimer timer(s_.work, s_.work.event_location_s);
    theta = search_.locate(c_, s_, dp_, h_try, active_);
  }
  if (theta <= 1.0) {
    step_to_event<Coupled, Damped>(spans, h_try * theta, theta == 1.0 && clipped, t_stop);
    // A closed-form crossing due at the same instant switches with them.
    if (theta == 1.0 && clipped && t_stop == crossing.t && !crossing.recheck) sw_.flag(crossing.block);
    switch_now();
    stage1_valid_ = false;
    sample_if_due();
    return;
  }
  take_step_end(spans);
  dp_.accept_fsal();
  s_.t = clipped ? t_stop : s_.t + h_try;
  ++s_.steps;
  control_.accepted(h_try, err, clipped);
  if (clipped && t_stop == crossing.t && crossing.recheck) {
    WorkTimer timer(s_.work, s_.work.switching_s);
    active_.recheck(c_, s_);
  } else if (clipped && t_stop == crossing.t) {
    sw_.flag(crossing.block);
    switch_now();
    stage1_valid_ = false;
  } else {
    // Ringing grooves whose transient has died leave the stepped set (stage 1 of the others
    // stays valid: nothing switched).
    {
      WorkTimer timer(s_.work, s_.work.switching_s);
      active_.retire_settled(c_, s_);
    }
    promote_runs();
  }
  sample_if_due();
}

template <bool Coupled, bool Damped>
double EventRun::attempt(const std::vector<BlockRange>& spans, double h) {
  WorkTimer timer(s_.work, s_.work.stepping_s);
  ++s_.work.stepped_attempts;
  for (const auto& sp : spans) s_.work.block_steps += sp.hi - sp.lo;
  const double err = dp_.attempt<Coupled, Damped>(c_, spans, s_.u.data(), s_.v.data(), s_.t, h, sw_.mobile(),
                                                  sw_.f_kin(), control_.atol_u(), control_.atol_v(), control_.rtol());
  s_.rhs_evals += 6;
  return err;
}

// Redo the step to h_event (the earliest event) and flag the blocks found there. at_stop: the
// event is at the very end of a step clipped to t_stop, which is then the time exactly.
template <bool Coupled, bool Damped>
void EventRun::step_to_event(const std::vector<BlockRange>& spans, double h_event, bool at_stop, double t_stop) {
  if (h_event > 0.0) {
    ++s_.work.event_steps;
    attempt<Coupled, Damped>(spans, h_event);
    take_step_end(spans);
    s_.t = at_stop ? t_stop : s_.t + h_event;
    ++s_.steps;
  }
  for (int i : search_.hits()) sw_.flag(i);
}

template void EventRun::run<true, true>();
template void EventRun::run<true, false>();
template void EventRun::run<false, true>();
template void EventRun::run<false, false>();

}  // namespace sb::event_detail
