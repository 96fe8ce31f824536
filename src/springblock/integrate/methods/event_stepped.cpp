#include "springblock/integrate/methods/event_stepped.hpp"

#include <algorithm>

namespace sb::event_detail {

template <bool Coupled, bool Damped>
void SteppedEvolve::step() {
  State& s = core_.s;
  const auto& spans = core_.active.stepped();
  if (stage1_at_ != core_.epochs.now()) {
    WorkTimer timer(s.work, s.work.stepping_s);
    // The stepped runs' stuck borders hold still through the stages; the stages start afresh
    // after every change to the stepped runs that this step did not make (the right-hand side
    // has jumped, or the runs are others).
    dp_.set_frozen(s.u.data(), spans);
    dp_.first_stage<Coupled, Damped>(core_.c, spans, s.u.data(), s.v.data(), s.t, core_.sw.mobile(), core_.sw.f_kin());
    ++s.rhs_evals;
    stage1_at_ = core_.epochs.now();
  }
  const EventCore::Stop stop = core_.next_stop();
  if (stop.event.t <= s.t) {
    if (core_.take_event(stop.event)) core_.switch_now();
    return;
  }
  bool clipped = false;
  const double h_try = control_.trial(s.t, stop.t, clipped);
  const double err = attempt<Coupled, Damped>(spans, h_try);
  if (!StepControl::acceptable(err)) {
    ++s.work.rejected_steps;
    control_.rejected(h_try, err);
    return;
  }
  const double theta = [&] {
    WorkTimer timer(s.work, s.work.event_location_s);
    return search_.locate(core_.c, s, dp_, h_try, core_.active);
  }();
  const bool reached = stop.reached(clipped);
  if (theta <= 1.0) {
    // The step redone to the earliest event (at the very end of a step clipped to stop.t, that is
    // the time exactly), and the blocks found there flagged.
    const double h_event = h_try * theta;
    if (h_event > 0.0) {
      ++s.work.event_steps;
      attempt<Coupled, Damped>(spans, h_event);
      take_step_end(spans);
      s.t = theta == 1.0 && clipped ? stop.t : s.t + h_event;
      ++s.steps;
    }
    for (int i : search_.hits()) core_.sw.flag(i);
    // A closed-form event due at the same instant switches with them.
    if (theta == 1.0 && reached && !stop.event.recheck) core_.sw.flag(stop.event.block);
    core_.switch_now();
    core_.sample_if_due();
    return;
  }
  take_step_end(spans);
  dp_.accept_fsal();
  s.t = clipped ? stop.t : s.t + h_try;
  ++s.steps;
  control_.accepted(h_try, err, clipped);
  if (reached) {
    if (core_.take_event(stop.event)) core_.switch_now();
  } else {
    // Ringing grooves whose transient has died leave the stepped set (stage 1 of the others
    // stays valid: nothing switched).
    {
      WorkTimer timer(s.work, s.work.switching_s);
      core_.active.retire_settled(core_.c, s);
    }
    core_.promote([] {});
  }
  core_.sample_if_due();
}

template <bool Coupled, bool Damped>
double SteppedEvolve::attempt(const std::vector<BlockRange>& spans, double h) {
  State& s = core_.s;
  WorkTimer timer(s.work, s.work.stepping_s);
  ++s.work.stepped_attempts;
  for (const auto& sp : spans) s.work.block_steps += sp.hi - sp.lo;
  const double err = dp_.attempt<Coupled, Damped>(core_.c, spans, s.u.data(), s.v.data(), s.t, h, core_.sw.mobile(),
                                                  core_.sw.f_kin(), control_.atol_u(), control_.atol_v(), control_.rtol());
  s.rhs_evals += 6;
  return err;
}

void SteppedEvolve::take_step_end(const std::vector<BlockRange>& spans) {
  State& s = core_.s;
  for (const auto& sp : spans) {
    std::copy(dp_.u1() + sp.lo, dp_.u1() + sp.hi, s.u.begin() + sp.lo);
    std::copy(dp_.v1() + sp.lo, dp_.v1() + sp.hi, s.v.begin() + sp.lo);
  }
}

template void SteppedEvolve::step<true, true>();
template void SteppedEvolve::step<true, false>();
template void SteppedEvolve::step<false, true>();
template void SteppedEvolve::step<false, false>();

}  // namespace sb::event_detail
