#pragma once
// The exact motion of the runs the event method steps: the state of its exact stepper.
//
// While something slides, a run the active set steps (one holding a sliding block, or a
// grooves-only run still ringing) is, between two switches, a linear system with constant
// forcing (the equation in run_shape.hpp). Its motion is its record in the run store (its affine
// path A + B t and its normal modes, each a damped oscillator in closed form, run_store.hpp). Nothing is approximated, so
// there is no error control and no step is ever rejected: the runs advance together by steps of
// at most H, 0.75 rad of the fastest rate any run of the chain can have. H
// only sets how often the event screen (events/span_screen.hpp) looks: a full step moves each
// mode by its exact transition over H, computed once per run shape; a shorter one (cut to a
// sample, a closed-form event or the end of the run) and the move to an event inside a step use
// the closed form itself. The grid recurrence restarts from the closed form every kResync steps,
// so its round-off never accumulates.
//
// The state lives in the modes: the stepper keeps each run's coordinates at its current time and
// at the end of the step it is taking; the blocks' u and v in the chain's State are written only
// when asked (write), at switches and samples. The bounds on a row's derivatives are the
// store's, taken at the projection, which hold until the next one (row_bound).
#include <cstdint>
#include <limits>
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
  // The longest step (RunShapes::step_for).
  double H() const { return H_; }

  // After a classification at s.t: the runs in `spans`. A run the previous projection had too is
  // kept as it is (its modes are exact at s.t) if its modes are at s.t, its record is still the
  // one it projected, and none of its blocks nor the blocks beside it switched since (switched_at:
  // per block, the epoch of its last switch; since: the epoch of the previous projection); every
  // other run is projected afresh from s.u and s.v.
  void project(const Chain& c, const State& s, const std::vector<BlockRange>& spans, const std::int64_t* switched_at,
               std::int64_t since);
  // The modes at now() + h into the step's end, from those at now(): the grid transition for
  // h == H(), the closed form otherwise.
  void advance(double h);
  // The step's end becomes the current state, at time t (the caller's clock for now() + h).
  void take(double t);
  // The current state moved by tau (0 <= tau) by the closed form, at time t.
  void take_at(double tau, double t);
  double now() const { return now_.t; }

  // Write the current u, v of every run's blocks (ends_only: the two end rows of each run,
  // which are all a contact block's force reads).
  void write(double* u, double* v, bool ends_only);
  // The same for the runs a switch of the given blocks reads: those holding or beside one of
  // them, and every grooves-only run (the active set judges whether it has rung down).
  void write_near(const std::vector<int>& blocks, double* u, double* v);
  // The same for the runs none of whose blocks, nor the blocks beside them, switched after epoch
  // `since` (switched_at: per block, the epoch of its last switch). forget() then lets the runs
  // go: the next projection keeps none.
  void write_untouched(const std::int64_t* switched_at, std::int64_t since, double* u, double* v);
  void forget();

  // Row evaluations of block i, which must be in a run: at the current state (end = false) or
  // at the step's end (end = true, time now() + h of the last advance).
  bool holds(int i) const { return span_of_[i] >= 0; }
  // The run holding block i was projected by the last project() and has not moved since: its
  // rows the screen reads (end rows and sliding blocks' rows) are then, at now(), the state's u
  // and v, which their offsets make them: a + (x - a) is x exactly when a and x are within a
  // factor 2 (x - a is then exact), and within an ulp of x otherwise (a row crossing zero), so
  // the screen may read the state instead.
  bool fresh(int i) const { return spans_[span_of_[i]].fresh; }
  double u(int i, bool end) const { return store_.row_u(i, at(end).t, at(end).x.q.data()) + du_[i]; }
  double v(int i, bool end) const { return store_.row_v(i, at(end).x.p.data()) + dv_[i]; }
  double a(int i, bool end) const { return store_.row_a(i, at(end).x.q.data(), at(end).x.p.data()); }
  // A bound on the order-th derivative of u of block i (order 2 to 5) from the projection on, for
  // the end rows of a run and its sliding blocks (RunStore::bound).
  double row_bound(int i, int order) const { return store_.bound(i, order); }
  // u of block i about now() as a polynomial in tau: c[j], j = 0 .. kDegree + 1 (exact to
  // round-off for tau <= H: the remainder is below 0.75^(kDegree+2) / (kDegree+2)! of the
  // modes' amplitude).
  void row_taylor(int i, double* c) const;

  const std::vector<BlockRange>& spans() const { return ranges_; }
  // A grooves-only run (index in spans()) has rung down below the scales after this time
  // (+inf without damping, or for a run holding a contact block), from its modes at the
  // projection (envelope.hpp).
  double settled_after(int k, double eps_u, double eps_v) const;

 private:
  struct Span {
    int lo, hi;
    std::int64_t id;  // its record's serial number in the store
    int since;        // grid steps since the modes were last set from the closed form
    bool grooves;     // no contact block in it
    bool fresh;       // projected by the last project()
  };
  void project_one(const Chain& c, const State& s, Span& sp);
  // The store's record of span sp, if it is still the one sp projected (else nullptr: another
  // user has taken its blocks, and with them the duty to write them).
  const RunStore::Run* mine(const Span& sp) const {
    const RunStore::Run* r = store_.exact({sp.lo, sp.hi});
    return r != nullptr && r->id == sp.id ? r : nullptr;
  }
  void write_rows(const Span& sp, double* u, double* v, bool ends_only = false);
  const Moment& at(bool end) const { return end ? end_ : now_; }

  double H_;
  RunStore& store_;
  std::vector<Span> spans_, kept_;
  std::vector<BlockRange> ranges_;
  std::vector<int> span_of_;     // block -> index in spans_ (-1: none)
  std::vector<double> du_, dv_;  // per block: the projection's round-off (project_one)
  Moment now_, end_;             // the runs' modes now and at the end of the last advance
};

}  // namespace sb::event_detail
