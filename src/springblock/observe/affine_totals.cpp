#include "springblock/observe/affine_totals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "springblock/infinity.hpp"

namespace sb {

AffineTotals affine_share(double a, double b, bool sliding, double t) {
  const double sg = a + b * t >= 0 ? 1.0 : -1.0;
  return {sg * a, sg * b, a, b, b != 0.0 && (b > 0) != (sg > 0) ? -a / b : kInf, sliding ? 1 : 0};
}

AffineTotals operator+(const AffineTotals& x, const AffineTotals& y) {
  return {x.A + y.A, x.B + y.B, x.As + y.As, x.Bs + y.Bs, std::min(x.t_sign, y.t_sign), x.n_sliding + y.n_sliding};
}

AffineForceTree::AffineForceTree(const Chain& c) : leaf_of_(c.N, -1), a_(c.N, 0.0), b_(c.N, 0.0), sliding_(c.N, 0) {
  int n = 0;
  for (int i = 0; i < c.N; ++i)
    if (c.contact[i]) leaf_of_[i] = n++;
  while (size_ < n) size_ *= 2;
  block_of_.assign(size_, -1);
  for (int i = 0; i < c.N; ++i)
    if (leaf_of_[i] >= 0) block_of_[leaf_of_[i]] = i;
  node_.assign(2 * size_, AffineTotals{});
  for (auto& x : node_) x.t_sign = kInf;
}

void AffineForceTree::set(int i, double a, double b, bool sliding, double t) {
  const int leaf = leaf_of_[i];
  if (leaf < 0) return;
  a_[i] = a, b_[i] = b, sliding_[i] = sliding;
  int k = size_ + leaf;
  node_[k] = affine_share(a, b, sliding, t);
  for (k /= 2; k >= 1; k /= 2) combine(k);
}

void AffineForceTree::refresh(int k, double due, double t) {
  if (!(node_[k].t_sign <= due)) return;
  if (k >= size_) {
    const int i = block_of_[k - size_];  // a padding leaf never has a sign change due
    node_[k] = affine_share(a_[i], b_[i], sliding_[i] != 0, t);
    return;
  }
  refresh(2 * k, due, t);
  refresh(2 * k + 1, due, t);
  combine(k);
}

const AffineTotals& AffineForceTree::at(double t_first) {
  // A leaf whose force was due to reach zero by t_first takes its sign again at t_first. Its
  // zero time -a / b is rounded, so a leaf within a few ulp of it is taken again too: the sign
  // then comes from the same expression as a sum over the chain at t_first would give. A force
  // still negative there by round-off keeps its zero time, and the stretch stops before it.
  refresh(1, t_first + 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(t_first), t_first);
  return node_[1];
}

void SwitchedTotals::switched(const int* first, const int* last) {
  if (!tree_) return;  // the first stretch sets every leaf
  for (const int* i = first; i != last; ++i)
    if (!flagged_[*i]) flagged_[*i] = 1, dirty_.push_back(*i);
}

const AffineTotals& SwitchedTotals::at(const Chain& c, const State& s, const double* a, const double* b,
                                       double t_first) {
  if (!tree_) {
    tree_ = std::make_unique<AffineForceTree>(c);
    flagged_.assign(c.N, 0);
    for (int i = 0; i < c.N; ++i) tree_->set(i, a[i], b[i], s.dir[i] != 0, t_first);
  }
  for (int i : dirty_) tree_->set(i, a[i], b[i], s.dir[i] != 0, t_first), flagged_[i] = 0;
  dirty_.clear();
  return tree_->at(t_first);
}

}  // namespace sb
