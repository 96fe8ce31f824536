#include "springblock/integrate/linear/span_modes.hpp"

#include <algorithm>

namespace sb::event_detail {
namespace {

// Grid steps between restarts of the recurrence from the closed form (its round-off grows by a
// few ulp of the modes per step).
constexpr int kSpanResync = 256;

}  // namespace

SpanModes::SpanModes(const Chain& c, RunStore& store)
    : H_(store.shapes().step()),
      store_(store),
      span_of_(c.N, -1),
      du_(c.N),
      dv_(c.N),
      buf_{Coords(c.N), Coords(c.N)},
      scratch_(c.N) {}

void SpanModes::project(const Chain& c, const State& s, const std::vector<BlockRange>& spans,
                        const std::int64_t* switched_at, std::int64_t since, bool keep_any) {
  // Slots are the blocks' own indices, so a kept run's modes stay where they are.
  next_.clear();
  for (const BlockRange& r : spans) {
    const int k = span_of_[r.lo];
    const bool keep = keep_any && k >= 0 && spans_[k].lo == r.lo && spans_[k].hi == r.hi &&
                      mine(spans_[k]) && untouched(r, switched_at, since);
    if (keep) {
      next_.push_back(spans_[k]);
      next_.back().fresh = false;
      spans_[k].id = -1;
    } else {
      next_.push_back({r, 0, 0, false, true, 0, s.t, s.t});
    }
  }
  forget();  // the runs let go leave the store (kept ones were marked above)
  spans_.swap(next_);
  for (std::size_t k = 0; k < spans_.size(); ++k)
    std::fill(span_of_.begin() + spans_[k].lo, span_of_.begin() + spans_[k].hi, static_cast<int>(k));
  for (Span& sp : spans_)
    if (sp.fresh) project_one(c, s, sp);
}

// The record projected from the state, the stepper's coordinates started from it, and what the
// projection's round-off leaves of each row the screen reads (the end rows, a stuck neighbour's
// force, and the sliding blocks', their stops) at s.t. A row sums modes of the whole run, so a
// block at rest beside fast ones reads a velocity of ~1e-16 of theirs instead of 0: enough,
// below the stop margin eps_v, to stop a block the instant it restarts. Such a row keeps the
// difference as a constant, so it starts exactly where the state says.
void SpanModes::project_one(const Chain& c, const State& s, Span& sp) {
  const RunStore::Run& rec = store_.project(c, sp, s.t, s.u.data(), s.v.data(), s.dir.data(), RunStore::kSpan);
  sp.id = rec.id;
  sp.grooves = true;
  for (int i = sp.lo; i < sp.hi && sp.grooves; ++i) sp.grooves = !c.contact[i];
  Coords& now = at(sp, false);
  std::copy(store_.q0() + sp.lo, store_.q0() + sp.hi, now.q.begin() + sp.lo);
  std::copy(store_.p0() + sp.lo, store_.p0() + sp.hi, now.p.begin() + sp.lo);
  const int n = sp.hi - sp.lo;
  for (int row = 0; row < n; ++row) {
    const int i = sp.lo + row;
    du_[i] = 0.0, dv_[i] = 0.0;
    if (row != 0 && row != n - 1 && s.dir[i] == 0) continue;
    du_[i] = s.u[i] - store_.row_u(i, s.t, now.q.data());
    dv_[i] = s.v[i] - store_.row_v(i, now.p.data());
  }
}

void SpanModes::advance(int k0, int k1, double h) {
  for (int k = k0; k < k1; ++k) {
    Span& sp = spans_[k];
    sp.t1 = sp.t0 + h;
    const double* q = at(sp, false).q.data();
    const double* p = at(sp, false).p.data();
    double* qn = at(sp, true).q.data();
    double* pn = at(sp, true).p.data();
    const RunStore::Run& rec = store_.run(sp.lo);
    const RunShape& sh = *rec.shape;
    if (h == H_ && sp.since + 1 < kSpanResync) {
      step_modes(sh.n, sh.steps.p00.data(), sh.steps.p01.data(), sh.steps.p10.data(), sh.steps.p11.data(), q + sp.lo,
                 p + sp.lo, qn + sp.lo, pn + sp.lo);
      ++sp.since;
    } else {
      // A step off the grid, or the restart: from the projection itself when it is due.
      if (h == H_) store_.coords(rec, sp.t1, qn, pn);
      else sh.evolve(q + sp.lo, p + sp.lo, h, qn + sp.lo, pn + sp.lo);
      sp.since = 0;
    }
  }
}

void SpanModes::take(int k0, int k1, double t) {
  for (int k = k0; k < k1; ++k) {
    Span& sp = spans_[k];
    sp.cur = 1 - sp.cur;
    sp.t0 = sp.t1 = t;
    sp.fresh = false;  // the rows have left the projected state
  }
}

void SpanModes::take_at(int k0, int k1, double tau, double t) {
  for (int k = k0; k < k1; ++k) {
    Span& sp = spans_[k];
    store_.run(sp.lo).shape->evolve(at(sp, false).q.data() + sp.lo, at(sp, false).p.data() + sp.lo, tau,
                                    at(sp, true).q.data() + sp.lo, at(sp, true).p.data() + sp.lo);
  }
  take(k0, k1, t);
}

void SpanModes::bring(int k0, int k1, double t) {
  for (int k = k0; k < k1; ++k)
    if (spans_[k].t0 != t) take_at(k, k + 1, t - spans_[k].t0, t);
}

void SpanModes::forget() {
  for (const Span& sp : spans_) {
    if (mine(sp)) store_.drop(sp.lo);
    std::fill(span_of_.begin() + sp.lo, span_of_.begin() + sp.hi, -1);
  }
  spans_.clear();
}

bool SpanModes::untouched(BlockRange r, const std::int64_t* switched_at, std::int64_t since) const {
  const int N = static_cast<int>(span_of_.size());
  for (int i = std::max(r.lo - 1, 0); i < std::min(r.hi + 1, N); ++i)
    if (switched_at[i] > since) return false;
  return true;
}

}  // namespace sb::event_detail
