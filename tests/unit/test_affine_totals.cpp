// AffineForceTree (observe/affine_totals.hpp) against the totals FrictionObserver::sample_affine
// sums over the chain in block order, and the exact per-block solver (K_int = 0) with the tree
// against the same solver whose observer sums every stretch itself.
#include "springblock/observe/affine_totals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "forwarding_observer.hpp"
#include "hand_chain.hpp"
#include "springblock/integrate/methods/event_driven.hpp"
#include "springblock/observe/friction_observer.hpp"

namespace {

// The totals as sample_affine forms them without the tree: signs at t_first, in block order.
sb::AffineTotals block_order(const sb::Chain& c, const std::vector<double>& a, const std::vector<double>& b,
                             const std::vector<bool>& sliding, double t_first) {
  sb::AffineTotals x;
  x.t_sign = std::numeric_limits<double>::infinity();
  for (int i = 0; i < c.N; ++i) {
    if (!c.contact[i]) continue;
    const double sg = a[i] + b[i] * t_first >= 0 ? 1.0 : -1.0;
    if (b[i] != 0.0 && (b[i] > 0) != (sg > 0)) x.t_sign = std::min(x.t_sign, -a[i] / b[i]);
    x.A += sg * a[i], x.B += sg * b[i];
    x.As += a[i], x.Bs += b[i];
    x.n_sliding += sliding[i] ? 1 : 0;
  }
  return x;
}

// Stuck blocks (slope b > 0) whose forces cross zero between updates, sliding blocks (b = 0) of
// either sign, grooves (not counted), updated a few at a time as events would: after each
// batch, the totals for a stretch starting later must be the block-order ones, the sign change
// time and the sliding count exactly, the sums to round-off. Made to fail by not taking the
// signs again (AffineForceTree::refresh skipped): A and t_sign then go wrong once a force
// crosses zero.
TEST(AffineTotals, EqualTheBlockOrderSumsAcrossSignChanges) {
  const int N = 203;
  std::vector<std::uint8_t> contact(N, 1);
  for (int i = 5; i < N; i += 17) contact[i] = 0;
  const sb::Chain c = sbtest::hand_chain(contact, 0.0, 1e4, std::vector<double>(N, 1.0), std::vector<double>(N, 0.5));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> a(N), b(N);
  std::vector<bool> sliding(N);
  sb::AffineForceTree tree(c);
  const double slope = 2.0;
  auto reset = [&](int i, double t) {
    sliding[i] = U(rng) > 0.6;
    // A stuck block's force reaches zero within the next few time units, or already has.
    a[i] = sliding[i] ? U(rng) : -slope * (t + 3.0 * (U(rng) + 0.5));
    b[i] = sliding[i] ? 0.0 : slope;
    tree.set(i, a[i], b[i], sliding[i], t);
  };
  double t = 0;
  for (int i = 0; i < N; ++i) reset(i, t);
  int crossings = 0;
  for (int step = 0; step < 400; ++step) {
    t += 0.05 * (1.0 + U(rng));
    // Some stretches start exactly where a force reaches zero: the sign there is the
    // expression's, whichever way round-off takes it.
    if (step % 7 == 3)
      for (int i = 0; i < N; ++i)
        if (contact[i] && b[i] > 0 && -a[i] / b[i] > t) {
          t = -a[i] / b[i];
          break;
        }
    const sb::AffineTotals want = block_order(c, a, b, sliding, t);
    const sb::AffineTotals& got = tree.at(t);
    double scale = 0;
    for (int i = 0; i < N; ++i) scale += std::fabs(a[i]) + std::fabs(b[i]) * t;
    EXPECT_NEAR(got.A, want.A, 1e-13 * scale) << "step " << step;
    EXPECT_NEAR(got.B, want.B, 1e-13 * scale) << "step " << step;
    EXPECT_NEAR(got.As, want.As, 1e-13 * scale) << "step " << step;
    EXPECT_NEAR(got.Bs, want.Bs, 1e-13 * scale) << "step " << step;
    EXPECT_EQ(got.t_sign, want.t_sign) << "step " << step;
    EXPECT_EQ(got.n_sliding, want.n_sliding) << "step " << step;
    for (int i = 0; i < N; ++i) crossings += contact[i] && b[i] > 0 && a[i] + b[i] * t >= 0;
    for (int k = 0; k < 3; ++k) reset(static_cast<int>(rng() % N), t);
  }
  EXPECT_GT(crossings, 1000);  // the test saw forces that had crossed zero since they were set
}

// Forwards to a friction observer per-block stretches as any others, so it sums every stretch over
// the chain in block order instead of keeping the tree.
class SumsItself final : public sbtest::Forwarding {
 public:
  using Forwarding::Forwarding;
  long sample_affine(const sb::Chain& c, const sb::State& s, long k0, double dt, long n,
                     const sb::AffineForces& f) override {
    with_totals += f.per_block;
    return inner_.sample_affine(c, s, k0, dt, n, sb::AffineForces{f.a, f.b});
  }
  long with_totals = 0;
};

// A K_int = 0 chain of 40 blocks with grooves run by the exact per-block solver: mu_s, its time
// and mu_d with the tree's totals equal those of the observer summing each stretch itself (the
// same signs and stretches, sums to round-off). Made to fail by a refresh that takes the signs
// again but leaves the sums of the nodes above them stale (both tests here fail).
TEST(AffineTotals, UncoupledRunsGiveTheSameStatisticsAsSummingEachStretch) {
  const int N = 40;
  std::vector<std::uint8_t> contact(N, 1);
  std::vector<double> mu_s(N), mu_d(N);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> G(0.0, 1.0);
  for (int i = 0; i < N; ++i) {
    contact[i] = i % 9 != 4;
    mu_s[i] = contact[i] ? 1.0 + 0.1 * G(rng) : 0.0;
    mu_d[i] = contact[i] ? std::min(mu_s[i], 0.5 + 0.01 * G(rng)) : 0.0;
  }
  for (double gamma : {1e4, 0.0}) {
    const sb::Chain c = sbtest::hand_chain(contact, 0.0, gamma, mu_s, mu_d);
    const double t0 = c.F_n * 1.0 / (c.K_s * c.v_slider);  // the loading time of mu_s = 1
    sb::FrictionObserverConfig cfg;
    cfg.F_load = c.F_n * c.n_contact;
    cfg.mu_d_skip_s = 0.25 * t0;
    sb::FrictionObserver tree_obs(cfg), own_obs(cfg);
    SumsItself own(own_obs);
    sb::State a = sb::State::at_rest(c), b = sb::State::at_rest(c);
    sb::EventDriven ev(1e-9, true);
    ev.run(c, a, 6 * t0, 1e-5, tree_obs);
    ev.run(c, b, 6 * t0, 1e-5, own);
    std::printf("gamma %g: %ld stretches with totals, %llu window samples, mu_d %.6f\n", gamma, own.with_totals,
                static_cast<unsigned long long>(own_obs.window_samples()), own_obs.mu_d());
    EXPECT_GT(own.with_totals, 100) << "gamma " << gamma;
    ASSERT_TRUE(tree_obs.slipped());
    EXPECT_EQ(tree_obs.window_samples(), own_obs.window_samples());
    EXPECT_EQ(tree_obs.t_peak(), own_obs.t_peak());
    EXPECT_NEAR(tree_obs.max_mu(), own_obs.max_mu(), 1e-14);
    EXPECT_NEAR(tree_obs.mu_d(), own_obs.mu_d(), 1e-13);
    EXPECT_NEAR(tree_obs.mu_d_signed(), own_obs.mu_d_signed(), 1e-13);
  }
}

}  // namespace
