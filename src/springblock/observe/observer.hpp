#pragma once
// Observers see the chain at sample times and at its switches; integrators call them and never
// compute observables themselves (odeint's observer concept).
#include <cstddef>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/observe/affine_totals.hpp"
#include "springblock/state.hpp"

namespace sb {

// A stretch of samples an integrator can sum without visiting each one (a quiet phase's: see
// QuietPhase::window_sums), offered to observers that need only time averages.
class SampleStretch {
 public:
  virtual ~SampleStretch() = default;
  // The sums over samples k0 .. k0 + n - 1 of sum_i |f_i| and sum_i f_i (friction forces of the
  // contact blocks); false when they cannot be had in closed form (then nothing is summed).
  virtual bool sums(long k0, long n, double& sum_abs, double& sum_signed) = 0;
  // The state at sample k, its friction sums in State::presummed and, where the observer's
  // needs_positions_at says so, its positions: for a series or a snapshot. Does not change what
  // sums() gives.
  virtual const State& at(long k) = 0;
  // Bounds on the friction sums over samples k0 .. k0 + n - 1 for an observer after their maximum:
  // at sample k0 + j each sum lies within `reach` of the straight line from its value `first` at
  // j = 0 to `last` at j = n - 1 (evaluated as first + (last - first) j / (n - 1)), round-off of
  // the sums, the line and the bounds included. False when there are none (no sign is fixed).
  struct Envelope {
    double abs_first, abs_last, signed_first, signed_last, reach;
  };
  virtual bool envelope(long k0, long n, Envelope& e) {
    (void)k0, (void)n, (void)e;
    return false;
  }
};

// The friction forces of a stretch of affine samples: f_i(t) = a[i] + b[i] t for every contact
// block, and, where the integrator keeps them (totals != nullptr), the sums over the contact
// blocks a stretch starting at its first sample needs (affine_totals.hpp), which an observer then
// need not form itself.
struct AffineForces {
  const double* a;
  const double* b;
  const AffineTotals* totals = nullptr;
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

class Observer {
 public:
  virtual ~Observer() = default;
  // Called at t = 0 and then at every sample time with the state at exactly that time.
  virtual void sample(const Chain& chain, const State& state) = 0;
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
  // Whether a sample at time t that carries its friction sums (State::presummed) needs the
  // positions as well; an integrator may leave them unwritten where no observer needs them. An
  // observer that reads State::presummed says when it does; the default always needs them.
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
  // A block of samples t_k = k dt, k = k0 .. k0 + n - 1, inside which nothing switches, offered
  // as a SampleStretch. An observer takes all of them (returns n) or none (returns 0; the
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
