// EventQueue against what it stands for: after every refresh(), next() and next_real() equal a
// full scan of the entries in block order (earliest t, a real event before a recheck, then the
// lower block; next_real ignores rechecks). Random changes in batches of one to many blocks,
// with ties and infinities on purpose: a changed block that was and stays the winner, two
// changed blocks under one node, a winner that loses to an unchanged block. (A level-by-level
// update with early stops was tried against this test and measured no faster: perf, smooth
// N = 200, mu_d 0.9, 7 % of the run in refresh() before and after.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "springblock/integrate/events/event_queue.hpp"

namespace {

using sb::event_detail::EventQueue;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Entry {
  double t = kInf;
  bool recheck = false;
};

EventQueue::Next scan(const std::vector<Entry>& e) {
  EventQueue::Next best{kInf, -1, false};
  for (int i = 0; i < static_cast<int>(e.size()); ++i) {
    if (!(e[i].t < kInf)) continue;
    const bool better = best.block < 0 || e[i].t < best.t || (e[i].t == best.t && !e[i].recheck && best.recheck);
    if (better) best = {e[i].t, i, e[i].recheck};
  }
  return best;
}

double scan_real(const std::vector<Entry>& e) {
  double best = kInf;
  for (const Entry& x : e)
    if (!x.recheck && x.t < best) best = x.t;
  return best;
}

void run_trial(int N, unsigned seed, int max_batch) {
  std::mt19937 rng(seed);
  // Few distinct times, so that ties are common.
  std::uniform_int_distribution<int> pick_t(0, 12), pick_block(0, N - 1), batch(1, max_batch), coin(0, 3);
  EventQueue q(N);
  std::vector<Entry> e(N);
  q.refresh();
  for (int round = 0; round < 400; ++round) {
    const int n = batch(rng);
    for (int k = 0; k < n; ++k) {
      const int i = pick_block(rng);
      const int tt = pick_t(rng);
      e[i].t = tt == 12 ? kInf : 1.0 + 0.25 * tt;
      e[i].recheck = coin(rng) == 0;
      q.set(i, e[i].t, e[i].recheck);
    }
    q.refresh();
    const EventQueue::Next want = scan(e), got = q.next();
    ASSERT_EQ(got.block, want.block) << "N " << N << " seed " << seed << " round " << round;
    if (want.block >= 0) {
      ASSERT_EQ(got.t, want.t);
      ASSERT_EQ(got.recheck, want.recheck);
    } else {
      ASSERT_FALSE(got.t < kInf);
    }
    ASSERT_EQ(q.next_real(), scan_real(e)) << "N " << N << " seed " << seed << " round " << round;
  }
}

TEST(EventQueue, NextEqualsAFullScanAfterEveryRefresh) {
  for (int N : {1, 2, 3, 7, 8, 9, 64, 200, 361})
    for (unsigned seed = 1; seed <= 6; ++seed) {
      run_trial(N, seed, 1);
      run_trial(N, 100 + seed, 4);
      run_trial(N, 200 + seed, N);
    }
}

// A block that holds the earliest entry moves later, by one change and again with its neighbours:
// the trees must give the lead back to an unchanged block.
TEST(EventQueue, AWinnerThatMovesLaterHandsTheLeadOn) {
  EventQueue q(16);
  for (int i = 0; i < 16; ++i) q.set(i, 10.0 + i, false);
  q.refresh();
  EXPECT_EQ(q.next().block, 0);
  q.set(0, 100.0, false);
  q.refresh();
  EXPECT_EQ(q.next().block, 1);
  EXPECT_EQ(q.next_real(), 11.0);
  q.set(1, 5.0, true);  // earliest, but a recheck: next() takes it, next_real() does not
  q.refresh();
  EXPECT_EQ(q.next().block, 1);
  EXPECT_TRUE(q.next().recheck);
  EXPECT_EQ(q.next_real(), 12.0);
}

}  // namespace
