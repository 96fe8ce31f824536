#include "springblock/integrate/events/event_queue.hpp"

#include <algorithm>
#include <cstring>

#include "springblock/infinity.hpp"

namespace sb::event_detail {

EventQueue::Key EventQueue::key(double t, std::uint32_t tie) {
  // IEEE order as unsigned integers: flip every bit of a negative double, only the sign bit of
  // a positive one. Adding 0 first makes -0 into +0, which compares equal to it as a double.
  t += 0.0;
  std::uint64_t b;
  std::memcpy(&b, &t, sizeof b);
  b = (b >> 63) != 0 ? ~b : b | (std::uint64_t{1} << 63);
  return (Key(b) << 64) | tie;
}

EventQueue::Node EventQueue::leaf(int i) const {
  const bool rc = recheck_[i] != 0;
  const auto block = static_cast<std::uint32_t>(i);
  return {key(t_[i], (std::uint32_t{rc} << 31) | block), key(rc ? kInf : t_[i], block)};
}

EventQueue::EventQueue(int N) : t_(N, kInf), recheck_(N, 0), dirty_(N) {
  while (P_ < N) P_ *= 2;
  tree_.assign(2 * P_, Node{kEmpty, kEmpty});
  for (int i = 0; i < N; ++i) dirty_.add(i);
  refresh();
}

void EventQueue::set(int i, double t, bool recheck) {
  if (t_[i] == t && (recheck_[i] != 0) == recheck) return;
  t_[i] = t;
  recheck_[i] = recheck;
  dirty_.add(i);
}

void EventQueue::refresh() {
  // A block's leaf takes its new key here, and its climb stops at the first node whose keys do
  // not change: every node above it already holds the earliest of its subtree. Each climb leaves
  // the whole tree consistent, so the dirty blocks may climb in any order.
  for (int i : dirty_.list()) {
    tree_[P_ + i] = leaf(i);
    for (int n = (P_ + i) >> 1; n >= 1; n >>= 1) {
      const Node& l = tree_[2 * n];
      const Node& r = tree_[2 * n + 1];
      const Node w{std::min(l.all, r.all), std::min(l.real, r.real)};
      if (w.all == tree_[n].all && w.real == tree_[n].real) break;
      tree_[n] = w;
    }
  }
  dirty_.clear();
  const Node& top = tree_[1];
  const int b = top.all == kEmpty ? -1 : static_cast<int>(static_cast<std::uint32_t>(top.all) & 0x7fffffffu);
  const int e = top.real == kEmpty ? -1 : static_cast<int>(static_cast<std::uint32_t>(top.real));
  next_ = (b >= 0 && t_[b] < kInf) ? Next{t_[b], b, recheck_[b] != 0} : Next{kInf, -1, false};
  next_real_ = (e >= 0 && !recheck_[e]) ? t_[e] : kInf;
}

void EventQueue::offer(int i) {
  const bool rc = recheck_[i] != 0;
  // The main tree's order (its keys); with no entry yet (block -1, t = inf) only a finite time
  // counts.
  if (next_.block < 0 ? t_[i] < kInf : leaf(i).all < leaf(next_.block).all) next_ = {t_[i], i, rc};
  if (!rc && t_[i] < next_real_) next_real_ = t_[i];
}

}  // namespace sb::event_detail
