// Scenes that differ only in extraction rules or run length share one simulation in
// run_ensembles (observe/fan_out.hpp). Each must get exactly what a run of its own gives: the
// same mu_s, mu_d, peak and window, to the last bit, for every integrator path (the stepped
// event method with grooves and quiet phases, the per-block K_int = 0 solver, RK4).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {

Scene shared_scene(const std::string& pattern, const std::string& method) {
  Scene s;
  set_scene_field(s, "N", "48");
  set_scene_field(s, "length", "0.96cm");
  set_scene_field(s, "pattern", pattern);
  set_scene_field(s, "method", method);
  set_scene_field(s, "duration", "3t0");
  s.reps = 3;
  s.seed = 11;
  s.threads = 1;
  return s;
}

// Variants of `b` around the same trajectory: run length, the mu_s rule, the mu_d window, and a
// run ending exactly on a sample time (`on_sample`, e.g. 2 s = 200000 x 1e-5 s), the case where
// a run of its own serves its last sample outside any affine stretch.
std::vector<Scene> variants(const Scene& b, const std::string& on_sample) {
  std::vector<Scene> v(7, b);
  set_scene_field(v[6], "duration", on_sample);
  set_scene_field(v[1], "duration", "2t0");
  set_scene_field(v[2], "peak_rule", "drop");
  set_scene_field(v[3], "peak_rule", "drop");
  set_scene_field(v[3], "peak_drop", "0.02");
  set_scene_field(v[4], "mu_d_skip", "0");
  set_scene_field(v[5], "duration", "2.5t0");
  set_scene_field(v[5], "mu_d_skip", "0.5");
  return v;
}

void expect_same_as_own_runs(const std::vector<Scene>& scenes) {
  const auto pooled = run_ensembles(scenes);
  int shared = 0, windows = 0;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const auto own = run_ensemble(scenes[k]);
    shared += pooled[k].trajectory_from >= 0;
    ASSERT_EQ(own.runs.size(), pooled[k].runs.size());
    for (std::size_t r = 0; r < own.runs.size(); ++r) {
      const auto &a = own.runs[r], &b = pooled[k].runs[r];
      const std::string where = "scene " + std::to_string(k) + " rep " + std::to_string(r);
      EXPECT_EQ(a.slipped, b.slipped) << where;
      EXPECT_EQ(a.mu_s, b.mu_s) << where;
      EXPECT_EQ(a.t_peak_s, b.t_peak_s) << where;
      EXPECT_EQ(a.t_slip_s, b.t_slip_s) << where;
      EXPECT_EQ(a.max_mu, b.max_mu) << where;
      EXPECT_EQ(a.window_samples, b.window_samples) << where;
      EXPECT_EQ(a.mu_d, b.mu_d) << where;
      EXPECT_EQ(a.mu_d_signed, b.mu_d_signed) << where;
      EXPECT_LE(b.switches, a.switches) << where;  // counted up to the view's last sample
      if (pooled[k].trajectory_from >= 0) {
        EXPECT_EQ(b.wall_s, 0.0) << where;
      }
      windows += b.window_samples > 0;
    }
  }
  // Not vacuous: the runs reach their dynamic phase.
  EXPECT_GT(windows, 0);
  // Every variant but the longest is observed on the longest one's run.
  EXPECT_EQ(shared, static_cast<int>(scenes.size()) - 1);
}

}  // namespace

TEST(SharedTrajectory, EventMethodWithGroovesMatchesOwnRuns) {
  expect_same_as_own_runs(variants(shared_scene("periodic:3,3", "event"), "2s"));  // 3 t0 = 2.4 s
}

// Grooves of ten blocks: the loading phase's quiet phases are long, so several views take the
// same stretch of samples from its bounds (QuietPhase::envelope), each looking only at the
// samples that may hold its peak; they look in their own order and must each get the doubles of
// their own runs.
TEST(SharedTrajectory, EventMethodWithLongGroovesMatchesOwnRuns) {
  Scene b = shared_scene("periodic:10,10", "event");
  set_scene_field(b, "N", "120");
  set_scene_field(b, "length", "2.4cm");
  set_scene_field(b, "duration", "2t0");
  std::vector<Scene> v = variants(b, "1s");  // 2 t0 = 1.6 s
  set_scene_field(v[1], "duration", "1.5t0");
  set_scene_field(v[5], "duration", "1.8t0");
  expect_same_as_own_runs(v);
}

TEST(SharedTrajectory, EventMethodSmoothMatchesOwnRuns) {
  expect_same_as_own_runs(variants(shared_scene("smooth", "event"), "1s"));  // 3 t0 = 1.2 s
}

TEST(SharedTrajectory, UncoupledSolverMatchesOwnRuns) {
  Scene b = shared_scene("periodic:2,1", "event");
  set_scene_field(b, "k_int_scale", "0");
  expect_same_as_own_runs(variants(b, "1s"));  // 3 t0 = 1.8 s
}

TEST(SharedTrajectory, Rk4MatchesOwnRuns) {
  Scene b = shared_scene("periodic:2,2", "rk4");
  set_scene_field(b, "N", "12");
  set_scene_field(b, "length", "0.24cm");
  set_scene_field(b, "dt", "4e-7s");
  set_scene_field(b, "duration", "1.6t0");
  b.reps = 1;
  std::vector<Scene> v = variants(b, "1s");  // 1.6 t0 = 1.28 s
  v.erase(v.begin() + 3, v.begin() + 6);  // RK4 steps every h: four variants keep the test short
  set_scene_field(v[1], "duration", "1.3t0");
  expect_same_as_own_runs(v);
}

TEST(SharedTrajectory, DifferentPhysicsOrStopRuleIsNotShared) {
  Scene a = shared_scene("smooth", "event");
  Scene b = a, c = a;
  set_scene_field(b, "tol", "1e-10");
  set_scene_field(c, "stop_after_mu_s", "true");
  const auto pooled = run_ensembles({a, b, c, c});
  for (const auto& e : pooled) EXPECT_EQ(e.trajectory_from, -1);
}

// Which samples a shorter view receives follows the integrator's own end rule. RK4 runs
// llround(t_end / h) steps, so a run whose t_end lies a rounding error below a step time still
// takes that step and samples there; the event method samples at k dt <= t_end.
TEST(SharedTrajectory, SampleWindowFollowsEachIntegratorsEndRule) {
  const double h = 4e-7, t_step = 2600000 * h;  // a step (and sample) time, 1.04 s
  const double t_end = std::nextafter(t_step, 0.0);
  RunControl rk4;
  rk4.method = Method::RK4;
  rk4.dt_s = h;
  EXPECT_TRUE(make_integrator(rk4)->samples_within(t_step, t_end));
  EXPECT_FALSE(make_integrator(rk4)->samples_within(t_step + 25 * h, t_end));
  RunControl event;
  event.method = Method::Event;
  EXPECT_FALSE(make_integrator(event)->samples_within(t_step, t_end));
  EXPECT_TRUE(make_integrator(event)->samples_within(t_end, t_end));
}
