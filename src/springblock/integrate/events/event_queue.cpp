#include "springblock/integrate/events/event_queue.hpp"
#include "springblock/integrate/infinity.hpp"

namespace sb::event_detail {

EventQueue::EventQueue(int N) : N_(N), t_(N, kInf), recheck_(N, 0), dirty_(N, 0) {
  while (P_ < N_) P_ *= 2;
  tree_.assign(2 * P_, -1);
  for (int i = 0; i < N_; ++i) tree_[P_ + i] = i;
  for (int n = P_ - 1; n >= 1; --n) tree_[n] = earlier(tree_[2 * n + 1], tree_[2 * n]) ? tree_[2 * n + 1] : tree_[2 * n];
  tree_real_ = tree_;
}

void EventQueue::set(int i, double t, bool recheck) {
  if (t_[i] == t && (recheck_[i] != 0) == recheck) return;
  t_[i] = t;
  recheck_[i] = recheck;
  if (!dirty_[i]) dirty_[i] = 1, dirty_list_.push_back(i);
}

bool EventQueue::earlier(int a, int b) const {
  if (a < 0) return false;
  if (b < 0) return true;
  if (t_[a] != t_[b]) return t_[a] < t_[b];
  if (recheck_[a] != recheck_[b]) return recheck_[a] < recheck_[b];
  return a < b;
}

bool EventQueue::earlier_real(int a, int b) const {
  auto t = [&](int i) { return i < 0 || recheck_[i] ? kInf : t_[i]; };
  if (t(a) != t(b)) return t(a) < t(b);
  return a >= 0 && (b < 0 || a < b);
}

void EventQueue::refresh() {
  // The climb from a changed leaf stops at the first node whose winner, in both trees, is
  // unchanged and is not block i: no node above it depends on i then. A node whose winner is
  // another changed block is brought up to date by that block's own climb, which never stops
  // where its block wins. Every order is total (time, recheck, block), so each node holds the
  // unique earliest block of its subtree whatever order the climbs take.
  for (int i : dirty_list_) {
    dirty_[i] = 0;
    for (int n = (P_ + i) >> 1; n >= 1; n >>= 1) {
      const int l = 2 * n, r = 2 * n + 1;
      const int w = earlier(tree_[r], tree_[l]) ? tree_[r] : tree_[l];
      const int w_real = earlier_real(tree_real_[r], tree_real_[l]) ? tree_real_[r] : tree_real_[l];
      if (w == tree_[n] && w_real == tree_real_[n] && w != i && w_real != i) break;
      tree_[n] = w, tree_real_[n] = w_real;
    }
  }
  dirty_list_.clear();
  const int b = tree_[1], e = tree_real_[1];
  next_ = (b >= 0 && t_[b] < kInf) ? Next{t_[b], b, recheck_[b] != 0} : Next{kInf, -1, false};
  next_real_ = (e >= 0 && !recheck_[e]) ? t_[e] : kInf;
}

void EventQueue::offer(int i) {
  const bool rc = recheck_[i] != 0;
  // The trees' order; with no entry yet (block -1, t = inf) only a finite time counts.
  if (next_.block < 0 ? t_[i] < kInf : earlier(i, next_.block)) next_ = {t_[i], i, rc};
  if (!rc && t_[i] < next_real_) next_real_ = t_[i];
}

}  // namespace sb::event_detail
