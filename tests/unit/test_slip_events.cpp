// Slip-event statistics (observe/slip_events.hpp), read off the integrators' switches alone.
//  * They count what the work profile counts: every block-slip episode (WorkProfile::slip_starts)
//    in some event, and, in the event method, as many events as quiet phases began after sliding
//    (WorkProfile::slip_events), plus one when the run ends at the instant an event ended.
//  * A single block, and two identical ones, slip by the closed-form cycle's amount.
//  * The switched blocks' positions are exact: the event method's fast paths (quiet phases, exact
//    stepper, modal and settled runs) and the K_int = 0 solver give the events of the
//    Dormand-Prince stepper at a tight tolerance.
//  * Observing them changes no other result; they are the same at any thread count and on a
//    shared trajectory; the event method and RK4 agree on their ensemble statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <utility>
#include <string>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/ensemble.hpp"
#include "springblock/integrate/methods/event_driven.hpp"
#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/theory.hpp"

using namespace sb;

namespace {

Scene scene(const std::string& pattern, const std::string& duration, int reps = 3) {
  Scene s;
  set_scene_field(s, "N", "48");
  set_scene_field(s, "length", "0.96cm");
  set_scene_field(s, "pattern", pattern);
  set_scene_field(s, "duration", duration);
  set_scene_field(s, "slip_events", "true");
  set_scene_field(s, "sample_dt", "1e-2ms");  // events come from the switches; samples only cost
  s.reps = reps;
  s.seed = 11;
  s.threads = 1;
  return s;
}

Scene undamped_low_mu_d() {
  Scene s = scene("smooth", "2t0", 2);
  set_scene_field(s, "damping", "0");
  set_scene_field(s, "mu_d", "0.1,0.01");
  return s;
}

long long episodes(const SlipEventRecord& rec) {
  long long n = rec.under_way.episodes;
  for (const SlipEvent& e : rec.events) n += e.episodes;
  return n;
}

// The run ended at the instant its last recorded event ended (no quiet phase followed it).
bool ended_with_an_event(const SlipEventRecord& rec, double t_end) {
  if (rec.unfinished || rec.events.empty()) return false;
  const SlipEvent& e = rec.events.back();
  return std::fabs(e.t_start_s + e.duration_s - t_end) <= 1e-12 * t_end;
}

// What holds for any record: events in time order, none overlapping, sizes that make sense.
void expect_well_formed(const SlipEventRecord& rec, int n_contact, const std::string& where) {
  double t_free = -1;
  for (const SlipEvent& e : rec.events) {
    EXPECT_GE(e.t_start_s, t_free) << where;
    EXPECT_GE(e.duration_s, 0.0) << where;
    EXPECT_GE(e.slip_m, 0.0) << where;
    EXPECT_GE(e.blocks, 1) << where;
    EXPECT_LE(e.blocks, e.episodes) << where;
    EXPECT_LE(e.blocks, n_contact) << where;
    t_free = e.t_start_s + e.duration_s;
  }
}

// (a) The event method: every episode in an event, as many events as the work profile's.
void expect_counts_of_the_work_profile(const Scene& sc, int& unfinished, int& ended_on_event) {
  for (int rep = 0; rep < sc.reps; ++rep) {
    const RunResult r = run_repetition(sc, rep);
    ASSERT_TRUE(r.slip_events.has_value());
    const SlipEventRecord& rec = *r.slip_events;
    const std::string where = sc.pattern.text() + " rep " + std::to_string(rep);
    const int n_contact = static_cast<int>(std::lround(r.contact_fraction * sc.geometry.N));
    expect_well_formed(rec, n_contact, where);
    EXPECT_EQ(episodes(rec), r.work.slip_starts) << where;
    const bool on_event = ended_with_an_event(rec, r.t_end_s);
    EXPECT_EQ(static_cast<long long>(rec.events.size()), r.work.slip_events + (on_event ? 1 : 0)) << where;
    unfinished += rec.unfinished;
    ended_on_event += on_event;
  }
}

TEST(SlipEvents, CountsAgreeWithTheWorkProfile) {
  int unfinished = 0, ended_on_event = 0;
  for (const char* pattern : {"smooth", "periodic:2,2", "periodic:1,5"}) {
    const Scene sc = scene(pattern, "2t0");
    expect_counts_of_the_work_profile(sc, unfinished, ended_on_event);
    EXPECT_GT(run_repetition(sc, 0).slip_events->events.size(), 10u) << pattern;
  }
  // Undamped with a low mu_d: blocks that stop and slide on (often backwards) at the same instant,
  // an episode ended and another begun (hundreds per repetition; a handful at the defaults).
  expect_counts_of_the_work_profile(undamped_low_mu_d(), unfinished, ended_on_event);
  EXPECT_EQ(unfinished, 0);  // events last ~1e-4 s of every 0.1 s: a run rarely ends in one
  EXPECT_EQ(ended_on_event, 0);
  // A run cut in the middle of its longest event (a shorter run is a prefix of the longer): that
  // one is not recorded, and its episodes so far are under_way's; and a run cut at the very end of
  // one (the end time is the event's end, rounded: on it or a hair before or after).
  for (const char* pattern : {"smooth", "periodic:2,2"}) {
    const Scene sc = scene(pattern, "2t0", 1);
    const auto events = run_repetition(sc, 0).slip_events->events;
    ASSERT_FALSE(events.empty()) << pattern;
    const SlipEvent* longest = &events.front();
    for (const SlipEvent& e : events)
      if (e.duration_s > longest->duration_s) longest = &e;
    for (double cut : {0.5, 1.0}) {
      Scene shorter = sc;
      shorter.run.duration_s = longest->t_start_s + cut * longest->duration_s;
      expect_counts_of_the_work_profile(shorter, unfinished, ended_on_event);
    }
  }
  EXPECT_GE(unfinished, 2);
  EXPECT_GE(ended_on_event, 1);
}

TEST(SlipEvents, CountsAgreeWhenTheRunStopsAtItsFirstPeak) {
  Scene sc = scene("smooth", "3t0", 4);
  set_scene_field(sc, "stop_after_mu_s", "true");
  int unfinished = 0, ended_on_event = 0;
  expect_counts_of_the_work_profile(sc, unfinished, ended_on_event);
  // The loading phase ends inside the avalanche that sets the last block sliding.
  EXPECT_EQ(unfinished, sc.reps);
}

// (a) RK4 and the K_int = 0 solver count no slip events in their work profile (they have no
// quiet phases), but every block-slip episode: each must be in an event.
TEST(SlipEvents, EveryEpisodeOfRk4AndOfTheUncoupledSolver) {
  Scene rk4 = scene("smooth", "1.5t0", 2);  // smooth: RK4 jumps over the quiet phases
  set_scene_field(rk4, "method", "rk4");
  Scene rk4_restarts = undamped_low_mu_d();
  set_scene_field(rk4_restarts, "method", "rk4");
  Scene uncoupled = scene("periodic:2,2", "2t0");
  set_scene_field(uncoupled, "k_int_scale", "0");
  for (const Scene& sc : {rk4, rk4_restarts, uncoupled})
    for (int rep = 0; rep < sc.reps; ++rep) {
      const RunResult r = run_repetition(sc, rep);
      const std::string where = method_name(sc.run.method) + " k_int_scale " + std::to_string(sc.k_int_scale);
      ASSERT_TRUE(r.slip_events.has_value());
      expect_well_formed(*r.slip_events, 48, where);
      EXPECT_EQ(episodes(*r.slip_events), r.work.slip_starts) << where;
      EXPECT_GT(r.slip_events->events.size(), 0u) << where;
      EXPECT_EQ(r.work.slip_events, 0) << where;
    }
}

// (b) One block on its slider, undamped: every slip starts at the threshold from rest, so every
// event is the closed-form cycle's: one block, one episode, duration T_d, and slip v (T_d + T_s)
// (the slider's advance over a period, the block's too since it is fixed while stuck).
struct Cycle {
  double t_first, period, T_d, slip;
};

Cycle closed_form(const Chain& c) {
  const theory::SingleBlock b{c.m, c.K_s, c.v_slider, c.F_n};
  const auto cyc = theory::cycle(b, c.mu_s[0], c.mu_d[0]);
  return {c.f_static[0] / (c.K_s * c.v_slider), cyc.T_d_s + cyc.T_s_s, cyc.T_d_s, c.v_slider * (cyc.T_d_s + cyc.T_s_s)};
}

// Runs `c` to the middle of the fifth slip and checks the four events before it, each of
// `blocks` identical blocks sliding together. t_tol bounds the error of one switching time: the
// k-th event starts after 2k switches.
void expect_cycles(Integrator& integ, const Chain& c, int blocks, double t_tol, double slip_rel, const std::string& where) {
  const Cycle cyc = closed_form(c);
  const double t_end = cyc.t_first + 4 * cyc.period + 0.5 * cyc.T_d;
  State s = State::at_rest(c);
  SlipEventObserver obs;
  integ.run(c, s, t_end, 1e-3, obs);
  ASSERT_EQ(obs.events().size(), 4u) << where;
  EXPECT_TRUE(obs.unfinished()) << where;
  for (int k = 0; k < 4; ++k) {
    const SlipEvent& e = obs.events()[k];
    EXPECT_EQ(e.blocks, blocks) << where << " event " << k;
    EXPECT_EQ(e.episodes, blocks) << where << " event " << k;
    EXPECT_NEAR(e.t_start_s, cyc.t_first + k * cyc.period, (2 * k + 1) * t_tol) << where << " event " << k;
    EXPECT_NEAR(e.duration_s, cyc.T_d, 2 * t_tol) << where << " event " << k;
    EXPECT_NEAR(e.slip_m, blocks * cyc.slip, slip_rel * blocks * cyc.slip) << where << " event " << k;
  }
  EXPECT_EQ(obs.under_way().blocks, blocks) << where;
}

TEST(SlipEvents, SingleBlockSlipsByTheClosedFormCycle) {
  for (double K_int : {0.0, 1e3}) {  // the K_int = 0 solver; the coupled event method (no neighbour)
    const Chain c = sbtest::hand_chain({1}, K_int, 0.0, {1.0}, {0.4});
    EventDriven ev(1e-10);
    expect_cycles(ev, c, 1, 1e-9, 1e-9, "event K_int " + std::to_string(K_int));
  }
  const Chain c = sbtest::hand_chain({1}, 1e3, 0.0, {1.0}, {0.4});
  const double h = 1e-8;
  Rk4 rk4(h);  // switches resolved to one step
  expect_cycles(rk4, c, 1, h, 1e-6, "rk4");
}

// Two identical blocks without internal springs switch at the same instants, each in its own call
// (the per-block solver): one event of two blocks. (Coupled, a round-off difference in their
// first threshold crossings grows about a thousandfold each cycle: no longer one event by the
// fourth.)
TEST(SlipEvents, TwoIdenticalBlocksMakeOneEventOfTwo) {
  const Chain c = sbtest::hand_chain({1, 1}, 0.0, 0.0, {1.0, 1.0}, {0.4, 0.4});
  EventDriven ev(1e-10);
  expect_cycles(ev, c, 2, 1e-9, 1e-9, "uncoupled pair");
}

// The switched blocks' positions are exact: the fast paths give the stepper's events.
void expect_same_events(const std::vector<SlipEvent>& a, const std::vector<SlipEvent>& b, double t_tol,
                        double slip_scale, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].blocks, b[k].blocks) << where << " event " << k;
    EXPECT_EQ(a[k].episodes, b[k].episodes) << where << " event " << k;
    EXPECT_NEAR(a[k].t_start_s, b[k].t_start_s, t_tol) << where << " event " << k;
    EXPECT_NEAR(a[k].duration_s, b[k].duration_s, t_tol) << where << " event " << k;
    EXPECT_NEAR(a[k].slip_m, b[k].slip_m, 1e-6 * slip_scale) << where << " event " << k;
  }
}

// Both runs to time T: the fast paths and the stepper at tol 1e-12.
void expect_fast_as_stepped(const Chain& c, double T, double t_tol, const std::string& where) {
  const double dt = 1.2345678e-3;  // samples off the round thresholds
  State a = State::at_rest(c), b = State::at_rest(c);
  SlipEventObserver oa, ob;
  EventDriven fast(1e-9, true), stepped(1e-12, false);
  fast.run(c, a, T, dt, oa);
  stepped.run(c, b, T, dt, ob);
  EXPECT_GT(oa.events().size(), 2u) << where;
  expect_same_events(oa.events(), ob.events(), t_tol, c.F_n / c.K_s, where);
}

TEST(SlipEvents, FastPathsGiveTheSteppersEvents) {
  // Coupled, with grooves (modal and settled runs, quiet phases) and without (the exact stepper);
  // and K_int = 0 (the per-block solver).
  const std::vector<Chain> chains = {
      sbtest::hand_chain({1, 0, 0, 1, 1, 0, 1, 1}, 2e3, 1e4, {1.0, 0, 0, 0.93, 1.12, 0, 0.87, 1.05},
                         {0.5, 0, 0, 0.47, 0.55, 0, 0.52, 0.4}),
      sbtest::hand_chain({1, 1, 1, 1, 1, 1}, 5e3, 0.0, {1.0, 0.93, 1.12, 0.87, 1.05, 0.95}, {0.5, 0.47, 0.55, 0.52, 0.4, 0.3}),
      sbtest::hand_chain({1, 1, 0, 1, 1}, 0.0, 1e4, {1.0, 0.93, 0, 1.12, 0.87}, {0.5, 0.47, 0, 0.55, 0.3})};
  for (std::size_t k = 0; k < chains.size(); ++k)  // a couple of cycles
    expect_fast_as_stepped(chains[k], 0.9, 1e-9, "chain " + std::to_string(k));
  // Drawn chains of pawls and grooves of one to three blocks, to 0.6 loading times: short runs
  // made modal beside switching blocks. Further on, the stepper's errors (1e-12 a step) grow
  // until events start 1e-7 s apart (periodic:3,3 at one t0), and later split or merge differently.
  for (const char* pattern : {"periodic:2,2", "periodic:1,2", "periodic:3,3"}) {
    Scene s;
    set_scene_field(s, "N", "24");
    set_scene_field(s, "length", "0.48cm");
    set_scene_field(s, "pattern", pattern);
    s.seed = 5;
    validate(s);
    expect_fast_as_stepped(build_chain(s, 0), 0.6 * s.t0_s(), 1e-8, pattern);
  }
}

bool same(const SlipEventRecord& a, const SlipEventRecord& b) {
  if (a.events.size() != b.events.size() || a.unfinished != b.unfinished) return false;
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    const SlipEvent &x = a.events[k], &y = b.events[k];
    if (x.t_start_s != y.t_start_s || x.duration_s != y.duration_s || x.blocks != y.blocks ||
        x.episodes != y.episodes || x.slip_m != y.slip_m)
      return false;
  }
  return true;
}

// (c) A seed fixes them whatever the thread count.
TEST(SlipEvents, SameWhateverTheThreadCount) {
  Scene sc = scene("periodic:2,2", "2t0", 4);
  const auto one = run_ensemble(sc);
  sc.threads = 2;
  const auto two = run_ensemble(sc);
  for (std::size_t r = 0; r < one.runs.size(); ++r)
    EXPECT_TRUE(same(*one.runs[r].slip_events, *two.runs[r].slip_events)) << "rep " << r;
  sc.seed = 12;  // and they depend on the draws
  EXPECT_FALSE(same(*one.runs[0].slip_events, *run_ensemble(sc).runs[0].slip_events));
}

// Observing them is a tap on the switches: every other number to the last bit.
TEST(SlipEvents, ObservingThemChangesNoOtherResult) {
  for (const char* pattern : {"periodic:2,2", "smooth"}) {
    Scene with = scene(pattern, "2t0", 2), without = with;
    without.observe.slip_events = false;
    const auto a = run_ensemble(with), b = run_ensemble(without);
    for (std::size_t r = 0; r < a.runs.size(); ++r) {
      EXPECT_FALSE(b.runs[r].slip_events.has_value());
      EXPECT_EQ(a.runs[r].mu_s, b.runs[r].mu_s);
      EXPECT_EQ(a.runs[r].mu_d, b.runs[r].mu_d);
      EXPECT_EQ(a.runs[r].steps, b.runs[r].steps);
      EXPECT_EQ(a.runs[r].rhs_evals, b.runs[r].rhs_evals);
#define SB_SAME(name, doc) EXPECT_EQ(a.runs[r].work.name, b.runs[r].work.name) << #name;
      SB_WORK_COUNTS(SB_SAME)
#undef SB_SAME
    }
  }
}

// Per repetition: events, their mean size in blocks and mean slip [um], chain-spanning events.
struct PerRun {
  std::vector<double> events, blocks, slip_um, spanning;
};

PerRun per_run(const EnsembleResult& e, int n_contact) {
  PerRun p;
  for (const RunResult& r : e.runs) {
    const auto& ev = r.slip_events->events;
    double blocks = 0, slip = 0, spanning = 0;
    for (const SlipEvent& x : ev) blocks += x.blocks, slip += x.slip_m, spanning += x.blocks == n_contact;
    p.events.push_back(static_cast<double>(ev.size()));
    p.blocks.push_back(blocks / ev.size());
    p.slip_um.push_back(1e6 * slip / ev.size());
    p.spanning.push_back(spanning);
  }
  return p;
}

// (c) The event method and RK4 (the paper's method and step, 1e-4 ms) agree on the ensemble's slip
// events within 3 combined standard errors of 20 repetitions each. The draws are the same, but
// the trajectories part after the first avalanches (RK4 resolves a switch to one step), so the
// repetitions are compared as two samples, not as pairs.
TEST(SlipEvents, EventMethodAndRk4AgreeOnTheEnsemble) {
  Scene ev = scene("smooth", "4t0", 20);
  ev.seed = 3;
  Scene rk = ev;
  set_scene_field(rk, "method", "rk4");
  const PerRun a = per_run(run_ensemble(ev), 48), b = per_run(run_ensemble(rk), 48);
  const std::vector<std::pair<const char*, std::vector<double> PerRun::*>> quantities = {
      {"events per run", &PerRun::events}, {"blocks per event", &PerRun::blocks},
      {"slip per event [um]", &PerRun::slip_um}, {"chain-spanning events per run", &PerRun::spanning}};
  for (const auto& [name, q] : quantities) {
    const Statistic x = summarize(a.*q), y = summarize(b.*q);
    const double z = (x.mean - y.mean) / std::hypot(x.sem, y.sem);
    std::printf("%s: event %.4g +- %.2g, rk4 %.4g +- %.2g, z = %.2f\n", name, x.mean, x.sem, y.mean, y.sem, z);
    EXPECT_LE(std::fabs(z), 3.0) << name;
    EXPECT_GT(x.mean, 0.0) << name;
  }
}

// A scene observed on a longer scene's trajectory (FanOut) gets the events of its own run.
TEST(SlipEvents, SharedTrajectoryGivesEachSceneItsOwn) {
  for (const char* method : {"event", "rk4"}) {
    Scene longer = scene(method == std::string("rk4") ? "smooth" : "periodic:2,2", "3t0", 2);
    set_scene_field(longer, "method", method);
    Scene shorter = longer;
    set_scene_field(shorter, "duration", "2t0");
    const auto pooled = run_ensembles({longer, shorter});
    ASSERT_EQ(pooled[1].trajectory_from, 0);
    const auto own = run_ensemble(shorter);
    for (std::size_t r = 0; r < own.runs.size(); ++r) {
      EXPECT_TRUE(same(*own.runs[r].slip_events, *pooled[1].runs[r].slip_events)) << method << " rep " << r;
      EXPECT_LT(pooled[1].runs[r].slip_events->events.size(), pooled[0].runs[r].slip_events->events.size());
    }
  }
}

// What MPI ranks send back: the events survive the results JSON.
TEST(SlipEvents, SurviveTheResultsJson) {
  const RunResult r = run_repetition(scene("smooth", "1.3t0", 1), 0);
  nlohmann::json j = r;
  RunResult back = j.get<RunResult>();
  ASSERT_TRUE(back.slip_events.has_value());
  EXPECT_TRUE(same(*r.slip_events, *back.slip_events));
  EXPECT_EQ(r.slip_events->under_way.episodes, back.slip_events->under_way.episodes);
}

}  // namespace
