#include "springblock/integrate/linear/modal_runs.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace sb::event_detail {
namespace {

// The sample recurrence restarts from the closed form this often, so its round-off never
// accumulates (the same rule as the quiet phase's samples).
constexpr int kSampleResync = 64;

}  // namespace

ModalRuns::ModalRuns(const Chain& c, RunStore& store)
    : store_(store),
      run_of_(c.N, -1),
      cursor_(c.N),
      scratch_(c.N),
      velocity_(c.N) {}

void ModalRuns::add(const Chain& c, const State& s, int lo, int hi, bool grooves) {
  const RunStore::Run& rec =
      store_.project(c, {lo, hi}, s.t, s.u.data(), s.v.data(), s.dir.data(), RunStore::kModal);
  const Ends ends{rec.shape, {store_.A(lo), store_.A(hi - 1)}, {store_.B(lo), store_.B(hi - 1)}};
  Run run{lo, hi, ends, grooves};
  if (grooves) run.settled_after = s.t + store_.envelope(rec).time_below(settle_.u, settle_.v);
  for (int i = lo; i < hi; ++i) run_of_[i] = static_cast<int>(runs_.size());
  runs_.push_back(run);
}

// The runs' order in runs_ means nothing (each writes and searches its own blocks), so the last
// one fills the gap.
void ModalRuns::drop(int lo) {
  const int k = run_of_[lo];
  for (int i = runs_[k].lo; i < runs_[k].hi; ++i) run_of_[i] = -1;
  if (store_.owner(lo) == RunStore::kModal) store_.drop(lo);
  if (k + 1 < static_cast<int>(runs_.size())) {
    runs_[k] = runs_.back();
    for (int i = runs_[k].lo; i < runs_[k].hi; ++i) run_of_[i] = k;
  }
  runs_.pop_back();
}

const ModalRuns::Run& ModalRuns::scratch_at(int i, double t) {
  Run& r = runs_[run_of_[i]];
  if (r.scratch_t == t) return r;
  store_.coords(record(r), t, scratch_.q.data(), scratch_.p.data());
  r.scratch_t = t;
  return r;
}

void ModalRuns::row_taylor(int i, double t, int deg, double* c) {
  scratch_at(i, t);
  store_.taylor(i, t, scratch_.q.data(), scratch_.p.data(), deg, c);
}

void ModalRuns::materialise(double t, double* u, double* v, bool at_sample, Rows rows) {
  const double sample_dt = store_.shapes().sample_dt();
  for (Run& r : runs_) {
    const double* q = cursor_.q.data();
    const double* qd = cursor_.p.data();
    const bool step = at_sample && sample_dt > 0 &&
                      std::fabs((t - r.tc) - sample_dt) <= 1e-9 * sample_dt && r.since + 1 < kSampleResync;
    if (step) {
      r.ends.shape->step_sample(cursor_.q.data() + r.lo, cursor_.p.data() + r.lo);
      ++r.since;
    } else if (at_sample) {
      store_.coords(record(r), t, cursor_.q.data(), cursor_.p.data());
      r.since = 0;
    } else {
      scratch_at(r.lo, t);  // off-sample evaluations must not move the cursor
      q = scratch_.q.data(), qd = scratch_.p.data();
    }
    if (at_sample) r.tc = t;
    if (rows == Rows::kEnds) {
      // The copy in r.ends holds while the run keeps the record it was projected into.
      assert(r.ends.shape == record(r).shape && r.ends.A[1] == store_.A(r.hi - 1) && r.ends.B[0] == store_.B(r.lo));
      double first, last;
      r.ends.shape->end_rows(q + r.lo, first, last);
      u[r.lo] = r.ends.A[0] + r.ends.B[0] * t + first;
      u[r.hi - 1] = r.ends.A[1] + r.ends.B[1] * t + last;
      continue;
    }
    store_.write(record(r), t, q, qd, u, v, rows == Rows::kGrooveEnds && r.grooves);
  }
}

void ModalRuns::materialise_run(int i, double t, double* u, double* v) {
  const Run& r = scratch_at(i, t);
  store_.write(record(r), t, scratch_.q.data(), scratch_.p.data(), u, v);
}

}  // namespace sb::event_detail
