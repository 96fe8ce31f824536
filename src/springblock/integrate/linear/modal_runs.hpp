#pragma once
// Exact propagation of short mobile runs while something slides (the active set's kModal runs).
//
// Between two switches a run of mobile blocks (sliding and groove blocks between stuck blocks
// or chain ends) is a linear system with constant forcing, f_kin in run_shape.hpp's equation the
// signed kinetic friction of its sliding blocks: an affine path plus damped modes in closed form,
// so the run needs no time step at all. Its events are found by EdgeMarch:
//   * a sliding block stops when dir v falls below -kStopMargin v_s (round_off.hpp);
//   * a stuck block beside the run (and beside no stepped run) starts to slide when |F| reaches
//     f_static; F is affine plus the modes of the one or two runs it borders.
// For a run of n blocks a switch costs O(n^2) (projection) plus the event searches, against a
// Dormand-Prince step every ~0.1/omega_max while it moves; the active set uses this only up to
// a run length set by the caller, where it is cheaper (measured in bench_methods), and for a
// run holding a contact block only once it has outlasted a short slip (ActiveSet::promote_runs).
//
// A run none of whose blocks nor stuck neighbours switched keeps its record in the run store and
// its event times across switches elsewhere: a switch costs only the runs it touches. The record
// (path, modes, origin) is the store's (run_store.hpp); a modal run adds a sample cursor, scratch
// coordinates at the time of the last search, and the searches themselves.
#include <limits>
#include <vector>

#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class ModalRuns {
 public:
  ModalRuns(const Chain& c, RunStore& store);

  // Register run [lo, hi) as modal, projected afresh at s.t (grooves: it holds no contact
  // block). A run that stays modal with nothing in or beside it switched is simply kept (the
  // active set decides): it keeps its record.
  void add(const Chain& c, const State& s, int lo, int hi, bool grooves);
  // The run starting at block lo is no longer modal (its record leaves the store).
  void drop(int lo);
  // Transients below these (in u and v, every row) count as gone: see settled_after().
  void set_settle_scales(double eps_u, double eps_v) { settle_ = {eps_u, eps_v}; }
  // For the run holding block i: a time after which its deviation from the affine path is
  // below the settle scales in every row (envelope.hpp, from its modes at projection;
  // +inf without damping or with a mode not underdamped, where no bound is taken).
  // Lets the active set settle a kept groove run without evaluating it.
  double settled_after(int i) const { return runs_[run_of_[i]].settled_after; }
  // True if a modal run spans exactly [lo, hi).
  bool same_run(int lo, int hi) const {
    return run_of_[lo] >= 0 && runs_[run_of_[lo]].lo == lo && runs_[run_of_[lo]].hi == hi;
  }

  // First block of the run holding block i.
  int run_start(int i) const { return runs_[run_of_[i]].lo; }
  // Exact u of a block in a modal run at time t (direct evaluation).
  double u(int i, double t) const { return store_.u(i, t); }
  // A bound on the modes' part, |u - (A + B t)| <= amplitude(i) at every time after the
  // projection (finite for a run's end rows): with the affine path (RunStore::path_u) enough to
  // decide that a stuck neighbour is far from its threshold without evaluating the modes.
  double amplitude(int i) const { return store_.bound(i, 0); }
  // u of block i about time t as a polynomial in tau (RunStore::taylor): the exact stepper's
  // screen of a stuck block beside this run (span_screen.hpp).
  void row_taylor(int i, double t, int deg, double* c);
  // Write every modal run's exact u, v at t. at_sample: t is a sample time, so the modal
  // coordinates may be advanced by the sample recurrence and kept as its new start. The rows
  // written: every row, or only the two end rows (the ones a stuck neighbour's force reads),
  // O(n) instead of O(n^2), of the grooves-only runs (a reader of every contact block's
  // position), or only the end rows' u of every run (a reader of the stuck neighbours' forces
  // alone, which read no velocity); what is not written is left stale.
  enum class Rows { kEvery, kGrooveEnds, kEnds };
  void materialise(double t, double* u, double* v, bool at_sample, Rows rows = Rows::kEvery);
  // Write the exact u, v at t (off the sample grid) of the run holding block i only.
  void materialise_run(int i, double t, double* u, double* v);

  // Event searches from s.t up to t_limit. t = +inf when there is none before t_limit;
  // limited then says whether one may follow later (search again from t_limit).
  struct Found {
    double t;
    bool limited;
    double resume;  // where a limited search goes on: t_limit, or later if a bound says so
  };
  // Stop of sliding block i (fresh: its run was projected at s.t, so s.v[i] is exact).
  Found stop_time(const Chain& c, const State& s, int i, bool fresh, double t_limit);
  // Threshold crossing of stuck block j whose neighbours are modal runs, settled grooves or
  // stuck blocks (no stepped run). For a neighbour that is not modal, base is its position at
  // s.t and nb_B its drift velocity (0 when stuck); index 0 is the left neighbour.
  Found crossing_time(const Chain& c, const State& s, int j, const double base[2], const double nb_B[2],
                      double t_limit);

 private:
  // What a sample reads of a run's end rows, copied from its record at projection: the samples
  // visit every modal run, and on a long chain the records and the per-block paths lie far apart
  // in memory while these sit in the run's own entry.
  struct Ends {
    const RunShape* shape = nullptr;
    double A[2] = {0, 0}, B[2] = {0, 0};  // the first and last rows' affine path
  };
  struct Run {
    int lo, hi;
    Ends ends;
    bool grooves = false;  // no contact block in it
    double tc = std::numeric_limits<double>::quiet_NaN();  // time of the sample cursor (NaN: none yet)
    int since = 0;  // recurrence steps since the cursor was last set from the closed form
    double settled_after = std::numeric_limits<double>::infinity();
    double scratch_t = std::numeric_limits<double>::quiet_NaN();  // time of its scratch coordinates (scratch_at)
  };
  // The modal coordinates at t of the run r holding block i into the scratch slots [r.lo, r.hi),
  // computed once per t (a switch searches a run's stops and both its stuck neighbours' crossings
  // from the same s.t); returns r.
  const Run& scratch_at(int i, double t);
  const RunStore::Run& record(const Run& r) const { return store_.run(r.lo); }

  Scales settle_;  // set_settle_scales
  RunStore& store_;
  std::vector<Run> runs_;
  std::vector<int> run_of_;  // block -> index in runs_ (-1: not in a modal run)
  Coords cursor_;            // per mode slot: the sample cursor
  Coords scratch_;           // per mode slot: coordinates at a run's scratch_t
  Coords velocity_;          // per mode slot: the velocity modes' initial values at s.t (stop_time)
  EdgeMarch march_;
};

}  // namespace sb::event_detail
