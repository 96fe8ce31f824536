#include "springblock/integrate/methods/event_exact.hpp"

#include <algorithm>
#include <stdexcept>

#include "springblock/infinity.hpp"

namespace sb::event_detail {

ExactEvolve::ExactEvolve(EventCore& core) : core_(core), spans_(core.c, core.store), screen_(core.c) {}

void ExactEvolve::project() {
  State& s = core_.s;
  WorkTimer timer(s.work, s.work.stepping_s);
  old_.swap(groups_);
  groups_.clear();
  // An old group is stale where the last classification renewed a block in its [lo, hi). One
  // classification since the last projection lists what it renewed; none renewed nothing (a
  // promotion or a retirement changes only the runs it moves, and their groups with them); after
  // more than one (a phase of another evolve step between), nothing is known.
  const ActiveSet& active = core_.active;
  const std::int64_t since = active.classifications() - seen_;
  seen_ = active.classifications();
  const std::vector<int>& renewed = active.renewed();
  auto stale = [&](const Group& was) {
    const auto it = std::lower_bound(renewed.begin(), renewed.end(), was.lo);
    return since > 1 || (since == 1 && it != renewed.end() && *it < was.hi);
  };
  spans_.project(core_.c, s, active.stepped(), core_.epochs.switched(), projected_at_, in_step_);
  projected_at_ = valid_at_ = core_.epochs.now();
  const int n = spans_.count();
  ClockAudit* audit = core_.opt.diag.audit;
  std::size_t o = 0;  // the first old group not before the one being formed
  for (int k0 = 0; k0 < n;) {
    int k1 = k0 + 1;
    // A stuck block between two runs borders both.
    while (k1 < n && spans_.span(k1).lo == spans_.span(k1 - 1).hi + 1) ++k1;
    Group g{k0, k1, spans_.span(k0).lo - 1, spans_.span(k1 - 1).hi + 1, s.t};
    bool same = true;  // its runs kept, and they made one group before
    for (int k = k0; k < k1 && same; ++k) same = spans_.kept(k);
    while (o < old_.size() && old_[o].lo < g.lo) ++o;
    same = same && o < old_.size() && old_[o].lo == g.lo && old_[o].hi == g.hi;
    const bool keep = same && !stale(old_[o]);
    if (audit != nullptr && same) ++(keep ? audit->kept : audit->renewed);
    if (keep) {
      Group& was = old_[o];
      if (audit != nullptr && !screen_.current(s, spans_, active, was.watch))
        throw std::logic_error("exact stepper: a group kept its clock across a change its screen reads");
      g.t1 = was.t1, g.h = was.h, g.tau = was.tau;
      g.watch = std::move(was.watch);
    } else {
      spans_.bring(k0, k1, s.t);
      screen_.rebuild(core_.c, s, spans_, active, k0, k1, g.watch);
    }
    groups_.push_back(std::move(g));
    k0 = k1;
  }
  settle_ = kInf;
  for (int k = 0; k < n; ++k)
    settle_ = std::min(settle_, spans_.settled_after(k, active.settle_eps_u(), active.settle_eps_v()));
}

void ExactEvolve::leave() {
  spans_.write_untouched(core_.s.t, core_.epochs.switched(), projected_at_, core_.s.u.data(), core_.s.v.data());
  spans_.forget();
  groups_.clear();
  in_step_ = false;
}

void ExactEvolve::switch_now() {
  State& s = core_.s;
  if (core_.may_go_quiet()) write(false);
  else spans_.write_near(s.t, core_.sw.flagged(), s.u.data(), s.v.data());
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

void ExactEvolve::write_for_sample() {
  State& s = core_.s;
  if (valid()) write(core_.opt.friction_only);
  else if (in_step()) spans_.write_untouched(s.t, core_.epochs.switched(), projected_at_, s.u.data(), s.v.data());
}

void ExactEvolve::moved_on() {
  retire();
  core_.promote([&] {
    if (valid()) write(false);
  });
  core_.sample_if_due([&] { write_for_sample(); });
}

void ExactEvolve::step_group(Group& g) {
  State& s = core_.s;
  const double H = spans_.H();
  {
    WorkTimer timer(s.work, s.work.stepping_s);
    if (g.h > 0) spans_.take(g.k0, g.k1, g.t1), SpanScreen::accept(g.watch);  // its clean step, reached
    ++s.work.stepped_attempts;
    for (int k = g.k0; k < g.k1; ++k) s.work.block_steps += spans_.span(k).size();
    spans_.advance(g.k0, g.k1, H);
  }
  const double tau = [&] {
    WorkTimer timer(s.work, s.work.event_location_s);
    return screen_.locate(core_.c, s, spans_, core_.active, g.watch, spans_.t0(g.k0), H);
  }();
  ++s.steps;
  g.h = H, g.tau = tau;
  g.t1 = spans_.t0(g.k0) + (g.event() ? tau : H);
}

void ExactEvolve::take_event(Group& g, const EventCore::Stop& stop) {
  State& s = core_.s;
  {
    WorkTimer timer(s.work, s.work.stepping_s);
    ++s.work.event_steps;
    if (g.tau < g.h) spans_.take_at(g.k0, g.k1, g.tau, g.t1);
    else spans_.take(g.k0, g.k1, g.t1);
  }
  g.h = 0;
  for (int i : g.watch.hits()) core_.sw.flag(i);
  // A closed-form event due at the same instant switches with them.
  if (g.t1 == stop.t && stop.t == stop.event.t && !stop.event.recheck) core_.sw.flag(stop.event.block);
  switch_now();
  core_.sample_if_due([&] { write_for_sample(); });
}

void ExactEvolve::step() {
  State& s = core_.s;
  if (!valid()) project();
  in_step_ = true;
  const EventCore::Stop stop = core_.next_stop();
  if (stop.event.t <= s.t) {
    if (core_.take_event(stop.event)) switch_now();
    return;
  }
  Group& g = *std::ranges::min_element(groups_, {}, &Group::t1);  // the group whose screen has looked least far ahead
  if (g.t1 == s.t && !g.event()) {
    step_group(g);
    return;
  }
  if (g.t1 < stop.t || (g.event() && g.t1 == stop.t)) {
    // Nothing anywhere before g.t1: the chain's time moves there.
    s.t = g.t1;
    if (g.event()) take_event(g, stop);
    else moved_on();
    return;
  }
  s.t = stop.t;
  if (stop.t == stop.event.t) {
    if (core_.take_event(stop.event)) switch_now();
    core_.sample_if_due([&] { write_for_sample(); });
  } else {
    moved_on();
  }
}

}  // namespace sb::event_detail
