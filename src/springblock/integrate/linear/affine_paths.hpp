#pragma once
// The affine particular solution u_p = A + B t of a run of grooves held by stuck blocks (or free
// chain ends) at its two ends: the path a groove run settles onto once its transient has died,
// with
//   K B = K_s v 1,   K A = -m gamma B + K_int (u_left e_1 + u_right e_n),
// K the run's stiffness matrix (run_stiffness.hpp). The solution is linear in the two boundary
// positions, and K depends only on the run's length and whether each end is held, so the pieces
// B, a0 = K^-1 (-m gamma B), gL = K^-1 K_int e_1, gR = K^-1 K_int e_n are solved once per shape
// (a symmetric tridiagonal solve, O(n)) and a run's A, B cost one pass over its blocks.
#include <map>
#include <tuple>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

// The pieces of the affine path per run shape, cached: the one place the particular solution is
// computed, for settled grooves (AffinePaths), the quiet phase's groove runs and the modal runs
// (which subtract their sliding blocks' kinetic friction on top).
class AffineShapes {
 public:
  struct Shape {
    std::vector<double> B, a0, gL, gR;  // A = a0 + u_left gL + u_right gR
  };
  explicit AffineShapes(const Chain& c) : K_s_(c.K_s), K_int_(c.K_int), m_gamma_(c.m * c.gamma), v_(c.v_slider) {}
  // The run of n blocks, held at its left / right end by a stuck block or not (a free end).
  // References stay valid for the life of this object.
  const Shape& get(int n, bool left, bool right);

 private:
  double K_s_, K_int_, m_gamma_, v_;
  std::map<std::tuple<int, bool, bool>, Shape> shapes_;
  std::vector<double> diag_, off_, rhs_;  // tridiagonal work arrays
};

class AffinePaths {
 public:
  explicit AffinePaths(const Chain& c);

  // A, B of the grooves of run r from the positions of the stuck blocks beside it in s.
  void compute(const State& s, BlockRange r);
  // The path of block i (valid for the blocks of the last run computed that holds it).
  double u(int i, double t) const { return A_[i] + B_[i] * t; }
  double drift(int i) const { return B_[i]; }
  // Every block of r within eps_u of its path in u and eps_v in v at s.t.
  bool within(const State& s, BlockRange r, double eps_u, double eps_v) const;
  // Write the path's u, v at t for the blocks of r.
  void write(BlockRange r, double t, double* u, double* v) const;

 private:
  int N_;
  AffineShapes shapes_;
  std::vector<double> A_, B_;  // per block
};

}  // namespace sb::event_detail
