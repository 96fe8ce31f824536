// The work profile (work_profile.hpp) must be true to the run it describes and must not touch it:
// timing the kinds of work changes no result to the last bit; the counters agree with the run's
// own counts (every sample accounted for, a slip start for every slide, steps that add up); the
// times are all there when asked for and add up to no more than the repetition's wall time, and
// are absent from the JSON when not asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {

Scene base(const std::string& pattern) {
  Scene s;
  set_scene_field(s, "N", "48");
  set_scene_field(s, "length", "0.96cm");
  set_scene_field(s, "pattern", pattern);
  set_scene_field(s, "duration", "2t0");
  s.reps = 2;
  s.seed = 11;
  s.threads = 1;
  return s;
}

void expect_timing_changes_nothing(const Scene& plain) {
  Scene timed = plain;
  timed.observe.timed_work = true;
  const auto a = run_ensemble(plain), b = run_ensemble(timed);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t r = 0; r < a.runs.size(); ++r) {
    EXPECT_EQ(a.runs[r].mu_s, b.runs[r].mu_s) << r;
    EXPECT_EQ(a.runs[r].mu_d, b.runs[r].mu_d) << r;
    EXPECT_EQ(a.runs[r].steps, b.runs[r].steps) << r;
    EXPECT_EQ(a.runs[r].switches, b.runs[r].switches) << r;
#define SB_SAME(name, doc) EXPECT_EQ(a.runs[r].work.name, b.runs[r].work.name) << #name;
    SB_WORK_COUNTS(SB_SAME)
#undef SB_SAME
  }
}

// The scene's repetitions with the work profile's times on.
std::vector<RunResult> timed_runs(const Scene& sc) {
  Scene timed = sc;
  timed.observe.timed_work = true;
  return run_ensemble(timed).runs;
}

// The sample times in (0, t_end] of a run.
std::int64_t sample_times(const RunResult& r, const Scene& sc) {
  return static_cast<std::int64_t>(std::floor(r.t_end_s / sc.run.sample_dt_s + 1e-9));
}

// Every time there, none negative, and together no more than the repetition's wall time.
void expect_times_add_up(const RunResult& r) {
  const WorkProfile& w = r.work;
  ASSERT_TRUE(w.timed);
  double sum = 0;
#define SB_SUM(name, doc) EXPECT_GE(w.name, 0.0) << #name, sum += w.name;
  SB_WORK_TIMES(SB_SUM)
#undef SB_SUM
  EXPECT_LE(sum, r.wall_s);
}

// Counts that must hold on any event run.
void expect_consistent_counts(const Scene& sc) {
  for (const auto& r : timed_runs(sc)) {
    const WorkProfile& w = r.work;
    // Every sample time in (0, t_end] is served once, one by one, in an affine stretch or in a
    // block summed over the modes (the sample at t = 0 is the run's start, not counted).
    EXPECT_EQ(w.samples + w.stretch_samples + w.summed_samples + w.peak_samples, sample_times(r, sc));
    // A switch is a start or a stop, and a block stops only after it started.
    EXPECT_GT(w.slip_starts, 0);
    EXPECT_GE(r.switches, w.slip_starts);
    EXPECT_LE(r.switches, 2 * w.slip_starts);
    EXPECT_GT(w.slip_events, 0);
    EXPECT_LE(w.slip_events, w.slip_starts);
    // Accepted steps of any kind: the trial steps kept (neither rejected nor followed by a redo
    // to an event), the redone event steps and the exact jumps.
    EXPECT_LE(r.steps, w.stepped_attempts - w.rejected_steps + w.exact_jumps);
    EXPECT_GE(r.steps, w.event_steps + w.exact_jumps);
    EXPECT_LE(w.rejected_steps + w.event_steps, w.stepped_attempts);
    EXPECT_GE(w.block_steps, w.stepped_attempts);  // a trial integrates at least one block
    expect_times_add_up(r);
    EXPECT_GT(w.stepping_s, 0.0);
  }
}

// The fixed-step RK4 (the paper's method) times its kinds too: its steps, the switching rules
// after each, its jumps over a fully stuck chain and its samples, every one served singly. A
// coarse step (1e-6 s, 0.5 rad of the fastest mode, well inside RK4's stability) keeps it short.
Scene rk4(const std::string& pattern) {
  Scene s = base(pattern);
  set_scene_field(s, "method", "rk4");
  set_scene_field(s, "dt", "1e-6s");
  s.reps = 1;
  return s;
}

void expect_rk4_times(const Scene& sc) {
  for (const auto& r : timed_runs(sc)) {
    const WorkProfile& w = r.work;
    EXPECT_EQ(w.samples, sample_times(r, sc) + 1);  // and the one at t = 0, which RK4 serves too
    EXPECT_EQ(w.stretch_samples + w.summed_samples + w.peak_samples, 0);
    EXPECT_GT(w.slip_starts, 0);
    expect_times_add_up(r);
    EXPECT_GT(w.stepping_s, 0.0);
    EXPECT_GT(w.switching_s, 0.0);
    EXPECT_GT(w.sampling_s, 0.0);
    EXPECT_EQ(w.event_location_s, 0.0);  // RK4 locates nothing: it switches at step ends
  }
}

// Blocks without internal springs (K_int = 0) are solved one by one in closed form
// (uncoupled.hpp): the rules at each block's event are switching, finding its next event is
// event location, and the samples are served one by one or as affine stretches between events.
Scene uncoupled(const std::string& pattern) {
  Scene s = base(pattern);
  set_scene_field(s, "k_int_scale", "0");
  return s;
}

void expect_uncoupled_times(const Scene& sc) {
  for (const auto& r : timed_runs(sc)) {
    const WorkProfile& w = r.work;
    EXPECT_EQ(w.samples + w.stretch_samples, sample_times(r, sc) + 1);  // and the one at t = 0
    EXPECT_GT(w.stretch_samples, 0);
    EXPECT_GT(w.slip_starts, 0);
    EXPECT_GE(w.switch_instants, w.slip_starts);
    expect_times_add_up(r);
    EXPECT_GT(w.event_location_s, 0.0);
    EXPECT_GT(w.switching_s, 0.0);
    EXPECT_GT(w.sampling_s, 0.0);
  }
}

}  // namespace

TEST(WorkProfile, UncoupledTimingChangesNothing) { expect_timing_changes_nothing(uncoupled("periodic:3,3")); }
TEST(WorkProfile, UncoupledTimesItsEvents) { expect_uncoupled_times(uncoupled("periodic:3,3")); }
TEST(WorkProfile, Rk4TimingChangesNothing) { expect_timing_changes_nothing(rk4("periodic:3,3")); }
TEST(WorkProfile, Rk4TimesItsSteps) { expect_rk4_times(rk4("periodic:3,3")); }
TEST(WorkProfile, Rk4TimesItsQuietJumps) {
  // Without grooves a fully stuck chain is jumped over: those jumps are quiet time.
  for (const auto& r : timed_runs(rk4("smooth"))) EXPECT_GT(r.work.quiet_s, 0.0);
}

TEST(WorkProfile, TimingChangesNothingWithGrooves) { expect_timing_changes_nothing(base("periodic:3,3")); }
TEST(WorkProfile, TimingChangesNothingSmooth) { expect_timing_changes_nothing(base("smooth")); }
TEST(WorkProfile, CountsAddUpWithGrooves) { expect_consistent_counts(base("periodic:3,3")); }
TEST(WorkProfile, CountsAddUpSmooth) { expect_consistent_counts(base("smooth")); }

TEST(WorkProfile, JsonHasTimesOnlyWhenTimed) {
  Scene plain = base("periodic:3,3");
  plain.reps = 1;
  Scene timed = plain;
  timed.observe.timed_work = true;
  const nlohmann::json a = run_ensemble(plain).runs[0], b = run_ensemble(timed).runs[0];
  EXPECT_TRUE(a.at("work").contains("slip_starts"));
  EXPECT_FALSE(a.at("work").contains("stepping_s"));
  EXPECT_TRUE(b.at("work").contains("stepping_s"));
  EXPECT_GT(b.at("work").at("slip_starts").get<long long>(), 0);
}
