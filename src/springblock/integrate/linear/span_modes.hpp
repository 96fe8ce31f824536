#pragma once
// The exact motion of the runs the event method steps: the state of its exact stepper.
//
// While something slides, a run the active set steps (one holding a sliding block, or a
// grooves-only run still ringing) is, between two switches, a linear system with constant
// forcing (the equation in modal_runs.hpp). Its motion is its affine particular solution A + B t
// (the pieces of affine_paths.hpp, less its sliding blocks' kinetic friction) plus its normal
// modes, each a damped oscillator in closed form (damped_mode.hpp). Nothing is approximated, so
// there is no error control and no step is ever rejected: the runs advance together by steps of
// at most H, 0.75 rad of the fastest rate any run of the chain can have. H
// only sets how often the event screen (events/span_screen.hpp) looks: a full step moves each
// mode by its exact transition over H, computed once per run shape; a shorter one (cut to a
// sample, a closed-form event or the end of the run) and the move to an event inside a step use
// the closed form itself. The grid recurrence restarts from the closed form every kResync steps,
// so its round-off never accumulates.
//
// The state lives in the modes: the blocks' u and v in the chain's State are written only when
// asked (write), at switches and samples. Every mode's energy q'^2 + omega^2 q^2 never grows, so
// bounds on a row's derivatives taken at the projection hold until the next one (row_bound).
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/linear/affine_paths.hpp"
#include "springblock/integrate/linear/run_basis.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class SpanModes {
 public:
  // Degree of the Taylor polynomials the screen builds over one step (see row_taylor).
  static constexpr int kDegree = 12;

  explicit SpanModes(const Chain& c);
  // The longest step, H = 0.75 / (the fastest rate of any mode of any run of the chain).
  double H() const { return H_; }

  // After a classification at s.t: the runs in `spans`. A run the previous projection had too is
  // kept as it is (its modes are exact at s.t) if its modes are at s.t and none of its blocks nor
  // the blocks beside it switched since (switched: per block, 1 if it did); every other run is
  // projected afresh from s.u and s.v.
  void project(const Chain& c, const State& s, const std::vector<BlockRange>& spans, const std::uint8_t* switched);
  // The modes at now() + h into the step's end, from those at now(): the grid transition for
  // h == H(), the closed form otherwise.
  void advance(double h);
  // The step's end becomes the current state, at time t (the caller's clock for now() + h).
  void take(double t);
  // The current state moved by tau (0 <= tau) by the closed form, at time t.
  void take_at(double tau, double t);
  double now() const { return t_; }

  // Write the current u, v of every run's blocks (ends_only: the two end rows of each run,
  // which are all a contact block's force reads).
  void write(double* u, double* v, bool ends_only) const;
  // The same for the runs a switch of the given blocks reads: those holding or beside one of
  // them, and every grooves-only run (the active set judges whether it has rung down).
  void write_near(const std::vector<int>& blocks, double* u, double* v) const;
  // The same for the runs none of whose blocks, nor the blocks beside them, switched (switched:
  // per block), and the modes then forgotten: the next projection keeps no run.
  void write_untouched(const std::uint8_t* switched, double* u, double* v) const;
  void forget() { t_ = std::numeric_limits<double>::quiet_NaN(); }

  // Row evaluations of block i, which must be in a run: at the current state (end = false) or
  // at the step's end (end = true, time now() + h of the last advance).
  bool holds(int i) const { return span_of_[i] >= 0; }
  // The run holding block i was projected by the last project() and has not moved since: its
  // rows the screen reads (end rows and sliding blocks' rows) are then, at now(), the state's u
  // and v, which their offsets make them: a + (x - a) is x exactly when a and x are within a
  // factor 2 (x - a is then exact), and within an ulp of x otherwise (a row crossing zero), so
  // the screen may read the state instead.
  bool fresh(int i) const { return spans_[span_of_[i]].fresh; }
  double u(int i, bool end) const { return A_[i] + B_[i] * (end ? t_ + h_ : t_) + row_dot(i, end ? qn_.data() : q_.data()) + du_[i]; }
  double v(int i, bool end) const { return B_[i] + row_dot(i, end ? pn_.data() : p_.data()) + dv_[i]; }
  double a(int i, bool end) const;  // the acceleration
  // A bound on the order-th derivative of u of block i (order 2 to 5) from the projection on, for
  // the end rows of a run and its sliding blocks.
  double row_bound(int i, int order) const;
  // u of block i about now() as a polynomial in tau: c[j], j = 0 .. kDegree + 1 (exact to
  // round-off for tau <= H: the remainder is below 0.75^(kDegree+2) / (kDegree+2)! of the
  // modes' amplitude).
  void row_taylor(int i, double* c) const;

  const std::vector<BlockRange>& spans() const { return ranges_; }
  // A grooves-only run (index in spans()) has rung down below the scales after this time
  // (+inf without damping), from its modes at the projection (envelope.hpp).
  double settled_after(int k, double eps_u, double eps_v) const;

 private:
  struct Shape {
    const RunBasis* basis;
    const AffineShapes::Shape* path;
    std::vector<double> Qr;                  // Q row-major (a block's row is contiguous)
    std::vector<double> p00, p01, p10, p11;  // per mode: transition over H
    std::vector<double> w2;                  // per mode: omega^2
    std::vector<double> c[4];                // per mode: bounds on |q^(j)| per sqrt(energy), j = 2 .. 5
    std::vector<double> inv_pivot, upper;    // per row: K's tridiagonal factors
  };
  struct Span {
    int lo, hi;
    const Shape* shape;
    double t0;  // projection time of q0_, p0_
    int since;  // grid steps since the modes were last set from the closed form
    bool grooves;  // no contact block in it
    bool fresh;    // projected by the last project()
  };
  const Shape& shape(int n, bool left, bool right);
  void project_one(const Chain& c, const State& s, Span& sp);
  // The modes of span sp at tau after (q, p) into (qo, po), by the closed form.
  void direct(const Span& sp, const double* q, const double* p, double tau, double* qo, double* po) const;
  // Row of block i (its run's Q row) dotted with the per-slot array x (slots of its run).
  double row_dot(int i, const double* x) const {
    const Span& sp = spans_[span_of_[i]];
    const int n = sp.hi - sp.lo;
    const double* row = sp.shape->Qr.data() + static_cast<std::size_t>(i - sp.lo) * n;
    const double* xs = x + sp.lo;
    double d = 0;
    for (int k = 0; k < n; ++k) d += row[k] * xs[k];
    return d;
  }
  void write_rows(const Span& sp, double* u, double* v) const;
  void set_bounds(const Span& sp, int row);

  int N_;
  double K_s_, K_int_, m_, gamma_, H_, t_ = 0, h_ = 0;  // h_: the last advance
  RunBases bases_;
  AffineShapes paths_;
  std::map<std::tuple<int, bool, bool>, Shape> shapes_;
  std::vector<const Shape*> index_;  // shapes_ by 4 n + 2 left + right
  std::vector<Span> spans_, kept_;
  std::vector<BlockRange> ranges_;
  std::vector<int> span_of_;              // block -> index in spans_ (-1: none)
  std::vector<double> A_, B_;             // per block: particular solution
  std::vector<double> du_, dv_;           // per block: the projection's round-off (project_one)
  std::vector<double> bound_[4];          // per block: row_bound of orders 2 to 5 (end and sliding rows)
  std::vector<double> q_, p_, qn_, pn_;   // per mode slot (run lo + k): current and step end
  std::vector<double> q0_, p0_, sE_;      // at the projection: modes, sqrt of their energies
  std::vector<double> rhs_;
  mutable std::vector<double> scratch_u_, scratch_v_;  // write_rows: a run's Q q and Q p
};

}  // namespace sb::event_detail
