#pragma once
// The totals a stretch of affine samples needs (FrictionObserver::sample_affine), kept up to date
// block by block instead of summed over the chain at every stretch.
//
// Between two events of a chain without internal springs every contact block's friction force is
// affine, f_i(t) = a_i + b_i t, and a stretch of samples starting at t_first needs, over the
// contact blocks, the sums of s_i a_i and s_i b_i with s_i the sign of f_i(t_first), the sums of
// a_i and b_i, the number sliding, and the earliest time at which some f_i changes sign. Summed
// afresh that is O(contact blocks) per stretch, and a stretch ends at every event of any block:
// in fig2's K_int = 0 chains that sum is 39 % of the run (paper/choices.md). Here the blocks are the leaves of a binary
// tree whose nodes hold their subtree's totals; an event changes one leaf and the nodes above it
// (O(log N)). A leaf's sign is taken when it is set and taken again, by the same expression,
// whenever the stretch starts at or after the time its force was due to change sign.
//
// The totals are sums in the tree's order, not in block order: they differ from the chain-order
// sums in the last bits (the tests compare them to round-off), and depend only on the leaves'
// current values, not on the history of updates (no drift, the same doubles whatever the order
// of the events that set them).
#include <cstdint>
#include <memory>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb {

struct AffineTotals {
  double A = 0, B = 0;    // sum of s_i a_i and s_i b_i: sum_i |f_i(t)| = A + B t in the stretch
  double As = 0, Bs = 0;  // sum of a_i and b_i: sum_i f_i(t) = As + Bs t
  double t_sign = 0;      // the earliest time some f_i changes sign (+inf if none)
  int n_sliding = 0;      // contact blocks sliding
};

// One force a + b t's share of the totals for a stretch starting at t: its sign there (0 counts
// as positive), and the time it reaches zero if it is heading there (+inf otherwise). The one rule
// both the tree and a sum over the chain (FrictionObserver) apply.
AffineTotals affine_share(double a, double b, bool sliding, double t);
// x + y: the sums added, the earlier sign change, the sliding counts added.
AffineTotals operator+(const AffineTotals& x, const AffineTotals& y);

class AffineForceTree {
 public:
  explicit AffineForceTree(const Chain& c);
  // Block i's force is a + b t from now on (sliding: whether it slides); its sign is taken at t.
  // Blocks without contact are ignored (their a and b stay 0).
  void set(int i, double a, double b, bool sliding, double t);
  // The totals for a stretch starting at t_first (t_first at or after every set's t).
  const AffineTotals& at(double t_first);
  // Every block's a and b (0 for blocks without contact): the forces themselves, by block.
  const double* a() const { return a_.data(); }
  const double* b() const { return b_.data(); }

 private:
  void combine(int node) { node_[node] = node_[2 * node] + node_[2 * node + 1]; }
  // Takes again, at t, the sign of every leaf under `node` whose force was due to change sign by
  // `due`.
  void refresh(int node, double due, double t);

  int size_ = 1;                       // leaves in the tree (a power of two)
  std::vector<int> leaf_of_;           // block -> leaf index (-1: no contact)
  std::vector<int> block_of_;          // leaf -> block (-1: padding)
  std::vector<double> a_, b_;          // per block
  std::vector<std::uint8_t> sliding_;  // per block
  std::vector<AffineTotals> node_;     // 1-based heap order; leaf k is node size_ + k
};

// The tree kept by an observer of a run whose forces change only when their own block switches
// (AffineForces::per_block, the per-block solver): the blocks switched since the last stretch
// (switched) have their leaves set again from the integrator's forces when the next stretch
// starts (at), every contact block's on the first. A leaf set at the stretch's start rather than
// at its block's switch takes the same sign: a force that changed sign in between was due to, and
// takes its sign again at the stretch's start either way.
class SwitchedTotals {
 public:
  void switched(const int* first, const int* last);
  const AffineTotals& at(const Chain& c, const State& s, const double* a, const double* b, double t_first);

 private:
  std::unique_ptr<AffineForceTree> tree_;
  std::vector<int> dirty_;
  std::vector<char> flagged_;  // per block: in dirty_
};

}  // namespace sb
