// The active set's exact events: after a classification, the next event time of every contact
// block whose surroundings changed (a stuck block's closed-form or modal threshold crossing, a
// modal sliding block's stop), kept in the EventQueue.
#include <algorithm>
#include <cmath>

#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/numerics/affine_crossing.hpp"
#include "springblock/infinity.hpp"

namespace sb::event_detail {

// Closed-form crossings and the kept modal events first, then the fresh modal searches
// (finish_events).
void ActiveSet::update_events(const Chain& c, const State& s, const std::uint8_t* touched, bool all) {
  work_.pending.clear();
  if (all) {
    work_.cand.resize(N());
    for (int i = 0; i < N(); ++i) work_.cand[i] = i;
  } else {
    collect_candidates(s, touched);
  }
  for (int i : work_.cand) {
    if (c.contact[i] && s.dir[i] != 0) forces_.sliding(i, s.dir[i] * c.f_kinetic[i]);
    if (!c.contact[i] || (s.dir[i] != 0 && kind_[i] != kModal)) {
      events_.set(i, kInf, false);
    } else if (s.dir[i] != 0) {
      if (prev_.fresh[i]) events_.set(i, kInf, false), work_.pending.push_back(i);
    } else {
      // A stuck block keeps its event time unless something next to it changed: it does not
      // move, nor do its stuck neighbours, and a settled or kept modal neighbour follows the
      // same path as when the time was found.
      bool changed = all || switched(s, touched, i) || switched(s, touched, i - 1) ||
                     switched(s, touched, i + 1) || prev_.kind[i] != kStuck;
      for (int j : {i - 1, i + 1})
        if (j >= 0 && j < N()) changed = changed || kind_[j] != prev_.kind[j] || prev_.fresh[j];
      if (changed && !refresh_stuck(c, s, i)) work_.pending.push_back(i);
    }
  }
  // The previous classification is forgotten: every block whose dir or kind changed is a
  // candidate.
  for (int i : work_.cand) prev_.dir[i] = s.dir[i], prev_.kind[i] = kind_[i];
  finish_events(c, s);
}

bool ActiveSet::beside(int i, Kind k) const {
  return rules_.K_int > 0 && ((i > 0 && kind_[i - 1] == k) || (i + 1 < N() && kind_[i + 1] == k));
}

bool ActiveSet::refresh_stuck(const Chain& c, const State& s, int i) {
  // Beside a stepped run it is watched: the step's dense output finds its crossing. Beside a
  // modal run (and no stepped one) it is searched by finish_events.
  const bool watched = beside(i, kStepped);
  if (watched || beside(i, kModal)) {
    events_.set(i, kInf, false);
    forces_.live(i);
    return watched;
  }
  // Otherwise its force is affine: a settled neighbour follows its path, any other is stuck.
  double a = c.k_s(i) * (c.v_slider * s.t - s.u[i]), b = c.k_s(i) * c.v_slider;
  if (rules_.K_int > 0) {
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= N()) continue;
      const double k_ij = c.spring_between(i, j);
      if (kind_[j] == kSettled) {
        a += k_ij * (path_u(j, s.t) - s.u[i]);
        b += k_ij * path_slope(j);
      } else {
        a += k_ij * (s.u[j] - s.u[i]);
      }
    }
  }
  forces_.affine(i, a - b * s.t, b);  // a + b tau with tau = t - s.t
  events_.set(i, s.t + affine_crossing(a, b, c.f_static[i]), false);
  return true;
}

void ActiveSet::search_modal(const Chain& c, const State& s, int i, double limit) {
  ModalRuns::Found f;
  if (s.dir[i] != 0) {
    f = modal_.stop_time(c, s, i, prev_.fresh[i] != 0, limit);
  } else {
    double base[2] = {0, 0}, nb_B[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      const int j = side == 0 ? i - 1 : i + 1;
      if (j < 0 || j >= N()) continue;
      if (kind_[j] == kSettled) base[side] = path_u(j, s.t), nb_B[side] = path_slope(j);
      else base[side] = s.u[j];
    }
    f = modal_.crossing_time(c, s, i, base, nb_B, limit);
  }
  // Cut off at the limit: search again from there if it ever becomes the next event.
  events_.set(i, std::isfinite(f.t) ? f.t : f.limited ? f.resume : kInf, !std::isfinite(f.t) && f.limited);
}

void ActiveSet::finish_events(const Chain& c, const State& s) {
  // Each fresh modal search goes only as far as the earliest event that can make it stale
  // (local_limit): most of them never become the next event, and one cut off is searched again
  // when it does (recheck()).
  events_.refresh();
  for (int i : work_.pending) {
    search_modal(c, s, i, std::min(local_limit(i), rules_.t_end));
    events_.offer(i);
  }
  work_.pending.clear();
}

// A search of block i reads its own run or the modal or settled runs beside it, and its
// neighbours; only a switch in those blocks or at those runs' borders changes them, and that
// searches i again. So the search need go no further than the earliest real event among them
// (rechecks are not events: each is at least its time, and two rechecks limited by each other
// would not progress). With the whole chain's earliest event as the limit, a long chain's searches
// would be cut at events far away and resumed from scratch, a cost growing with N. A stepped run
// among them or beside them can switch at any step without an entry in the queue: then the
// chain's earliest real event.
double ActiveSet::local_limit(int i) const {
  double t = kInf;
  bool unknown = false;  // a stepped run can switch a block at any step, with no entry here
  auto stepped = [&](int k) { return k >= 0 && k < N() && kind_[k] == kStepped; };
  auto take = [&](int k) {
    if (k < 0 || k >= N() || k == i) return;
    unknown = unknown || stepped(k - 1) || stepped(k) || stepped(k + 1);
    if (!events_.is_recheck(k)) t = std::min(t, events_.time(k));
  };
  take(i - 1), take(i + 1);
  for (int j : {i - 1, i, i + 1}) {
    if (j < 0 || j >= N() || (kind_[j] != kModal && kind_[j] != kSettled)) continue;
    const RunStore::Run& r = store_.run(j);
    take(r.lo - 1), take(r.hi);
    if (kind_[j] == kModal)
      for (int k = r.lo; k < r.hi; ++k) take(k);  // its sliding blocks' stops
  }
  return unknown ? events_.next_real() : t;
}

void ActiveSet::recheck(const Chain& c, const State& s) {
  const int i = events_.next().block;
  events_.set(i, kInf, false);
  prev_.fresh[i] = 0;
  work_.pending.assign(1, i);
  finish_events(c, s);
}

bool ActiveSet::retire_settled(const Chain& c, const State& s) {
  if (!rules_.settle_grooves) return false;
  bool changed = false;
  for (int k : list_.ringing) {
    Run& r = runs_[k];
    if (!settled_now(s, r.span)) continue;
    assign(c, s, r, kSettled);
    for (int i = r.span.lo; i < r.span.hi; ++i) prev_.kind[i] = kSettled;
    changed = true;
  }
  if (!changed) return false;
  list_stepped(s);
  // The stuck blocks beside a newly settled run may now have an affine force.
  for (const Run& r : runs_)
    if (r.kind == kSettled) renew_borders(c, s, r.span);
  finish_events(c, s);
  return true;
}

void ActiveSet::renew_borders(const Chain& c, const State& s, BlockRange r) {
  for (int i : {r.lo - 1, r.hi})
    if (i >= 0 && i < N() && c.contact[i] && s.dir[i] == 0 && events_.time(i) == kInf && !refresh_stuck(c, s, i))
      work_.pending.push_back(i);
}

bool ActiveSet::promote_runs(const Chain& c, const State& s) {
  if (!(s.t >= list_.next_promotion)) return false;
  bool changed = false;
  work_.visit.assign(list_.live.begin(), list_.live.end());
  std::size_t cursor = 0;
  for (int lo : work_.visit) {
    Run& r = seek(cursor, lo);
    if (r.kind != kStepped || r.grooves || r.span.hi - r.span.lo > rules_.modal_max || s.t < r.formed + rules_.promote_age)
      continue;
    // As a classification would treat a run that becomes modal: projected afresh (prev_.fresh), its
    // sliding blocks' stops and its stuck neighbours' crossings searched anew.
    assign(c, s, r, kModal);
    std::fill(prev_.kind.begin() + r.span.lo, prev_.kind.begin() + r.span.hi, kModal);
    changed = true;
    for (int i = r.span.lo; i < r.span.hi; ++i)
      if (c.contact[i] && s.dir[i] != 0) events_.set(i, kInf, false), work_.pending.push_back(i);
    renew_borders(c, s, r.span);  // they were watched beside it, so they have no event time
  }
  list_stepped(s);
  finish_events(c, s);
  return changed;
}

}  // namespace sb::event_detail
