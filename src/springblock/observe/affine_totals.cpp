#include "springblock/observe/affine_totals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sb {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}

AffineForceTree::AffineForceTree(const Chain& c) : leaf_of_(c.N, -1) {
  int n = 0;
  for (int i = 0; i < c.N; ++i)
    if (c.contact[i]) leaf_of_[i] = n++;
  while (size_ < n) size_ *= 2;
  leaves_.assign(size_, Leaf{});
  node_.assign(2 * size_, AffineTotals{});
  for (auto& x : node_) x.t_sign = kNever;
}

// A leaf's totals with its sign at t, as FrictionObserver::sample_affine takes it for a stretch
// starting at t: the sign of a + b t (0 counts as positive), and the time the force reaches zero
// if it is heading there.
void AffineForceTree::take_sign(const Leaf& f, double t, AffineTotals& node) {
  const double sg = f.a + f.b * t >= 0 ? 1.0 : -1.0;
  node.A = sg * f.a, node.B = sg * f.b;
  node.As = f.a, node.Bs = f.b;
  node.t_sign = f.b != 0.0 && (f.b > 0) != (sg > 0) ? -f.a / f.b : kNever;
  node.n_sliding = f.sliding ? 1 : 0;
}

void AffineForceTree::combine(int k) {
  const AffineTotals &l = node_[2 * k], &r = node_[2 * k + 1];
  AffineTotals& x = node_[k];
  x.A = l.A + r.A, x.B = l.B + r.B;
  x.As = l.As + r.As, x.Bs = l.Bs + r.Bs;
  x.t_sign = std::min(l.t_sign, r.t_sign);
  x.n_sliding = l.n_sliding + r.n_sliding;
}

void AffineForceTree::set(int i, double a, double b, bool sliding, double t) {
  const int leaf = leaf_of_[i];
  if (leaf < 0) return;
  leaves_[leaf] = {a, b, sliding};
  int k = size_ + leaf;
  take_sign(leaves_[leaf], t, node_[k]);
  for (k /= 2; k >= 1; k /= 2) combine(k);
}

void AffineForceTree::refresh(int k, double due, double t) {
  if (!(node_[k].t_sign <= due)) return;
  if (k >= size_) {
    take_sign(leaves_[k - size_], t, node_[k]);
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

}  // namespace sb
