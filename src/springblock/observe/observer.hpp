#pragma once
// Observers see the chain at sample times and at its switches; integrators call them and never
// compute observables themselves (odeint's observer concept).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/observe/affine_totals.hpp"
#include "springblock/observe/ringing_forces.hpp"
#include "springblock/state.hpp"

namespace sb {

// A stretch of samples in a quiet phase, offered with what the integrator knows exactly of the
// contact forces there (RingingForces), to observers that need only sums or bounds over it.
class SampleStretch {
 public:
  virtual ~SampleStretch() = default;
  virtual RingingForces& forces() = 0;
  // The state at sample k, where the observer's needs_positions_at says so with its positions, and
  // forces() then describing that sample (RingingForces::terms_now): for a series, a snapshot or
  // a sample that may hold a peak. Changes nothing forces() gives for the stretch.
  virtual const State& at(long k) = 0;
};

// The friction forces of a stretch of affine samples: f_i(t) = a[i] + b[i] t for every contact
// block. per_block: each force changes only when its own block switches (Observer::switched), so
// an observer may keep sums over the blocks from one stretch to the next (SwitchedTotals).
struct AffineForces {
  const double* a;
  const double* b;
  bool per_block = false;
};

// The contact blocks switched at one instant, as the integrator holds them (a list, or one block),
// without a copy. (std::span, were the public headers not C++17.)
class SwitchedBlocks {
 public:
  SwitchedBlocks(const std::vector<int>& blocks) : first_(blocks.data()), n_(blocks.size()) {}
  static SwitchedBlocks one(const int& block) { return SwitchedBlocks(&block, 1); }
  const int* begin() const { return first_; }
  const int* end() const { return first_ + n_; }
  std::size_t size() const { return n_; }

 private:
  SwitchedBlocks(const int* first, std::size_t n) : first_(first), n_(n) {}
  const int* first_;
  std::size_t n_;
};

// The contact forces of a sample of an active phase (something slides) as the integrator knows
// them, block by block (kind[i]):
//   kAffine   stuck, with nothing beside it moving off a known affine path: a[i] + b[i] t;
//   kSliding  dir f_kinetic, a[i] (b[i] = 0);
//   kLive     stuck beside a run that moves otherwise: read it from the state, which holds its
//             own and its neighbours' positions at the sample;
//   kNone     no contact (or not classified yet).
// a[i] and b[i] are 0 where the force is not known (kLive, kNone), so a sum over a and b needs
// no test of the kind.
// Between two samples only a few blocks change entry, so an observer that sums the forces keeps
// the affine and sliding ones in a tree (AffineForceTree) and reads only the live ones: O(what
// moves) a sample instead of O(N). changed lists the blocks whose entry changed since the
// previous sample_active or follow_forces call (every block when all_changed).
struct ActiveForces {
  enum Kind : std::uint8_t { kNone, kAffine, kSliding, kLive };
  const double* a;
  const double* b;
  const std::uint8_t* kind;
  const std::vector<int>& changed;
  bool all_changed;
  const std::vector<int>& live;
};

class Observer {
 public:
  virtual ~Observer() = default;
  // Called at t = 0 and then at every sample time with the state at exactly that time.
  virtual void sample(const Chain& chain, const State& state) = 0;
  // A sample at which the integrator knows the contact forces exactly (f, at state.t): the state's
  // positions are written only where needs_positions_at(state.t) says so. The default reads the
  // state.
  virtual void sample_ringing(const Chain& chain, const State& state, RingingForces& f) {
    (void)f;
    sample(chain, state);
  }
  // Called after the switching rules were applied at an instant and switched something, with the
  // contact blocks they switched (each once). s.t is the instant, and s.u, s.v and s.dir of those
  // blocks are exact there (the rules read their forces, so the integrator brought them there
  // first); other blocks' positions may be stale. A block listed that slides still (or is stuck
  // still) stopped and started again (or started and stopped) at the instant. Several calls may
  // share one instant (the per-block solver applies the rules block by block). What switches is
  // the integrator's alone: an observer of the motion between switches (slip events) needs
  // nothing else. The default ignores it.
  virtual void switched(const Chain& chain, const State& state, SwitchedBlocks blocks) {
    (void)chain, (void)state, (void)blocks;
  }
  // Whether the observer takes the samples of an active phase as ActiveForces (sample_active); the
  // integrator then writes only what the live blocks' forces read, unless needs_positions_at.
  virtual bool takes_active_forces() const { return false; }
  // A sample of an active phase (state at s.t; positions as takes_active_forces says), with the
  // forces the integrator knows. Called only where takes_active_forces() is true.
  virtual void sample_active(const Chain& chain, const State& state, const ActiveForces& f) {
    (void)f;
    sample(chain, state);
  }
  // The same forces' changes, at a sample the observer does not take (a view of a shared
  // trajectory that has it already): an observer that keeps sums of them follows the changes.
  virtual void follow_forces(const Chain& chain, const State& state, const ActiveForces& f) {
    (void)chain, (void)state, (void)f;
  }
  // An observer may end the run early (mu_s-only scenes, interruption).
  virtual bool wants_stop() const { return false; }
  // Whether samples must carry exact positions of groove blocks that have no contact
  // neighbour. An observer that reads only contact blocks' forces says no, and an integrator
  // with an exact groove solution may then skip evaluating those interiors at samples.
  virtual bool reads_groove_interiors() const { return true; }
  // Whether the observer reads nothing but s.t, s.dir, the slip counters and the contact blocks'
  // friction forces (friction_force()). In a chain without internal springs those depend on
  // the stuck blocks' positions only, so an exact per-block integrator may leave the positions
  // of moving blocks unevaluated at samples.
  virtual bool reads_only_friction() const { return false; }
  // Whether a sample served through sample_ringing needs the positions as well; an integrator may
  // leave them unwritten where no observer needs them. An observer that reads the forces instead
  // says when it does; the default always needs them.
  virtual bool needs_positions_at(double t) const {
    (void)t;
    return true;
  }
  // A stretch of samples at t_k = k dt, k = k0 .. k0 + n - 1, across which nothing switches and
  // every contact block's friction force is affine (f; s carries s.dir and the slip counters;
  // its positions are not those of any sample). An observer may take a prefix of the stretch at
  // once and return its length; the integrator serves the others one by one with sample(). The
  // default takes none.
  virtual long sample_affine(const Chain&, const State&, long k0, double dt, long n, const AffineForces& f) {
    (void)k0, (void)dt, (void)n, (void)f;
    return 0;
  }
  // A block of samples t_k = k dt, k = k0 .. k0 + n - 1, inside a quiet phase, offered as a
  // SampleStretch. An observer takes all of them (returns n) or none (returns 0; the
  // integrator then serves them one by one with sample()); whether it takes them must not
  // depend on how earlier samples came, so that a trajectory shared by several observers gives
  // each the result of its own run (FanOut). s carries s.dir, the slip counters and the work
  // counters. The default takes none.
  virtual long sample_sums(const Chain&, const State&, long k0, double dt, long n, SampleStretch& stretch) {
    (void)k0, (void)dt, (void)n, (void)stretch;
    return 0;
  }
};

}  // namespace sb
