// What a scene observes must not change what it measures: keeping mu(t) (the series) or taking
// stress snapshots leaves every repetition's mu_s, mu_d and peak unchanged to the last bit, on
// every integrator path (the event method with grooves, where quiet phases hand the observer
// affine stretches; a smooth chain; the per-block K_int = 0 solver; RK4). They once differed in
// the last bits, because the series and the snapshots switched the observer from affine
// stretches to per-sample sums. The series itself must agree with the statistics it accompanies:
// its peak before the end of loading is mu_s.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "springblock/ensemble.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene_fields.hpp"
#include "forwarding_observer.hpp"

using namespace sb;

namespace {

Scene base(const std::string& pattern, const std::string& method, const std::string& k_int_scale = "1") {
  Scene s;
  set_scene_field(s, "N", "48");
  set_scene_field(s, "length", "0.96cm");
  set_scene_field(s, "pattern", pattern);
  set_scene_field(s, "method", method);
  set_scene_field(s, "k_int_scale", k_int_scale);
  set_scene_field(s, "duration", "2t0");
  s.reps = 2;
  s.seed = 5;
  s.threads = 1;
  return s;
}

void expect_observation_changes_nothing(Scene plain) {
  Scene observed = plain;
  observed.observe.series = true;
  Scene stressed = plain;
  stressed.observe.stress_times_s = {0.4 * plain.duration(), 0.9 * plain.duration()};
  const auto a = run_ensemble(plain), b = run_ensemble(observed), c = run_ensemble(stressed);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  ASSERT_EQ(a.runs.size(), c.runs.size());
  int windows = 0;
  for (std::size_t r = 0; r < a.runs.size(); ++r) {
    for (const auto* other : {&b.runs[r], &c.runs[r]}) {
      const std::string where = "rep " + std::to_string(r) + (other == &b.runs[r] ? " (series)" : " (stress)");
      EXPECT_EQ(a.runs[r].mu_s, other->mu_s) << where;
      EXPECT_EQ(a.runs[r].mu_s_signed, other->mu_s_signed) << where;
      EXPECT_EQ(a.runs[r].t_peak_s, other->t_peak_s) << where;
      EXPECT_EQ(a.runs[r].window_samples, other->window_samples) << where;
      EXPECT_EQ(a.runs[r].mu_d, other->mu_d) << where;
      EXPECT_EQ(a.runs[r].mu_d_signed, other->mu_d_signed) << where;
    }
    windows += a.runs[r].window_samples > 0;
  }
  EXPECT_GT(windows, 0);  // not vacuous: the runs reach their dynamic phase
  // Repetition 0's series: its maximum up to the peak time is mu_s itself.
  const auto& run0 = b.runs[0];
  ASSERT_FALSE(run0.series.empty());
  double peak = 0;
  for (const auto& smp : run0.series)
    if (smp.t <= run0.t_peak_s) peak = std::max(peak, smp.mu);
  EXPECT_EQ(peak, run0.mu_s);
  EXPECT_EQ(c.runs[0].stress.size(), 2u);
}

// The series built from affine stretches against the one built sample by sample: the same
// times and sliding counts, mu to round-off.
void expect_stretch_series_is_the_per_sample_one(const Scene& sc) {
  const Chain c = build_chain(sc, 0);
  FrictionObserver stretched(sbtest::series_config(c)), single(sbtest::series_config(c));
  sbtest::PerSample per_sample(single);
  sbtest::run_from_rest(sc, c, stretched);
  sbtest::run_from_rest(sc, c, per_sample);
  const auto &a = stretched.series(), &b = single.series();
  ASSERT_EQ(a.size(), b.size());
  int sliding = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].t, b[k].t) << k;
    ASSERT_EQ(a[k].n_sliding, b[k].n_sliding) << "sample " << k << " t " << a[k].t;
    ASSERT_NEAR(a[k].mu, b[k].mu, 1e-12) << k;
    sliding += a[k].n_sliding > 0;
  }
  EXPECT_GT(sliding, 0);  // not vacuous: blocks slide at some samples
}

}  // namespace

TEST(FrictionObserver, SeriesFromStretchesEqualsSampleBySampleUncoupled) {
  expect_stretch_series_is_the_per_sample_one(base("smooth", "event", "0"));
}

TEST(FrictionObserver, SeriesFromStretchesEqualsSampleBySampleEventWithGrooves) {
  expect_stretch_series_is_the_per_sample_one(base("periodic:2,2", "event"));
}

TEST(FrictionObserver, KeepingTheSeriesChangesNoStatisticEventWithGrooves) {
  expect_observation_changes_nothing(base("periodic:2,2", "event"));
}

TEST(FrictionObserver, KeepingTheSeriesChangesNoStatisticEventSmooth) {
  expect_observation_changes_nothing(base("smooth", "event"));
}

TEST(FrictionObserver, KeepingTheSeriesChangesNoStatisticUncoupled) {
  expect_observation_changes_nothing(base("periodic:3,1", "event", "0"));
}

TEST(FrictionObserver, KeepingTheSeriesChangesNoStatisticRk4) {
  expect_observation_changes_nothing(base("smooth", "rk4"));
}

// The same for each reading of the first peak that ends loading earlier than all_slipped: a drop
// rule makes the observer test every sample, the event rule keeps the quiet phases' stretches.
TEST(FrictionObserver, KeepingTheSeriesChangesNoStatisticUnderEveryReading) {
  const std::pair<const char*, const char*> rules[] = {
      {"slid_or_drop", "peak_drop"}, {"slid_or_relative_drop", "peak_drop_fraction"}, {"slid_or_event", "peak_event_fraction"}};
  for (const auto& [rule, field] : rules) {
    SCOPED_TRACE(rule);
    Scene s = base("periodic:2,2", "event");
    set_scene_field(s, "peak_rule", rule);
    set_scene_field(s, field, "0.1");
    expect_observation_changes_nothing(s);
  }
}
