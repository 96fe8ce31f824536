// FrictionObserver::sample_affine against sample(): a stretch of samples in which every contact
// block is stuck on an affine force must give the same running maximum, peak time, end of
// loading and mu_d window as serving the samples one by one, including across a block whose
// force changes sign inside the stretch (where the affine shortcut has to stop) and under the
// drop rule (where the end of loading falls inside the stretch).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/observe/friction_observer.hpp"

namespace {

// Every block stuck at its own u, no grooves and no internal springs: f_i(t) = K_s (v t - u_i)
// is affine with a_i = f_i(0), b_i = K_s v. (The integrator's coefficients for coupled chains
// and grooves are checked through whole runs: the reproduction targets give the same digits.)
struct Affine {
  sb::Chain c;
  sb::State s;
  std::vector<double> a, b;
  explicit Affine(const std::vector<double>& u) {
    const int N = static_cast<int>(u.size());
    c = sbtest::hand_chain(std::vector<std::uint8_t>(N, 1), 0.0, 1e4, std::vector<double>(N, 1.0),
                           std::vector<double>(N, 0.5));
    s = sb::State::at_rest(c);
    s.u = u;
    a.resize(N), b.resize(N);
    for (int i = 0; i < N; ++i) {
      s.t = 0;
      a[i] = c.driving_force(i, s.u.data(), s.v.data(), 0.0);
      b[i] = c.K_s * c.v_slider;
    }
  }
};

struct Outcome {
  double mu_s, t_peak, mu_d, mu_d_signed;
  long window;
  bool slipped;
};

Outcome outcome(const sb::FrictionObserver& o) {
  return {o.max_mu(), o.t_peak(), o.mu_d(), o.mu_d_signed(), static_cast<long>(o.window_samples()), o.slipped()};
}

// Serve samples k0 .. k0+n-1 either one by one or through sample_affine (falling back to
// sample() whenever it takes none), the way the event integrator does.
void serve(sb::FrictionObserver& o, Affine& f, long k0, long n, double dt, bool affine, long* taken = nullptr) {
  long k = k0;
  while (k < k0 + n) {
    if (affine) {
      const long used = o.sample_affine(f.c, f.s, k, dt, k0 + n - k, sb::AffineForces{f.a.data(), f.b.data()});
      if (taken) *taken += used;
      if (used > 0) {
        k += used;
        continue;
      }
    }
    f.s.t = static_cast<double>(k) * dt;
    o.sample(f.c, f.s);
    ++k;
  }
}

void expect_same(const Outcome& x, const Outcome& y) {
  EXPECT_DOUBLE_EQ(x.mu_s, y.mu_s);
  EXPECT_DOUBLE_EQ(x.t_peak, y.t_peak);
  EXPECT_EQ(x.window, y.window);
  EXPECT_EQ(x.slipped, y.slipped);
  // The window sums are closed-form sums against a running sum: equal to round-off.
  if (x.window > 0) {
    EXPECT_NEAR(x.mu_d, y.mu_d, 1e-13 * std::fabs(y.mu_d));
    EXPECT_NEAR(x.mu_d_signed, y.mu_d_signed, 1e-13 * std::fabs(y.mu_d_signed));
  }
}

// Forces at t = 0 of 1.0, 1.2, -0.5, 0.8 and 1.1 N (u = -f / K_s); block 2's rises through zero
// at t = 0.1 s (b = K_s v = 5 N/s), inside the stretch.
const std::vector<double> kU = {-1e-4, -1.2e-4, 5e-5, -8e-5, -1.1e-4};

TEST(AffineSamples, LoadingPhaseMatchesOneByOne) {
  sb::FrictionObserverConfig cfg;
  Affine f1(kU), f2(kU);
  cfg.F_load = f1.c.F_load;
  sb::FrictionObserver one(cfg), many(cfg);
  long taken = 0;
  serve(one, f1, 0, 40000, 1e-5, false);
  serve(many, f2, 0, 40000, 1e-5, true, &taken);
  expect_same(outcome(many), outcome(one));
  // The sign change of block 2 splits the stretch; everything else went through the shortcut.
  EXPECT_GT(taken, 39000);
  EXPECT_LT(taken, 40000);
}

TEST(AffineSamples, DynamicPhaseWindowMatchesOneByOne) {
  sb::FrictionObserverConfig cfg;
  Affine f1(kU), f2(kU);
  for (Affine* f : {&f1, &f2}) {
    std::fill(f->s.slipped_once.begin(), f->s.slipped_once.end(), 1);
    f->s.n_slipped_once = f->c.n_contact;  // loading ends at the first sample
  }
  cfg.F_load = f1.c.F_load;
  cfg.mu_d_skip_s = 0.05;
  sb::FrictionObserver one(cfg), many(cfg);
  serve(one, f1, 3, 30000, 1e-5, false);
  serve(many, f2, 3, 30000, 1e-5, true);
  expect_same(outcome(many), outcome(one));
  EXPECT_GT(outcome(one).window, 20000);
}

TEST(AffineSamples, DropRuleEndsLoadingInsideTheStretch) {
  // Forces that fall: u moves ahead of the slider (v = 0 here), so mu decreases from the start
  // and the drop rule ends loading partway through the stretch.
  sb::FrictionObserverConfig cfg;
  Affine f1(kU), f2(kU);
  for (Affine* f : {&f1, &f2})
    for (double& x : f->b) x = -2.0;
  cfg.F_load = f1.c.F_load;
  cfg.peak_rule = sb::ExtractionRules::PeakRule::Drop;
  cfg.peak_drop = 0.05;
  sb::FrictionObserver one(cfg), many(cfg);
  // sample() reads the chain's own forces: give it the same falling load through v_slider.
  f1.c.v_slider = -2.0 / f1.c.K_s;
  f2.c.v_slider = f1.c.v_slider;
  serve(one, f1, 0, 20000, 1e-5, false);
  serve(many, f2, 0, 20000, 1e-5, true);
  ASSERT_TRUE(outcome(one).slipped);
  expect_same(outcome(many), outcome(one));
}

}  // namespace
