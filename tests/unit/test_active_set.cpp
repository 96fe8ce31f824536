// Tests of the active set that localises the event-driven stepper: which runs are stepped, which
// stuck blocks are watched, the settled grooves' affine solution against the equations of motion,
// and the closed-form threshold crossing of a stuck block with no stepped neighbour.
#include "springblock/integrate/events/active_set.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "hand_chain.hpp"

namespace {

using sb::event_detail::ActiveSet;

// Ten blocks: pawls 0-2 and 5-7, grooves 3-4 (held by two stuck blocks) and 8-9 (free end).
sb::Chain grooved(double gamma) {
  return sbtest::hand_chain({1, 1, 1, 0, 0, 1, 1, 1, 0, 0}, 7.3e5, gamma, std::vector<double>(10, 1.0),
                            std::vector<double>(10, 0.5));
}

const double kAtolU = 4e-13, kAtolV = 4e-13 * 6.45e4;

// Put every groove block on its quasi-static path u = A + B t (no transient), solved here with
// a dense Eigen solve of the grooves' equations, independently of the active set's tridiagonal
// solver: K B = K_s v 1 and K A = b - m gamma B, K the grooves' stiffness with the contact blocks
// held where they are.
void settle_grooves(const sb::Chain& c, sb::State& s) {
  std::vector<int> g;
  for (int i = 0; i < c.N; ++i)
    if (!c.contact[i]) g.push_back(i);
  const int n = static_cast<int>(g.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd load(n), b(n);
  for (int r = 0; r < n; ++r) {
    const int i = g[r];
    K(r, r) = c.K_s;
    load(r) = c.K_s * c.v_slider;
    b(r) = 0;
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= c.N) continue;
      K(r, r) += c.K_int;
      if (c.contact[j]) {
        b(r) += c.K_int * s.u[j];
      } else {
        const int q = static_cast<int>(std::find(g.begin(), g.end(), j) - g.begin());
        K(r, q) -= c.K_int;
      }
    }
  }
  const Eigen::VectorXd B = K.fullPivLu().solve(load);
  const Eigen::VectorXd A = K.fullPivLu().solve(b - c.m * c.gamma * B);
  for (int r = 0; r < n; ++r) {
    s.u[g[r]] = A(r) + B(r) * s.t;
    s.v[g[r]] = B(r);
  }
}

TEST(ActiveSet, StepsOnlyRunsThatMoveAndWatchesTheirStuckNeighbours) {
  const sb::Chain c = grooved(1e4);
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  s.dir[1] = 1;  // block 1 slides; 0 and 2 are stuck beside it
  // Groove 3-4 rings, groove 8-9 sits on its (approximate) quasi-static solution.
  settle_grooves(c, s);
  s.v[3] += 1e-3;
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, true, kAtolU, kAtolV);
  a.rebuild(c, s);
  std::vector<std::pair<int, int>> spans;
  for (const auto& sp : a.stepped()) spans.emplace_back(sp.lo, sp.hi);
  const std::vector<std::pair<int, int>> expect_spans = {{1, 2}, {3, 5}};
  EXPECT_EQ(spans, expect_spans);
  // Watched: the slider's stuck neighbours 0 and 2 (2 also borders the ringing groove), the
  // sliding block itself, and 5 beside the ringing groove. Nothing beyond.
  EXPECT_EQ(a.watched(), (std::vector<int>{0, 1, 2, 5}));
  EXPECT_EQ(a.kind(8), ActiveSet::kSettled);
  EXPECT_EQ(a.kind(6), ActiveSet::kStuck);
  // Without settling (the reference mode) the quiet groove is stepped as well.
  sb::event_detail::RunStore ref_store(c);
  ActiveSet ref(c, ref_store, false, kAtolU, kAtolV);
  ref.rebuild(c, s);
  EXPECT_EQ(ref.stepped().size(), 3u);
  EXPECT_EQ(ref.kind(8), ActiveSet::kStepped);
}

TEST(ActiveSet, UncoupledBlocksAreEachTheirOwnRun) {
  sb::Chain c = grooved(1e4);
  c.K_int = 0;
  sb::State s = sb::State::at_rest(c);
  s.dir[1] = s.dir[2] = 1;
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, false, kAtolU, kAtolV);
  a.rebuild(c, s);
  // Blocks 1 and 2 slide side by side but do not interact: separate runs, no stuck block watched.
  ASSERT_GE(a.stepped().size(), 2u);
  EXPECT_EQ(a.stepped()[0].lo, 1);
  EXPECT_EQ(a.stepped()[0].hi, 2);
  EXPECT_EQ(a.watched(), (std::vector<int>{1, 2}));
}

TEST(ActiveSet, SettledGrooveIsTheParticularSolutionOfItsEquations) {
  for (double gamma : {1e4, 0.0}) {
    const sb::Chain c = grooved(gamma);
    sb::State s = sb::State::at_rest(c);
    s.t = 0.02;
    for (int i = 0; i < c.N; ++i) s.u[i] = 1e-6 * std::sin(1.0 + i);
    settle_grooves(c, s);
    sb::event_detail::RunStore a_store(c);
    ActiveSet a(c, a_store, true, kAtolU, kAtolV);
    a.rebuild(c, s);
    // The groove positions relaxed above are within round-off of the active set's A + B t, so
    // both grooves are settled and nothing is stepped.
    EXPECT_TRUE(a.stepped().empty()) << "gamma " << gamma;
    ASSERT_EQ(a.kind(3), ActiveSet::kSettled);
    // A + B t solves m u'' + m gamma u' + K u = K_s v t + b exactly: u'' = 0, u' = B, so the
    // net force on every groove block (damping included) vanishes at any time, here long after
    // the rebuild. Scale of the terms: K_int times the groove displacements (~1e-6 m).
    for (double t : {0.02, 0.5, 3.0}) {
      std::vector<double> u = s.u, v = s.v;
      a.materialise(t, u.data(), v.data());
      for (int i : {3, 4, 8, 9}) {
        const double F = c.driving_force(i, u.data(), v.data(), t);
        EXPECT_NEAR(F, 0.0, 1e-9 * c.K_int * 1e-6) << "gamma " << gamma << " block " << i << " t " << t;
      }
    }
  }
}

TEST(ActiveSet, ClosedFormCrossingReachesTheThresholdExactly) {
  const sb::Chain c = grooved(1e4);
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  settle_grooves(c, s);
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, true, kAtolU, kAtolV);
  a.rebuild(c, s);
  ASSERT_TRUE(a.watched().empty());  // nothing slides, nothing rings
  const auto next = a.next_crossing();
  ASSERT_GE(next.block, 0);
  ASSERT_GT(next.t, s.t);
  // At the predicted instant the block's force (neighbours on their affine paths) is at its
  // threshold, and every other stuck block is still below its own.
  std::vector<double> u = s.u, v = s.v;
  a.materialise(next.t, u.data(), v.data());
  for (int i = 0; i < c.N; ++i) {
    if (!c.contact[i]) continue;
    const double F = c.driving_force(i, u.data(), v.data(), next.t);
    if (i == next.block)
      EXPECT_NEAR(std::fabs(F), c.f_static[i], 1e-12 * c.f_static[i]);
    else
      EXPECT_LE(std::fabs(F), c.f_static[i] * (1 + 1e-12)) << "block " << i;
  }
}

TEST(ActiveSet, RingingGrooveRetiresOnceItsTransientIsBelowTolerance) {
  const sb::Chain c = grooved(1e4);
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  settle_grooves(c, s);
  s.v[4] += 10 * kAtolV;  // a transient ten times the tolerance
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, true, kAtolU, kAtolV);
  a.rebuild(c, s);
  EXPECT_EQ(a.kind(4), ActiveSet::kStepped);
  EXPECT_FALSE(a.retire_settled(c, s));  // still ringing: stays
  s.v[4] -= 10 * kAtolV - 0.05 * kAtolV;  // decayed to 5 % of it
  EXPECT_TRUE(a.retire_settled(c, s));
  EXPECT_EQ(a.kind(4), ActiveSet::kSettled);
  EXPECT_TRUE(a.stepped().empty());
  // The stuck blocks beside it now have closed-form crossings.
  EXPECT_GE(a.next_crossing().block, 0);
}

TEST(ActiveSet, ShortRunsAreSteppedUntilTheyOutlastASlip) {
  // A sliding block alone between stuck neighbours is stepped when its run forms, and becomes
  // modal (its stop and its neighbours' crossings searched on its modes) only once it has slid
  // for promote_age() with nothing in or beside it switching; a switch beside it reshapes the
  // run, which is stepped again and ages afresh.
  const sb::Chain c = grooved(1e4);
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  settle_grooves(c, s);
  s.dir[1] = 1;  // block 1 slides between stuck pawls 0 and 2
  s.v[1] = 0.1 * c.v_slider;
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, true, kAtolU, kAtolV, 2, 64, 1.0);
  a.rebuild(c, s);
  EXPECT_EQ(a.kind(1), ActiveSet::kStepped);
  EXPECT_EQ(a.watched(), (std::vector<int>{0, 1, 2}));
  const double due = s.t + a.promote_age();
  EXPECT_EQ(a.next_promotion(), due);
  // Two periods of the fastest mode, sqrt((K_s + 4 K_int) / m).
  EXPECT_NEAR(a.promote_age(), 4 * M_PI / std::sqrt((c.K_s + 4 * c.K_int) / c.m), 1e-15 * a.promote_age());
  s.t = std::nextafter(due, 0.0);
  EXPECT_FALSE(a.promote_runs(c, s));
  EXPECT_EQ(a.kind(1), ActiveSet::kStepped);
  s.t = due;
  EXPECT_TRUE(a.promote_runs(c, s));
  EXPECT_EQ(a.kind(1), ActiveSet::kModal);
  EXPECT_TRUE(a.stepped().empty());
  EXPECT_TRUE(a.watched().empty());
  EXPECT_EQ(a.next_promotion(), std::numeric_limits<double>::infinity());
  // Its events are now searched on its modes: the next one is in the future.
  EXPECT_GT(a.next_crossing().t, s.t);
  // Block 0 starts to slide beside it: the run {0, 1} is new, so it is stepped and ages afresh.
  s.dir[0] = 1;
  std::vector<std::uint8_t> touched(c.N, 0);
  touched[0] = 1;
  a.materialise(s.t, s.u.data(), s.v.data());
  a.update(c, s, touched.data(), {0});
  EXPECT_EQ(a.kind(0), ActiveSet::kStepped);
  EXPECT_EQ(a.kind(1), ActiveSet::kStepped);
  EXPECT_EQ(a.next_promotion(), s.t + a.promote_age());
}

TEST(ActiveSet, ModalGrooveFarFromASwitchSettlesAtTheFirstSwitchAfterItsTransientIsGone) {
  // A switch renews only the runs beside it; a modal grooves-only run elsewhere changes kind with
  // time alone: it stays modal at a switch before its transient has died and is settled at the
  // first switch after, though nothing in or beside it switched.
  const sb::Chain c = grooved(1e4);
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  settle_grooves(c, s);
  s.v[3] += 100 * kAtolV;  // groove 3-4 rings
  s.dir[1] = 1;            // block 1 slides, pawl blocks 0 and 2 stuck around it
  s.v[1] = 0.1 * c.v_slider;
  sb::event_detail::RunStore a_store(c);
  ActiveSet a(c, a_store, true, kAtolU, kAtolV, 0, 64, 1.0);
  a.rebuild(c, s);
  ASSERT_EQ(a.kind(3), ActiveSet::kModal);
  ASSERT_EQ(a.kind(1), ActiveSet::kStepped);
  std::vector<std::uint8_t> touched(c.N, 0);
  auto switch_block_1 = [&](double t, std::int8_t dir) {
    s.t = t;
    s.dir[1] = dir;
    s.v[1] = dir != 0 ? 0.1 * c.v_slider : 0.0;
    touched[1] = 1;
    a.update(c, s, touched.data(), {1});
    touched[1] = 0;
  };
  // Block 1 stops 0.1 us later: the groove's transient (decay rate gamma / 2) is still there.
  switch_block_1(0.01 + 1e-7, 0);
  EXPECT_EQ(a.kind(3), ActiveSet::kModal);
  EXPECT_EQ(a.kind(4), ActiveSet::kModal);
  EXPECT_TRUE(a.stepped().empty());
  // It starts again 50 ms later, long after the transient fell below the settle scales.
  switch_block_1(0.06, 1);
  EXPECT_EQ(a.kind(3), ActiveSet::kSettled);
  EXPECT_EQ(a.kind(4), ActiveSet::kSettled);
  ASSERT_EQ(a.stepped().size(), 1u);
  EXPECT_EQ(a.stepped()[0].lo, 1);
  EXPECT_EQ(a.stepped()[0].hi, 2);
  EXPECT_EQ(a.watched(), (std::vector<int>{0, 1, 2}));
}

}  // namespace
