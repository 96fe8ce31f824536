// The first-peak rules on synthetic mu(t) histories. Drop rule: dips smaller than peak_drop do
// not end the loading phase; the first larger drop does. All-slipped rule: only the
// moment every contact block has slid once ends it, however large a precursor's dip. Either way
// mu_s is the peak reached before the end of loading.
#include <gtest/gtest.h>

#include "springblock/ensemble.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {
// A one-block "chain" whose friction equals its driving force K_s (v t - u): choosing u per
// sample scripts any mu(t) we like.
struct Scripted {
  Chain c;
  State s;
  Scripted() {
    c.N = 1;
    c.K_s = 1;
    c.v_slider = 0;
    c.F_load = 1;
    c.F_n = 1;
    c.contact = {1};
    c.f_static = {10};
    c.f_kinetic = {0.5};
    c.mu_s = {10};
    c.mu_d = {0.5};
    c.n_contact = 1;
    s = State::at_rest(c);
  }
  // Two contact blocks whose friction is scripted: block 0 carries mu, block 1 none.
  void make_two_blocks() {
    c.N = 2;
    c.contact = {1, 1};
    c.f_static = {10, 10};
    c.f_kinetic = {0.5, 0.5};
    c.mu_s = {10, 10};
    c.mu_d = {0.5, 0.5};
    c.n_contact = 2;
    s = State::at_rest(c);
  }
  void feed(FrictionObserver& obs, double t, double mu) {
    s.t = t;
    s.u[0] = -mu;  // friction = K_s (0 - u) = mu
    obs.sample(c, s);
  }
};
}  // namespace

TEST(FirstPeak, PrecursorDipsDoNotCount) {
  Scripted sc;
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::Drop;
  cfg.peak_drop = 0.05;
  FrictionObserver obs(cfg);
  double t = 0;
  for (double mu = 0; mu < 0.6; mu += 0.01) sc.feed(obs, t += 1, mu);
  sc.feed(obs, t += 1, 0.57);  // precursor: 0.03 below the running max
  EXPECT_FALSE(obs.slipped());
  for (double mu = 0.57; mu < 0.73; mu += 0.01) sc.feed(obs, t += 1, mu);
  const double peak = obs.max_mu();
  sc.feed(obs, t += 1, 0.50);  // macroscopic slip
  EXPECT_TRUE(obs.slipped());
  EXPECT_DOUBLE_EQ(obs.mu_s(), peak);
  EXPECT_GT(obs.mu_s(), 0.72);
}

TEST(FirstPeak, MuDAveragesOnlyTheWindowAfterTheSlip) {
  Scripted sc;
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::Drop;
  cfg.peak_drop = 0.05;
  cfg.mu_d_skip_s = 10;
  FrictionObserver obs(cfg);
  sc.feed(obs, 0, 0.0);
  sc.feed(obs, 1, 0.8);
  sc.feed(obs, 2, 0.3);  // slip at t = 2
  for (int k = 3; k < 12; ++k) sc.feed(obs, k, 0.1);   // inside the skip: ignored
  for (int k = 12; k < 22; ++k) sc.feed(obs, k, 0.6);  // window
  EXPECT_DOUBLE_EQ(obs.mu_d(), 0.6);
  EXPECT_EQ(obs.window_samples(), 10);
}

TEST(FirstPeak, AllSlippedRuleIgnoresLargePrecursorDips) {
  Scripted sc;
  sc.make_two_blocks();
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::AllSlipped;  // only all contact blocks slipped ends it
  FrictionObserver obs(cfg);
  double t = 0;
  for (double mu = 0; mu < 0.5; mu += 0.01) sc.feed(obs, t += 1, mu);
  sc.s.mark_slip(0);            // a precursor: one of two blocks slides...
  sc.feed(obs, t += 1, 0.30);   // ...and mu dips by 0.2, far more than any drop threshold
  EXPECT_FALSE(obs.slipped());
  for (double mu = 0.30; mu < 0.70; mu += 0.01) sc.feed(obs, t += 1, mu);
  const double peak = obs.max_mu();
  sc.s.mark_slip(1);            // now the whole surface has moved
  sc.feed(obs, t += 1, 0.45);
  EXPECT_TRUE(obs.slipped());
  EXPECT_DOUBLE_EQ(obs.mu_s(), peak);
  EXPECT_GT(obs.mu_s(), 0.69);
  sc.s.mark_slip(1);            // marking twice does not count twice
  EXPECT_EQ(sc.s.n_slipped_once, 2);
}

TEST(FirstPeak, NoSlipMeansUndefinedCoefficients) {
  Scripted sc;
  FrictionObserver obs(FrictionObserverConfig{});
  for (int k = 0; k < 10; ++k) sc.feed(obs, k, 0.1 * k);
  EXPECT_FALSE(obs.slipped());
  EXPECT_TRUE(std::isnan(obs.mu_s()));
  EXPECT_TRUE(std::isnan(obs.mu_d()));
}

// The end of loading is a property of the trajectory, not of when mu(t) is sampled. A slip that
// completes the set of slid blocks and is over within one sample interval used to go unseen: the
// quiet phase after it served its samples from a copy of the state with a stale count of slid
// blocks, so loading ended at the next active phase that held a sample, with a higher mu_s.
// On this sparse hierarchical surface, seed 11, repetition 0 slips at t = 0.2934 s; sampled every
// 1e-4 s the old code ended loading only at 0.4148 s (mu_s 0.721 instead of 0.639).
TEST(FirstPeak, EndOfLoadingDoesNotDependOnSampleSpacing) {
  Scene scene;
  scene.run.method = Method::Event;
  set_scene_field(scene, "N", "120");
  set_scene_field(scene, "length", "2.4cm");
  set_scene_field(scene, "pattern", "hierarchical:8,2");
  scene.seed = 11;
  scene.run.stop_after_mu_s = true;
  std::vector<RunResult> runs;
  for (double dt : {1e-5, 1e-4}) {
    scene.run.sample_dt_s = dt;
    runs.push_back(run_repetition(scene, 0));
  }
  ASSERT_TRUE(runs[0].slipped && runs[1].slipped);
  // Within one coarse sample interval of each other.
  EXPECT_NEAR(runs[1].t_slip_s, runs[0].t_slip_s, 1e-4 + 1e-12);
  // The sampled maximum can only miss what rises between two samples: mu rises at about
  // 1 / t0 (t0 = 1.5 s here), so by less than 1e-4 over one coarse interval.
  EXPECT_NEAR(runs[1].mu_s, runs[0].mu_s, 1e-4);
}

// The SlidOr* rules end loading at the all-slipped moment or at their own condition, whichever
// comes first.
TEST(FirstPeak, SlidOrDropEndsAtTheDropBeforeEveryBlockSlid) {
  Scripted sc;
  sc.make_two_blocks();
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::SlidOrDrop;
  cfg.peak_drop = 0.1;
  FrictionObserver obs(cfg);
  double t = 0;
  for (double mu = 0; mu < 0.6; mu += 0.01) sc.feed(obs, t += 1, mu);
  const double peak = obs.max_mu();
  sc.s.mark_slip(0);
  sc.feed(obs, t += 1, peak - 0.09);  // a dip smaller than the threshold
  EXPECT_FALSE(obs.slipped());
  sc.feed(obs, t += 1, peak - 0.11);  // falls 0.1 below the peak: loading over, one block slid
  EXPECT_TRUE(obs.slipped());
  EXPECT_DOUBLE_EQ(obs.mu_s(), peak);
  EXPECT_EQ(obs.t_slip(), t);
}

TEST(FirstPeak, SlidOrDropEndsWhenEveryBlockSlidWithoutADrop) {
  Scripted sc;
  sc.make_two_blocks();
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::SlidOrDrop;
  cfg.peak_drop = 0.2;
  FrictionObserver obs(cfg);
  double t = 0;
  for (double mu = 0; mu < 0.6; mu += 0.01) sc.feed(obs, t += 1, mu);
  sc.s.mark_slip(0);
  sc.s.mark_slip(1);
  sc.feed(obs, t += 1, 0.55);  // only 0.04 below the peak, but the whole surface has moved
  EXPECT_TRUE(obs.slipped());
  EXPECT_EQ(obs.t_slip(), t);
}

TEST(FirstPeak, RelativeDropScalesWithThePeak) {
  for (const double peak : {0.3, 0.8}) {
    Scripted sc;
    sc.make_two_blocks();
    FrictionObserverConfig cfg;
    cfg.peak_rule = ExtractionRules::PeakRule::SlidOrRelativeDrop;
    cfg.peak_drop_fraction = 0.2;
    FrictionObserver obs(cfg);
    double t = 0;
    sc.feed(obs, t += 1, peak);
    sc.feed(obs, t += 1, 0.81 * peak);  // 19 % below
    EXPECT_FALSE(obs.slipped()) << peak;
    sc.feed(obs, t += 1, 0.79 * peak);  // 21 % below
    EXPECT_TRUE(obs.slipped()) << peak;
    EXPECT_DOUBLE_EQ(obs.mu_s(), peak);
  }
}

// SlidOrEvent counts the distinct contact blocks of one slip event, from the switches.
TEST(FirstPeak, SlidOrEventEndsAtTheFirstLargeSlipEvent) {
  Scripted sc;
  sc.make_two_blocks();
  sc.c.N = 4;
  sc.c.contact = {1, 1, 1, 1};
  sc.c.f_static.assign(4, 10);
  sc.c.f_kinetic.assign(4, 0.0);  // only block 0's scripted force counts, sliding or not
  sc.c.mu_s.assign(4, 10);
  sc.c.mu_d.assign(4, 0.5);
  sc.c.n_contact = 4;
  sc.s = State::at_rest(sc.c);
  FrictionObserverConfig cfg;
  cfg.peak_rule = ExtractionRules::PeakRule::SlidOrEvent;
  cfg.peak_event_fraction = 0.5;  // two of the four blocks
  FrictionObserver obs(cfg);
  auto slide = [&](int i, int dir) {
    sc.s.dir[i] = static_cast<std::int8_t>(dir);
    if (dir != 0) sc.s.mark_slip(i);
    obs.switched(sc.c, sc.s, SwitchedBlocks::one(i));
  };
  double t = 0;
  for (double mu = 0; mu < 0.6; mu += 0.01) sc.feed(obs, t += 1, mu);
  slide(0, 1);  // a precursor of one block: starts...
  sc.feed(obs, t += 1, 0.2);
  slide(0, 0);  // ...and stops; a large dip, but one block of four
  sc.feed(obs, t += 1, 0.3);
  EXPECT_FALSE(obs.slipped());
  for (double mu = 0.3; mu < 0.7; mu += 0.01) sc.feed(obs, t += 1, mu);
  const double peak = obs.max_mu();
  slide(1, 1);  // one event moves blocks 1 and 2 (and block 1 twice: counted once)
  slide(1, 0);
  slide(1, 1);
  sc.feed(obs, t += 1, peak);
  EXPECT_FALSE(obs.slipped());
  slide(2, 1);
  sc.feed(obs, t += 1, peak - 0.01);
  EXPECT_TRUE(obs.slipped());
  EXPECT_DOUBLE_EQ(obs.mu_s(), peak);
  EXPECT_EQ(obs.t_slip(), t);
}
