#pragma once
// What the shape of a run determines, computed once and shared by everything that moves runs
// exactly (the run store and its users: the quiet phase, the modal runs, the exact stepper).
//
// A run is n consecutive mobile blocks (grooves or sliding blocks) between stuck blocks or chain
// ends. Between two switches it is the linear system
//   m u'' + m gamma u' + K u = K_s v t 1 + K_int (u_left e_1 + u_right e_n) - f_kin,
// K its stiffness: tridiagonal, K_s plus one K_int per neighbour that exists (a block of the run,
// or the stuck block at an end that is held) on the diagonal, -K_int beside it. Everything that
// depends on K and not on the run's position or forcing lives here:
//   * K's factors (one symmetric tridiagonal elimination): K^-1 of any right-hand side in O(n),
//     the one way K is inverted, for the affine path and for the kinetic friction alike;
//   * the affine path's pieces: u_p = A + B t with K B = K_s v 1 and
//     A = a0 + u_left gL + u_right gR - K^-1 f_kin, a0 = K^-1 (-m gamma B), gL, gR = K^-1 K_int e_1, e_n;
//   * the modes: K's orthonormal eigenvectors Q (by column, and by row in Qr: a block's row is
//     contiguous) and each mode's damped oscillator (damped_mode.hpp);
//   * each mode's exact transition over the steps the users take (the sample spacing, the exact
//     stepper's grid step, EdgeMarch's grid step), made when a user first asks for them (Parts),
//     and the constants of the bounds on a row's derivatives.
// On a chain of identical blocks K depends only on (n, left held, right held) and its modes are
// sampled sines and cosines (run_shape.cpp), so the shapes are keyed by that triple. A chain of
// blocks that differ keys them by the run's blocks instead, and its modes are the general case
// (general_modes.hpp) of which these closed forms are the fast special case (W = I).
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <utility>
#include <tuple>
#include <vector>

#include <Eigen/Dense>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/linear/damped_mode.hpp"
#include "springblock/model.hpp"

namespace sb::event_detail {

// K's factors by Thomas' algorithm (K is diagonally dominant, so no pivoting is needed).
struct Factors {
  std::vector<double> diag, off;         // K: diagonal, and the n - 1 entries beside it
  std::vector<double> inv_pivot, upper;  // 1 / pivot_r, and off_r / pivot_r
  void factor();
  // y = K^-1 f (y may be f).
  void solve(const double* f, double* y) const;
};

// The affine path's pieces (above), and whether a stuck block holds each end (else a free chain end: gL or gR is 0).
struct AffinePieces {
  std::vector<double> B, a0, gL, gR;
  bool left = false, right = false;
  // Row k's A without friction, from the held ends' positions (0 at a free end).
  double A(int k, double uL, double uR) const { return a0[k] + uL * gL[k] + uR * gR[k]; }
};

// Per mode: K's eigenvalue, omega^2, 1 / omega, and the bounds' constants: |q^(j)| <= c[j - 2]
// sqrt(E), j = 2 .. 5, for a mode of energy E = q'^2 + omega^2 q^2.
struct Spectrum {
  std::vector<double> lambda, w2, inv_omega;
  std::vector<double> c[4];
};

struct Transitions {
  std::uint8_t parts = 0;  // those made so far
  // Over the sample spacing, and the first row of (I - P)^-1 for the sum of a mode over
  // consecutive samples in closed form (NaN where I - P is too near singular: an undamped mode
  // that turns by a multiple of 2 pi).
  std::vector<Transition> sample;
  std::vector<std::array<double, 2>> sample_sum;
  std::vector<double> p00, p01, p10, p11;  // over the exact stepper's grid step, by element
  std::vector<Transition> march;           // over EdgeMarch's grid step
};

struct RunShape {
  // The transitions a shape carries once a user has asked for them.
  enum Parts : std::uint8_t { kStep = 1, kMarch = 2, kSample = 4 };
  int n = 0;
  Factors K;
  AffinePieces path;
  Eigen::MatrixXd Q;               // modes by column, Q^T W Q = I, eigenvalues rising
  std::vector<double> weight;      // W: the rows' masses over the chain's m; empty (all 1) on a uniform chain
  std::vector<double> Qr;          // the same by row
  std::vector<DampedMode> modes;   // alpha = gamma / 2, omega^2 = lambda / m
  Spectrum spectrum;
  Transitions steps;

  const double* row(int r) const { return Qr.data() + static_cast<std::size_t>(r) * n; }
  // Modes k0 .. k0 + m - 1 (every mode by default) from (q, p) moved on by tau >= 0 in closed
  // form into (qo, po); the four arrays start at mode k0.
  void evolve(const double* q, const double* p, double tau, double* qo, double* po, int k0 = 0, int m = -1) const {
    DampedMode::eval_all(
        m < 0 ? n : m, [&](int k) -> const DampedMode& { return modes[k0 + k]; }, tau,
        [&](int k, const DampedMode& md, double e) { md.eval_decayed(q[k], p[k], tau, e, qo[k], po[k]); });
  }
  // The modes (q, q') one sample spacing on.
  void step_sample(double* q, double* qd) const {
    for (int k = 0; k < n; ++k) {
      const double a = q[k], b = qd[k];
      const Transition& P = steps.sample[k];
      q[k] = P[0] * a + P[1] * b;
      qd[k] = P[2] * a + P[3] * b;
    }
  }
  // The first and last rows' modal parts, Q's end rows . q.
  void end_rows(const double* q, double& first, double& last) const {
    first = last = 0;
    const double* f = row(0);
    const double* l = row(n - 1);
    for (int k = 0; k < n; ++k) first += f[k] * q[k], last += l[k] * q[k];
  }
};

class RunShapes {
 public:
  // Transitions over the exact stepper's step (step()) and EdgeMarch's grid step.
  explicit RunShapes(const Chain& c);
  // The shape of run r of the chain, with the transitions `parts` (RunShape::Parts) made: get on a uniform chain,
  // general on one whose blocks differ. References stay valid for the life of this object.
  const RunShape& of(BlockRange r, std::uint8_t parts = 0) {
    return c_.uniform() ? get(r.size(), r.lo > 0, r.hi < c_.N, parts) : general(r, parts);
  }
  const RunShape& get(int n, bool left, bool right, std::uint8_t parts = 0);
  const RunShape& general(BlockRange r, std::uint8_t parts = 0);
  // Sample transitions of every shape, present and future.
  void set_sample_dt(double dt);
  double sample_dt() const { return sample_dt_; }
  // The exact stepper's step: 0.75 rad of the fastest rate any run's mode can have.
  double step() const { return step_; }
  double march_step() const { return march_step_; }
  int size() const { return static_cast<int>(shapes_.size()); }

 private:
  // The shape of run r, a stuck block holding its left and right ends as the flags say (on a
  // uniform chain r stands for every run of its length and ends).
  RunShape make(BlockRange r, bool left, bool right) const;
  std::vector<double> general_key(BlockRange r) const;
  static void finish_modes(RunShape& sh, double mass, double gamma);
  void add_parts(RunShape& sh, std::uint8_t parts) const;
  void set_sample_transitions(RunShape& sh) const;
  const Chain& c_;
  double step_, march_step_, sample_dt_ = 0;
  std::deque<RunShape> shapes_;   // every shape made (a deque: references stay valid)
  std::vector<RunShape*> index_;  // a uniform chain's by 4 n + 2 left + right: every projection looks one up
  // A chain whose blocks differ: each run (lo, hi) points at the shape of its blocks' values, one
  // for all runs whose blocks are equal (general_key), so their transitions are made once.
  std::map<std::pair<int, int>, RunShape*> ranged_;
  std::map<std::vector<double>, RunShape*> by_content_;
};

}  // namespace sb::event_detail
