#include "springblock/integrate/methods/event_exact.hpp"

#include <algorithm>

#include "springblock/integrate/numerics/infinity.hpp"

namespace sb::event_detail {

ExactEvolve::ExactEvolve(EventCore& core) : core_(core), spans_(core.c, core.store), screen_(core.c) {}

void ExactEvolve::project() {
  State& s = core_.s;
  WorkTimer timer(s.work, s.work.stepping_s);
  spans_.project(core_.c, s, core_.active.stepped(), core_.epochs.switched(), projected_at_);
  projected_at_ = valid_at_ = core_.epochs.now();
  screen_.rebuild(core_.c, s, spans_, core_.active);
  settle_ = kInf;
  for (int k = 0; k < static_cast<int>(spans_.spans().size()); ++k)
    settle_ = std::min(settle_, spans_.settled_after(k, core_.active.settle_eps_u(), core_.active.settle_eps_v()));
}

void ExactEvolve::leave() {
  spans_.write_untouched(core_.epochs.switched(), projected_at_, core_.s.u.data(), core_.s.v.data());
  spans_.forget();
}

void ExactEvolve::switch_now() {
  if (core_.may_go_quiet()) write(false);
  else spans_.write_near(core_.sw.flagged(), core_.s.u.data(), core_.s.v.data());
  core_.switch_now();
}

// A ringing run's envelope (a bound) says when it has surely rung down; the active set then
// judges it against its affine path from the state, as after a Dormand-Prince step, so every
// stepped run is written first.
void ExactEvolve::retire() {
  State& s = core_.s;
  if (s.t < settle_) return;
  WorkTimer timer(s.work, s.work.switching_s);
  write(false);
  if (core_.active.retire_settled(core_.c, s)) valid_at_ = -1;
  else settle_ = kInf;  // not reached again before the next projection
}

void ExactEvolve::step() {
  State& s = core_.s;
  if (!valid()) project();
  const EventCore::Stop stop = core_.next_stop();
  if (stop.event.t <= s.t) {
    if (core_.take_event(stop.event)) switch_now();
    return;
  }
  const bool clipped = s.t + spans_.H() >= stop.t;
  const double h = clipped ? stop.t - s.t : spans_.H();
  {
    WorkTimer timer(s.work, s.work.stepping_s);
    ++s.work.stepped_attempts;
    for (const auto& sp : core_.active.stepped()) s.work.block_steps += sp.hi - sp.lo;
    spans_.advance(h);
  }
  double tau;
  {
    WorkTimer timer(s.work, s.work.event_location_s);
    tau = screen_.locate(core_.c, s, spans_, core_.active, h);
  }
  const bool at_end = !(tau < h);
  const double t_new = !at_end ? s.t + tau : clipped ? stop.t : s.t + h;
  const bool reached = stop.reached(clipped);
  // At a sample right after a switch the runs are those of the last projection, still at s.t:
  // the switch wrote those it read, and the others are written here.
  auto write_for_sample = [&] {
    if (valid()) write(core_.opt.friction_only);
    else if (spans_.now() == s.t) spans_.write_untouched(core_.epochs.switched(), projected_at_, s.u.data(), s.v.data());
  };
  ++s.steps;
  if (tau <= h) {
    {
      WorkTimer timer(s.work, s.work.stepping_s);
      ++s.work.event_steps;
      if (at_end) spans_.take(t_new);
      else spans_.take_at(tau, t_new);
    }
    s.t = t_new;
    for (int i : screen_.hits()) core_.sw.flag(i);
    // A closed-form event due at the same instant switches with them.
    if (at_end && reached && !stop.event.recheck) core_.sw.flag(stop.event.block);
    switch_now();
    core_.sample_if_due(write_for_sample);
    return;
  }
  spans_.take(t_new);
  screen_.accept();
  s.t = t_new;
  if (reached) {
    if (core_.take_event(stop.event)) switch_now();
  } else {
    retire();
    core_.promote([&] {
      if (valid()) write(false);
    });
  }
  core_.sample_if_due(write_for_sample);
}

}  // namespace sb::event_detail
