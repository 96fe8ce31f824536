#pragma once
// The exact motion of the runs the event method steps: the state of its exact stepper.
//
// While something slides, a run the active set steps (one holding a sliding block, or a
// grooves-only run still ringing) is, between two switches, a linear system with constant
// forcing (the equation in run_shape.hpp). Its motion is its record in the run store (its affine
// path A + B t and its normal modes, each a damped oscillator in closed form, run_store.hpp).
// Nothing is approximated, so there is no error control and no step is ever rejected. The runs
// keep their own clocks: stuck blocks cut the chain into independent systems, so a run steps
// only when the event screen (events/span_screen.hpp) has looked as far as it can, not when a
// run elsewhere stops at an event. The stepper's owner groups the runs that share a stuck border
// (whose force reads both) on one clock and says which group moves; a group steps by at most H,
// 0.75 rad of the fastest rate any run of the chain can have. H only sets how often the screen
// looks: a full step moves each mode by its exact transition over H, computed once per run
// shape; the move to an event inside a step, or to any other time, uses the closed form itself.
// The grid recurrence restarts from the closed form every kSpanResync steps, so its round-off
// never accumulates.
//
// The state lives in the modes: each run keeps its coordinates at its current time t0 and at
// the end t1 of the step it is taking; the blocks' u and v in the chain's State are written only
// when asked (write, at a given time), at switches and samples. The bounds on a row's
// derivatives are the store's, taken at the projection, which hold until the next one
// (row_bound).
#include <cstdint>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class SpanModes {
 public:
  // Degree of the Taylor polynomials the screen builds over one step (see row_taylor).
  static constexpr int kDegree = 12;

  SpanModes(const Chain& c, RunStore& store);
  // The longest step (RunShapes::step).
  double H() const { return H_; }
  const RunStore& store() const { return store_; }

  // After a classification at s.t: the runs in `spans`. A run the previous projection had too is
  // kept as it is, on its own clock (its modes are exact at its t0 <= s.t), if keep_any (nothing
  // but this stepper moved the chain since the last projection), its record is still the one it
  // projected, and none of its blocks nor the blocks beside it switched since (switched_at: per
  // block, the epoch of its last switch; since: the epoch of the previous projection); every
  // other run is projected afresh from s.u and s.v, with t0 = t1 = s.t.
  void project(const Chain& c, const State& s, const std::vector<BlockRange>& spans, const std::int64_t* switched_at,
               std::int64_t since, bool keep_any);
  // Runs k0 .. k1 - 1 (one clock, t0): their modes at t0 + h into the step's end,
  // the grid transition for h == H(), the closed form otherwise.
  void advance(int k0, int k1, double h);
  // Their step's end becomes their current state, at time t (the caller's clock for t0 + h).
  void take(int k0, int k1, double t);
  // Their current state moved by tau (0 <= tau) by the closed form, at time t.
  void take_at(int k0, int k1, double tau, double t);
  // Their current state moved to time t >= t0 (nothing if they are there).
  void bring(int k0, int k1, double t);
  // Whether run k was kept by the last projection (read before it moves), and its current time.
  bool kept(int k) const { return !spans_[k].fresh; }
  double t0(int k) const { return spans_[k].t0; }
  // Runs are held (projected and not forgotten since).
  bool live() const { return !spans_.empty(); }

  // Write the u, v at time t (at or after each run's t0) of every run's blocks (ends_only: the
  // two end rows of each run, which are all a contact block's force reads).
  void write(double t, double* u, double* v, bool ends_only);
  // The same for the runs a switch of the given blocks reads: those holding or beside one of
  // them, and every grooves-only run (the active set judges whether it has rung down).
  void write_near(double t, const std::vector<int>& blocks, double* u, double* v);
  // The same for the runs none of whose blocks, nor the blocks beside them, switched after epoch
  // `since` (switched_at as for project()). forget() then lets the runs go: the next projection keeps none.
  void write_untouched(double t, const std::int64_t* switched_at, std::int64_t since, double* u, double* v);
  void forget();

  // Row evaluations of block i, which must be in a run: at its run's current state (end = false,
  // time t0) or at its step's end (end = true, time t1 of the last advance).
  bool holds(int i) const { return span_of_[i] >= 0; }
  // The run holding block i was projected by the last project() and has not moved since: its
  // rows the screen reads (end rows and sliding blocks' rows) are then, at its t0, the state's u
  // and v, which their offsets make them: a + (x - a) is x exactly when a and x are within a
  // factor 2 (x - a is then exact), and within an ulp of x otherwise (a row crossing zero), so
  // the screen may read the state instead.
  bool fresh(int i) const { return spans_[span_of_[i]].fresh; }
  double u(int i, bool end) const {
    const Span& sp = spans_[span_of_[i]];
    return store_.row_u(i, end ? sp.t1 : sp.t0, at(sp, end).q.data()) + du_[i];
  }
  double v(int i, bool end) const { return store_.row_v(i, at(spans_[span_of_[i]], end).p.data()) + dv_[i]; }
  double a(int i, bool end) const {
    const Coords& x = at(spans_[span_of_[i]], end);
    return store_.row_a(i, x.q.data(), x.p.data());
  }
  // A bound on the order-th derivative of u of block i (order 2 to 5) from the projection on, for
  // the end rows of a run and its sliding blocks (RunStore::bound).
  double row_bound(int i, int order) const { return store_.bound(i, order); }
  // u of block i about its run's t0 as a polynomial in tau: c[j], j = 0 .. kDegree + 1 (exact to
  // round-off for tau <= H: the remainder is below 0.75^(kDegree+2) / (kDegree+2)! of the
  // modes' amplitude).
  void row_taylor(int i, double* c) const;

  // The runs, in block order.
  int count() const { return static_cast<int>(spans_.size()); }
  const BlockRange& span(int k) const { return spans_[k]; }
  // A grooves-only run (index k < count()) has rung down below the scales after this time
  // (+inf without damping, or for a run holding a contact block), from its modes at the
  // projection (envelope.hpp).
  double settled_after(int k, double eps_u, double eps_v) const;

 private:
  struct Span : BlockRange {
    std::int64_t id;  // its record's serial number in the store
    int since;        // grid steps since the modes were last set from the closed form
    bool grooves;     // no contact block in it
    bool fresh;       // projected by the last project() and not moved since
    int cur;          // which of buf_ holds its current coordinates (the other: its step's end)
    double t0, t1;    // the times of its current coordinates and of its step's end
  };
  void project_one(const Chain& c, const State& s, Span& sp);
  // Whether none of r's blocks, nor the blocks beside them, switched after epoch since.
  bool untouched(BlockRange r, const std::int64_t* switched_at, std::int64_t since) const;
  // The store's record of span sp is still the one sp projected (else another user has taken its
  // blocks, and with them the duty to write them).
  bool mine(const Span& sp) const {
    const RunStore::Run* r = store_.exact(sp);
    return r != nullptr && r->id == sp.id;
  }
  // Its rows at time t (its coordinates moved there by the closed form into scratch_ first).
  void write_rows(const Span& sp, double t, double* u, double* v, bool ends_only = false);
  const Coords& at(const Span& sp, bool end) const { return buf_[end ? 1 - sp.cur : sp.cur]; }
  Coords& at(const Span& sp, bool end) { return buf_[end ? 1 - sp.cur : sp.cur]; }

  double H_;
  RunStore& store_;
  std::vector<Span> spans_, next_;  // next_: those of a projection, while it is made
  std::vector<int> span_of_;     // block -> index in spans_ (-1: none)
  std::vector<double> du_, dv_;  // per block: the projection's round-off (project_one)
  Coords buf_[2];                // per run, its current modes and those at its step's end (Span::cur)
  Coords scratch_;               // a run's modes moved to a write's time
};

}  // namespace sb::event_detail
