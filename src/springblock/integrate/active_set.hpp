#pragma once
// Which blocks the stepper has to integrate while something slides, and the exact treatment of
// everything else.
//
// Stuck contact blocks do not move, so during a phase (no switch) they cut the chain into
// independent pieces: each maximal run of mobile blocks (grooves and sliding blocks) between two
// stuck blocks or a chain end is its own linear system. A run is
//   * Active   if it holds a sliding block: stepped by Dormand-Prince;
//   * Ringing  if it is grooves only and still carries a transient: stepped too (its own blocks
//              only, so a groove far from the slip costs n, not N);
//   * Settled  if it is grooves only and its transient is below the tolerance (see below):
//              u = A + B t exactly, the affine particular solution (a tridiagonal solve).
// A stuck block with no stepped neighbour feels an affine force a + b t, so its threshold
// crossing is closed form; only stuck blocks next to a stepped run need the step's dense output.
// The cost of a step is therefore proportional to the blocks that actually move, which is what
// makes a precursor of a few blocks in a 360-block chain cheap.
//
// A settled run drops a transient smaller than 0.1 times the stepper's absolute tolerance (in u
// and in v); it keeps decaying, so the error committed is below one step's.
// With settle_grooves = false no run is ever settled (the reference mode used by the tests).
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

struct Span {
  int lo, hi;  // blocks lo .. hi-1
};

class ActiveSet {
 public:
  ActiveSet(const Chain& c, bool settle_grooves, double atol_u, double atol_v);

  // Classify the runs after a switch at s.t (every settled groove already materialised in s).
  void rebuild(const Chain& c, const State& s);

  // Runs stepped by Dormand-Prince, in block order.
  const std::vector<Span>& stepped() const { return stepped_; }
  // Blocks whose events the step's dense output must be searched for: every sliding block and
  // every stuck block next to a stepped run (K_int > 0).
  const std::vector<int>& watched() const { return watched_; }

  enum Kind : std::uint8_t { kStuck = 0, kStepped = 1, kSettled = 2 };
  Kind kind(int i) const { return static_cast<Kind>(kind_[i]); }
  // Displacement of a settled groove block at time t.
  double settled_u(int i, double t) const { return A_[i] + B_[i] * t; }

  // Write the settled grooves' exact u, v at time t into u, v.
  void materialise(double t, double* u, double* v) const;

  // After an accepted step at s.t: ringing runs whose transient has died become settled and
  // leave the stepped set. Returns true when the stepped set changed.
  bool retire_settled(const Chain& c, const State& s);

  struct Next {
    double t;   // earliest closed-form threshold crossing (infinity if none)
    int block;  // its block (lowest index on a tie), -1 if none
  };
  Next next_crossing() const { return next_; }

 private:
  struct Run {
    Span span;
    Kind kind;       // kStepped (active or ringing) or kSettled
    bool grooves;    // grooves only (never holds a contact block)
  };
  // A, B of the groove run over [lo, hi) held by stuck blocks (or free ends) at its boundaries.
  void particular(const Chain& c, const State& s, Span r);
  // The particular solution is linear in the two boundary positions:
  //   B = K^-1 K_s v 1,  A = K^-1 (-m gamma B) + u_left K_int K^-1 e_1 + u_right K_int K^-1 e_n,
  // and K depends only on the run's length and whether each end is held. Solved once per shape.
  struct Shape {
    std::vector<double> B, a0, gL, gR;
  };
  const Shape& shape(const Chain& c, int n, bool left, bool right);
  std::map<std::tuple<int, bool, bool>, Shape> shapes_;
  bool settled_now(const State& s, Span r) const;
  // Fill stepped_ and watched_ from runs_.
  void list_stepped(const State& s);
  // Closed-form crossing of stuck block i from time t (force affine: no stepped neighbour).
  void update_crossing(const Chain& c, const State& s, int i);
  void refresh_next();

  int N_;
  double K_int_;
  bool settle_grooves_;
  double eps_u_, eps_v_;
  std::vector<std::uint8_t> kind_;
  std::vector<Run> runs_;
  std::vector<Span> stepped_;
  std::vector<int> watched_;
  std::vector<double> A_, B_;          // per block, valid in groove runs
  std::vector<double> t_cross_;        // per contact block, closed-form crossing (inf if none / watched)
  std::vector<double> diag_, off_, rhs_;  // tridiagonal work arrays
  Next next_{0, -1};
};

}  // namespace sb::event_detail
