#pragma once
// Exact propagation of the chain while every contact block is stuck (nothing slides).
//
// Stuck blocks do not move. Each maximal run of groove blocks (a segment) between stuck blocks
// or a chain end is then an independent linear system, run_shape.hpp's equation without kinetic
// friction: an affine path plus damped modes in closed form.
//
// Each segment is a record of the run store (run_store.hpp), with its modes at the phase's start
// t0: a segment the active set holds already (settled on its path, or a modal groove run) keeps
// its record, moved to origin t0 by the closed form; any other is projected from the state. The
// shapes are shared by all grooves of a periodic pattern (run_shape.hpp), and since the contact
// mask is fixed the segments are found once per run.
//
// The next event is the first time a stuck block's driving force reaches +-f_static. A block
// with stuck neighbours only has an affine force (closed form). A block next to a segment has an
// affine force plus damped modes; its first crossing is searched by EdgeMarch (edge_march.hpp),
// the blocks in order of a cheap lower bound on their crossing so that later searches stop early.
//
// Samples inside a quiet phase are served by advance_sample and write_sample: the modal
// coordinates are advanced from the previous sample by each mode's exact transition matrix over
// the sample spacing (no transcendental calls), and segments whose modes have died out cost only
// their affine part.
// What the phase knows of the contact blocks' forces at its samples (each an affine part plus
// its segments' end rows) it offers to observers as RingingForces (quiet_ringing.hpp).
#include <cstdint>
#include <vector>

#include "springblock/integrate/linear/coords.hpp"
#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/model.hpp"
#include "springblock/observe/ringing_forces.hpp"

namespace sb::event_detail {

class QuietPhase {
 public:
  // A maximal run of grooves between stuck blocks or chain ends.
  struct GrooveRun {
    int first, n;
    const RunShape* shape;  // its path's left and right flags: a stuck block holds that end
    double dead_tau = 0;  // after this the modes are below round-off of u and v (evaluate skips them)
    double sample_dead_tau = 0;  // after this they are below the sample scales (samples skip them)
  };
  // A contact block and the segments it borders: its force is a + b tau + modal part (the affine
  // part and those segments' ends in the phase's EdgeForce of the same index).
  struct Edge {
    int block;
    EdgeMarch march;
    double lower = 0;  // lower bound on its crossing in the current phase
  };

  QuietPhase(const Chain& c, RunStore& store);

  // Start a quiet phase at time t0 from positions u and velocities v (every contact block
  // stuck, so its v is 0). A segment the store holds for the active set keeps its record (a
  // settled one its path, with no modes, rather than modes projected from the round-off of
  // u - (A + B t0)); the others are projected.
  void begin(const Chain& c, double t0, const double* u, const double* v);
  // The phase is over: the records it projected leave the store.
  void release();

  // Exact u, v of every groove block at time t >= t0 (other entries untouched).
  void evaluate(double t, double* u, double* v);
  // The same at a sequence of increasing sample times spaced by the store's sample spacing
  // (RunShapes::set_sample_dt; any other spacing falls back to the closed form), in two halves:
  // the modal coordinates brought to sample time t, then the rows written from them (write_sample
  // needs the advance_sample of the same t before it). With ends_only, only each segment's two end
  // rows are exact (O(modes) per segment instead of O(n^2)); the others are left untouched.
  // Enough for an observer that reads only the contact blocks' forces.
  // The recurrence restarts from the closed form at the phase's first sample, after a gap in
  // the spacing, and at every sample whose index is a multiple of kSampleBlock: a sample's value
  // then depends only on its index and the phase, not on which samples were served before it
  // (an observer may sum a whole block of them from RingingForces::sums).
  static constexpr long kSampleBlock = 64;
  void advance_sample(double t, bool ends_only);
  void write_sample(double t, double* u, double* v, bool ends_only);
  // The sample cursor (advance_sample's modes and time) kept and put back, for samples an
  // observer looked at inside a stretch it then declined: the samples served one by one after it
  // see the cursor they would have seen without the offer.
  void save_cursor() { kept_ = cursor_; }
  void restore_cursor() { cursor_ = kept_; }  // a copy: the kept cursor may be needed again

  struct Next {
    double t;   // event time, or t_limit when no stuck block reaches its threshold before it
    int block;  // the block that reaches its threshold first, -1 if none
  };
  // The first threshold crossing in (t0, t_limit].
  Next next_threshold(const Chain& c, double t_limit);

  // Samples for an observer of contact forces only (write_sample with ends_only, RingingForces,
  // all_dead_after) drop a segment's modes once every row's transient is below eps_u in u and eps_v
  // in v: the active set's settle scales (0.1 x the stepper's absolute tolerances), so a sample's
  // forces carry at most K_int eps_u per contact block beside a groove. The dynamics (evaluate,
  // next_threshold) keeps them to round-off. Without this call samples keep them to round-off too.
  void set_sample_scales(double eps_u, double eps_v) { scales_ = {eps_u, eps_v}; }

  // The time after which every segment's modes are below the sample scales: from then on every
  // groove block is on its affine path as far as samples go, and every contact block's force is
  // affine in t.
  double all_dead_after() const;
  // Those forces, f_i(t) = a[i] + b[i] t for each contact block i (given the contact blocks'
  // positions u; grooves get 0), valid after all_dead_after().
  void affine_forces(const Chain& c, const double* u, double* a, double* b) const;

 private:
  // Its RingingForces reads the phase's start and end, its segments (their records in the store),
  // the edges' forces, the blocks beside no segment and the sample cursor (quiet_ringing.hpp).
  friend class QuietRinging;
  struct Edges {
    std::vector<Edge> list;
    // list[k]'s force: fa + fb tau (begin) and the segment ends it rings with, as RingingForces
    // numbers them, with the springs between.
    std::vector<EdgeForce> forces;
    std::vector<int> order;  // by increasing lower bound (next_threshold)
  };
  // The contact blocks with no groove neighbour, their forces at t0, and how many phases began.
  struct Interior {
    std::vector<int> blocks;
    std::vector<double> a;
    long phase = 0;
  };
  // advance_sample's modes and their time, and whether they hold a sample of this phase.
  struct Cursor {
    double t = 0;
    Coords x;
    bool valid = false;
  };

  // begin()'s work per segment: the times after which its modes no longer count.
  void set_dead_times(GrooveRun& s) const;

  // The phase's start, and its end once next_threshold found it (+inf before).
  struct Span {
    double t0 = 0, next = 0;
  };
  Span span_;
  double slider_slope_ = 0;  // K_s v: the slope of every contact block's force in a quiet phase
  RunStore& store_;
  std::vector<GrooveRun> segs_;
  // The segments whose records have modes (the others are on their paths for the whole phase).
  std::vector<int> live_;
  Edges edges_;
  Interior interior_;
  Scales scales_;
  Cursor cursor_, kept_;
};

}  // namespace sb::event_detail
