#include "springblock/observe/fan_out.hpp"
#include "springblock/sample_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sb {

FanOut::FanOut(std::vector<View> views, double sample_dt, Within within)
    : views_(std::move(views)), sample_dt_(sample_dt), within_(std::move(within)) {
  if (views_.empty()) throw std::logic_error("FanOut: no views");
  for (const auto& v : views_)
    if (!v.obs) throw std::logic_error("FanOut: a view without an observer");
}

// Every method samples on SampleSchedule's grid, so the index is recovered by rounding.
long long FanOut::index_of(double t) const { return SampleSchedule::index_of(t, sample_dt_); }

void FanOut::record(View& v, const State& s) {
  v.steps = s.steps;
  v.rhs_evals = s.rhs_evals;
  v.switches = s.switches;
}

template <class Take>
void FanOut::deal(const State& s, Take take) {
  const long long k = index_of(s.t);
  for (auto& v : views_) {
    if (v.obs->wants_stop() || !within_(s.t, v.t_end) || k < v.next_k) continue;
    take(*v.obs);
    v.next_k = k + 1;
    record(v, s);
  }
}

void FanOut::sample(const Chain& c, const State& s) { deal(s, [&](Observer& o) { o.sample(c, s); }); }

void FanOut::sample_ringing(const Chain& c, const State& s, RingingForces& f) {
  deal(s, [&](Observer& o) { o.sample_ringing(c, s, f); });
}

// A view that does not take the sample still follows the forces' changes: its sums must hold the
// same leaves at its next sample as a run of its own would.
void FanOut::sample_active(const Chain& c, const State& s, const ActiveForces& f) {
  const long long k = index_of(s.t);
  for (auto& v : views_) {
    if (v.obs->wants_stop()) continue;
    if (!within_(s.t, v.t_end) || k < v.next_k) {
      v.obs->follow_forces(c, s, f);
      continue;
    }
    v.obs->sample_active(c, s, f);
    v.next_k = k + 1;
    record(v, s);
  }
}

void FanOut::follow_forces(const Chain& c, const State& s, const ActiveForces& f) {
  for (auto& v : views_)
    if (!v.obs->wants_stop()) v.obs->follow_forces(c, s, f);
}

bool FanOut::takes_active_forces() const {
  return std::all_of(views_.begin(), views_.end(), [](const View& v) { return v.obs->takes_active_forces(); });
}

void FanOut::switched(const Chain& c, const State& s, SwitchedBlocks blocks) {
  for (auto& v : views_)
    if (!v.obs->wants_stop() && within_(s.t, v.t_end)) v.obs->switched(c, s, blocks);
}

// A run of its own offers a view the samples strictly before its end at once (a sample exactly at
// the end comes through sample(), see event_driven.cpp, uncoupled.cpp): one past the last of
// them in [k0, k_stop).
long long FanOut::end_index(const View& v, long long k0, long long k_stop, double dt) {
  long long hi = std::min<long long>(k_stop, static_cast<long long>(std::floor(v.t_end / dt)) + 2);
  while (hi > k0 && !(static_cast<double>(hi - 1) * dt < v.t_end)) --hi;
  return hi;
}

long FanOut::sample_affine(const Chain& c, const State& s, long k0, double dt, long n, const AffineForces& f) {
  if (n <= 0) return 0;
  const long long k_stop = static_cast<long long>(k0) + n;  // one past the stretch
  auto t_of = [dt](long long k) { return static_cast<double>(k) * dt; };
  long long reached_min = k_stop;
  for (auto& v : views_) {
    if (v.obs->wants_stop()) continue;
    const long long hi = end_index(v, k0, k_stop, dt), lo = std::max<long long>(k0, v.next_k);
    long long reached = lo;
    if (lo < hi) {
      const long used = v.obs->sample_affine(c, s, static_cast<long>(lo), dt, static_cast<long>(hi - lo), f);
      if (used > 0) {
        v.next_k = lo + used;
        record(v, s);
      }
      reached = lo + used;
    }
    // Past its affine samples in this stretch, a view needs nothing more from it unless its
    // next sample (one exactly at its end) is inside the stretch: that one it takes from sample().
    if (reached >= hi && !(reached < k_stop && within_(t_of(reached), v.t_end))) reached = k_stop;
    reached_min = std::min(reached_min, reached);
  }
  return static_cast<long>(reached_min - k0);
}

long FanOut::sample_sums(const Chain& c, const State& s, long k0, double dt, long n, SampleStretch& stretch) {
  if (n <= 0) return 0;
  const long long k_stop = static_cast<long long>(k0) + n;
  auto t_of = [dt](long long k) { return static_cast<double>(k) * dt; };
  long long reached_min = k_stop;
  for (auto& v : views_) {
    if (v.obs->wants_stop()) continue;
    const long long hi = end_index(v, k0, k_stop, dt), lo = std::max<long long>(k0, v.next_k);
    // The block as a run of its own would offer it: to its end, or cut at the view's end (the
    // integrator's blocks end there too in such a run). Served one by one instead, a view's
    // last partial block summed differently from its own run's closed form and agreed with it
    // only while the difference rounded away (SharedTrajectory.*LongGrooves*).
    long long reached = lo;
    if (lo == k0 && hi > lo && v.obs->sample_sums(c, s, k0, dt, static_cast<long>(hi - k0), stretch) == hi - k0) {
      v.next_k = hi;
      record(v, s);
      reached = hi;
    }
    // Past its end inside the block a view needs nothing more from it, unless its next sample
    // (one exactly at its end) is inside: that one it takes from sample().
    if (reached >= hi && !(reached < k_stop && within_(t_of(reached), v.t_end))) reached = k_stop;
    reached_min = std::min(reached_min, reached);
  }
  return static_cast<long>(reached_min - k0);
}

bool FanOut::needs_positions_at(double t) const {
  const long long k = index_of(t);
  return std::any_of(views_.begin(), views_.end(), [&](const View& v) {
    return !v.obs->wants_stop() && within_(t, v.t_end) && k >= v.next_k && v.obs->needs_positions_at(t);
  });
}

bool FanOut::wants_stop() const {
  return std::all_of(views_.begin(), views_.end(), [](const View& v) { return v.obs->wants_stop(); });
}

bool FanOut::reads_groove_interiors() const {
  return std::any_of(views_.begin(), views_.end(), [](const View& v) { return v.obs->reads_groove_interiors(); });
}

bool FanOut::reads_only_friction() const {
  return std::all_of(views_.begin(), views_.end(), [](const View& v) { return v.obs->reads_only_friction(); });
}

}  // namespace sb
