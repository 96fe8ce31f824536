// The event method's exact stepper: the evolve step that moves the stepped runs by their modes
// (linear/span_modes.hpp) and finds their events with the span screen (events/span_screen.hpp).
// It has the same shape as the Dormand-Prince evolve (event_evolve.cpp) without error control:
// a step ends at the grid step H, the next sample, the next closed-form event or the end of the
// run, whichever is first, or at an event found inside it. At an event the runs are moved there
// by their closed form (no step is redone), written into the state, switched, and projected
// afresh before the next step.
#include <algorithm>

#include "springblock/integrate/numerics/infinity.hpp"

#include "springblock/integrate/methods/event_run.hpp"

namespace sb::event_detail {

bool EventRun::exact_now() {
  if (!spans_) return false;
  if (mode_valid_) return exact_mode_;
  bool fits = true;
  for (const BlockRange& r : active_.stepped()) fits = fits && r.size() <= opt_.exact_max_run;
  if (!fits && exact_mode_ && spans_->now() == s_.t) {
    // Dormand-Prince steps from the state: the runs no switch touched since the last projection
    // were not written before it (write_for_switch); the others were, and have switched since.
    spans_->write_untouched(spans_switched_.data(), s_.u.data(), s_.v.data());
    spans_->forget();
  }
  exact_mode_ = fits;
  mode_valid_ = true;
  return fits;
}

void EventRun::project_spans() {
  WorkTimer timer(s_.work, s_.work.stepping_s);
  spans_->project(c_, s_, active_.stepped(), spans_switched_.data());
  for (int i : spans_switched_list_) spans_switched_[i] = 0;
  spans_switched_list_.clear();
  screen_->rebuild(c_, s_, *spans_, active_);
  spans_settle_ = kInf;
  const auto& runs = spans_->spans();
  for (std::size_t k = 0; k < runs.size(); ++k) {
    bool grooves = true;
    for (int i = runs[k].lo; i < runs[k].hi && grooves; ++i) grooves = !c_.contact[i];
    if (grooves)
      spans_settle_ = std::min(spans_settle_, spans_->settled_after(static_cast<int>(k), active_.settle_eps_u(),
                                                                    active_.settle_eps_v()));
  }
  spans_valid_ = true;
}

void EventRun::write_spans(bool ends_only) { spans_->write(s_.u.data(), s_.v.data(), ends_only); }

// Before a switch of the flagged blocks: what it reads of the runs (SpanModes::write_near), or
// everything when it may stop every sliding block (a quiet phase starts from the whole state).
void EventRun::write_for_switch() {
  if (may_go_quiet()) write_spans(false);
  else spans_->write_near(sw_.flagged(), s_.u.data(), s_.v.data());
}

// A ringing run's envelope (a bound) says when it has surely rung down; the active set then
// judges it against its affine path from the state, as after a Dormand-Prince step, so every
// stepped run is written first.
void EventRun::retire_spans() {
  if (s_.t < spans_settle_) return;
  WorkTimer timer(s_.work, s_.work.switching_s);
  write_spans(false);
  if (active_.retire_settled(c_, s_)) spans_valid_ = false;
  else spans_settle_ = kInf;  // not reached again before the next projection
}

void EventRun::evolve_exact() {
  if (!spans_valid_) project_spans();
  const auto crossing = active_.next_crossing();
  if (crossing.t <= s_.t) {
    if (crossing.recheck) {
      WorkTimer timer(s_.work, s_.work.switching_s);
      active_.recheck(c_, s_);  // nothing switched: the runs stay as they are
    } else {
      sw_.flag(crossing.block);
      write_for_switch();
      switch_now();
    }
    return;
  }
  const double t_stop = std::min({clock_.next(), t_end_, crossing.t});
  const bool clipped = s_.t + spans_->H() >= t_stop;
  const double h = clipped ? t_stop - s_.t : spans_->H();
  {
    WorkTimer timer(s_.work, s_.work.stepping_s);
    ++s_.work.stepped_attempts;
    for (const auto& sp : active_.stepped()) s_.work.block_steps += sp.hi - sp.lo;
    spans_->advance(h);
  }
  double tau;
  {
    WorkTimer timer(s_.work, s_.work.event_location_s);
    tau = screen_->locate(c_, s_, *spans_, active_, h);
  }
  const bool at_end = !(tau < h);
  const double t_new = !at_end ? s_.t + tau : clipped ? t_stop : s_.t + h;
  ++s_.steps;
  if (tau <= h) {
    {
      WorkTimer timer(s_.work, s_.work.stepping_s);
      ++s_.work.event_steps;
      if (at_end) spans_->take(t_new);
      else spans_->take_at(tau, t_new);
    }
    s_.t = t_new;
    for (int i : screen_->hits()) sw_.flag(i);
    // A closed-form crossing due at the same instant switches with them.
    if (at_end && clipped && t_stop == crossing.t && !crossing.recheck) sw_.flag(crossing.block);
    write_for_switch();
    switch_now();
    sample_if_due();
    return;
  }
  spans_->take(t_new);
  screen_->accept();
  s_.t = t_new;
  if (clipped && t_stop == crossing.t && crossing.recheck) {
    WorkTimer timer(s_.work, s_.work.switching_s);
    active_.recheck(c_, s_);
  } else if (clipped && t_stop == crossing.t) {
    sw_.flag(crossing.block);
    write_for_switch();
    switch_now();
  } else {
    retire_spans();
    promote_runs();
  }
  sample_if_due();
}

}  // namespace sb::event_detail
