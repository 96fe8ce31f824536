// The event method's exact stepper (linear/span_modes.hpp, events/span_screen.hpp) against the
// Dormand-Prince stepper at a tight tolerance, its fallback to Dormand-Prince for long runs, its
// handling of creeping blocks, and the Bernstein root search its screen refines events with.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "springblock/integrate/numerics/bernstein.hpp"
#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/integrate/methods/event_driven.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene.hpp"

namespace {

sb::Scene small_scene(int N, const char* pattern, double duration_t0, bool stop_after_mu_s) {
  sb::Scene sc;
  sc.geometry.N = N;
  sc.geometry.L_x_m = 0.04 * N / 200.0;  // the paper's block size
  sc.pattern = sb::parse_pattern(pattern);
  sc.run.stop_after_mu_s = stop_after_mu_s;
  sc.run.duration_t0 = duration_t0;
  sc.reps = 1;
  sc.seed = 3;
  return sc;
}

struct StepperRun {
  std::vector<double> log;  // the instants with a switch
  double mu_s = 0;
  std::int64_t rhs = 0, switches = 0;
};

StepperRun run(const sb::Scene& sc, sb::EventDriven& e) {
  const sb::Chain c = sb::build_chain(sc, 0);
  sb::State s = sb::State::at_rest(c);
  sb::FrictionObserverConfig cfg;
  cfg.F_load = c.F_load;
  cfg.peak_rule = sb::ExtractionRules::PeakRule::AllSlipped;  // up to the whole surface's slip: many switches
  cfg.stop_after_mu_s = sc.run.stop_after_mu_s;
  sb::FrictionObserver obs(cfg);
  StepperRun r;
  e.set_switch_log(&r.log);
  e.run(c, s, sc.duration(), sc.run.sample_dt_s, obs);
  r.mu_s = obs.mu_s();
  r.rhs = s.rhs_evals;
  r.switches = s.switches;
  return r;
}

// Dormand-Prince at tol 1e-12, every run stepped: the reference the exact stepper must meet.
sb::EventDriven reference() {
  sb::EventDriven e(1e-12, true);
  e.set_exact_stepper(false);
  e.set_modal_max_run(0);
  return e;
}

TEST(ExactStepper, AgreesWithTightSteppingToTheFirstPeak) {
  // Up to the first macroscopic peak every switching instant is a smooth function of the
  // initial state, so two correct integrators give the same instants to their accuracy. The
  // bound is the one the modal runs meet against Dormand-Prince at tol 1e-11
  // (EventIntegrator.ModalRunsAgreeWithStepping); the reference here is tighter still. A
  // screen that missed or delayed one stop or crossing shifts every later instant far more.
  struct Case {
    const char* pattern;
    bool damped;
  };
  for (const Case k : {Case{"periodic:4,4", true}, Case{"smooth", true}, Case{"periodic:1,1", false},
                       Case{"hierarchical:12,3,1", true}}) {
    sb::Scene sc = small_scene(48, k.pattern, 2.0, true);
    if (!k.damped) sc.material.gamma_per_s = 0;
    sb::EventDriven exact(1e-8, true), ref = reference();
    const StepperRun a = run(sc, exact), b = run(sc, ref);
    std::printf("%s N=48 %s: exact mu_s %.12f (%zu instants, rhs %lld) | dopri5 1e-12 mu_s %.12f (rhs %lld)\n",
                k.pattern, k.damped ? "damped" : "undamped", a.mu_s, a.log.size(), (long long)a.rhs, b.mu_s,
                (long long)b.rhs);
    ASSERT_EQ(a.log.size(), b.log.size()) << k.pattern;
    ASSERT_GE(a.log.size(), 8u) << k.pattern;
    for (std::size_t i = 0; i < a.log.size(); ++i)
      EXPECT_NEAR(a.log[i], b.log[i], 1e-8 * b.log[i]) << k.pattern << " instant " << i;
    EXPECT_NEAR(a.mu_s, b.mu_s, 1e-6) << k.pattern;
    EXPECT_EQ(a.rhs, 0) << k.pattern;  // no run longer than exact_max_run: no right-hand side evaluated
  }
}

TEST(ExactStepper, RunsOnTheirOwnClocksMeetTheReference) {
  // A longer chain slips in several places at once: each group of runs steps on its own clock,
  // keeps what its screen found ahead across switches elsewhere, and is screened afresh when a
  // switch renews a block its screen reads (ExactEvolve::Group). A group kept when it should have
  // been renewed misses or delays a crossing, and every later instant moves.
  for (const char* pattern : {"smooth", "periodic:4,4", "hierarchical:12,3,1"}) {
    const sb::Scene sc = small_scene(400, pattern, 2.0, true);
    sb::EventDriven exact(1e-8, true), ref = reference();
    const StepperRun a = run(sc, exact), b = run(sc, ref);
    std::printf("%s N=400: exact mu_s %.12f (%zu instants) | dopri5 1e-12 mu_s %.12f\n", pattern, a.mu_s,
                a.log.size(), b.mu_s);
    ASSERT_EQ(a.log.size(), b.log.size()) << pattern;
    ASSERT_GE(a.log.size(), 100u) << pattern;
    for (std::size_t i = 0; i < a.log.size(); ++i)
      EXPECT_NEAR(a.log[i], b.log[i], 1e-8 * b.log[i]) << pattern << " instant " << i;
    EXPECT_NEAR(a.mu_s, b.mu_s, 1e-6) << pattern;
  }
}

TEST(ExactStepper, AGroupKeepsItsClockOnlyWhileWhatItsScreenReadsStands) {
  // A group keeps its screen across a switch elsewhere unless the classification renewed a block
  // it reads; the audit compares every kept screen with the one the classification would build
  // and throws at a mismatch. Modal runs of up to 8 blocks beside the stepped ones make the
  // renewal happen in this scene (one group in its first 2 repetitions); a stepper that kept that
  // group reads a neighbour's old record, and results move (mu_d 0.54623 -> 0.54602 in the
  // first repetition).
  sb::Scene sc;  // the paper's chain (L_x = 4 cm) with 400 blocks, seed 1, the default run length
  sc.geometry.N = 400;
  sc.pattern = sb::parse_pattern("hierarchical:12,3,1");
  sc.seed = 1;
  sb::ClockAudit audit;
  for (int rep = 0; rep < 2; ++rep) {
    const sb::Chain c = sb::build_chain(sc, rep);
    sb::State s = sb::State::at_rest(c);
    sb::FrictionObserverConfig cfg;
    cfg.F_load = c.F_load;
    sb::FrictionObserver obs(cfg);
    sb::EventDriven e(1e-8, true);
    e.set_modal_max_run(8);
    e.set_clock_audit(&audit);
    EXPECT_NO_THROW(e.run(c, s, sc.duration(), sc.run.sample_dt_s, obs));
  }
  std::printf("groups kept %ld, renewed by their surroundings %ld\n", audit.kept, audit.renewed);
  EXPECT_GT(audit.kept, 1000);
  EXPECT_GE(audit.renewed, 1);
}

TEST(ExactStepper, LongRunsFallBackToDormandPrince) {
  // With exact_max_run = 3 every run of four or more blocks is stepped by Dormand-Prince and the
  // shorter ones move by their modes, switching between the two as runs grow and split; the
  // instants still meet the reference.
  const sb::Scene sc = small_scene(48, "smooth", 2.0, true);
  sb::EventDriven mixed(1e-10, true), ref = reference();
  mixed.set_exact_stepper(true, 3);
  const StepperRun a = run(sc, mixed), b = run(sc, ref);
  std::printf("smooth N=48, exact_max_run 3: mu_s %.12f rhs %lld | reference %.12f\n", a.mu_s, (long long)a.rhs, b.mu_s);
  EXPECT_GT(a.rhs, 0);  // the fallback stepped something
  ASSERT_EQ(a.log.size(), b.log.size());
  for (std::size_t i = 0; i < a.log.size(); ++i) EXPECT_NEAR(a.log[i], b.log[i], 1e-8 * b.log[i]) << "instant " << i;
}

TEST(ExactStepper, CreepingBlocksDoNotStutter) {
  // Undamped, (mu_d)_m = 0.9: about one block in six has mu_d clipped to mu_s and creeps once it
  // slides. Its row of a run read from the modes carried the projection's round-off, ~1e-16 of
  // its fast neighbours' velocities, below the stop margin: such a block stopped and restarted
  // at once, 1 ulp of time apart, hundreds of thousands of times (seen: 4.9 times the switches of
  // Dormand-Prince at tol 1e-11). Each row now starts where the state says. The switch count is
  // not a converged observable (paper/choices.md), so the bound is loose; a stutter is not.
  sb::Scene sc = small_scene(40, "smooth", 3.0, false);
  sc.material.gamma_per_s = 0;
  sc.friction.mu_d_mean = 0.9;
  sb::EventDriven exact(1e-8, true), tight(1e-11, true);
  tight.set_exact_stepper(false);
  const StepperRun a = run(sc, exact), b = run(sc, tight);
  std::printf("smooth N=40 r=0.9 undamped, 3 t0: exact %lld switches mu_s %.12f | dopri5 1e-11 %lld switches mu_s %.12f\n",
              (long long)a.switches, a.mu_s, (long long)b.switches, b.mu_s);
  EXPECT_LT(a.switches, 1.5 * b.switches);
  EXPECT_NEAR(a.mu_s, b.mu_s, 1e-4);
}

// p(tau) = prod (tau - r_k), scaled, as monomial coefficients of degree D.
template <int D>
std::vector<double> poly_from_roots(const std::vector<double>& roots, double scale) {
  std::vector<double> c(D + 1, 0.0);
  c[0] = scale;
  int deg = 0;
  for (double r : roots) {
    for (int j = deg + 1; j >= 1; --j) c[j] = c[j - 1] - r * c[j];
    c[0] = -r * c[0];
    ++deg;
  }
  return c;
}

// The first root of c on [0, h] as the screen finds it: the Bernstein bracket, refined by the
// event search's regula falsi to 1e-15 (NaN if there is no bracket).
template <int D>
double first_root_of(const std::vector<double>& c, double h) {
  sb::event_detail::BernsteinRoots<D> b;
  double lo, hi;
  if (!b.first_bracket(c.data(), h, lo, hi)) return std::nan("");
  auto p = [&](double x) {
    double y = c[D];
    for (int j = D - 1; j >= 0; --j) y = y * x + c[j];
    return y;
  };
  return sb::event_detail::first_root(p, lo, p(lo), hi, p(hi), [](double) { return 1e-15; });
}

TEST(BernsteinRoots, FindsTheFirstRootOnly) {
  // Roots at 0.3, 0.5 and 0.9 of a step of 2, positive at 0: 0.3, whichever bracket holds it.
  EXPECT_NEAR(first_root_of<10>(poly_from_roots<10>({0.3, 0.5, 0.9}, -1.0), 2.0), 0.3, 1e-14);
  EXPECT_NEAR(first_root_of<10>(poly_from_roots<10>({0.9, 0.5, 1.7, 0.3}, 1.0), 2.0), 0.3, 1e-14);
  // Positive on the step: none (its roots lie beyond it).
  EXPECT_TRUE(std::isnan(first_root_of<10>(poly_from_roots<10>({2.5, 3.0}, 1.0), 2.0)));
  // A root exactly at the end of the step is found there.
  EXPECT_EQ(first_root_of<10>(poly_from_roots<10>({2.0}, -1.0), 2.0), 2.0);
}

TEST(BernsteinRoots, TouchesAndDips) {
  // (tau - 1)^2 + 1e-9: a touch from above that never crosses.
  auto c = poly_from_roots<10>({1.0, 1.0}, 1.0);
  c[0] += 1e-9;
  EXPECT_TRUE(std::isnan(first_root_of<10>(c, 2.0)));
  // (tau - 1)^2 - 1e-9: a dip below zero between two roots 6.3e-5 apart; the first is found.
  c[0] -= 2e-9;
  EXPECT_NEAR(first_root_of<10>(c, 2.0), 1.0 - std::sqrt(1e-9), 1e-12);
  // Zero at the start and rising (a block that has just started to slide): no event.
  EXPECT_TRUE(std::isnan(first_root_of<10>(poly_from_roots<10>({0.0, -1.0}, 1.0), 2.0)));
  // Zero at the start and falling: the event is at the start.
  EXPECT_NEAR(first_root_of<10>(poly_from_roots<10>({0.0, -1.0}, -1.0), 2.0), 0.0, 1e-9);
}

TEST(BernsteinRoots, NaNGivesTheWholeStepNotASearchOfEveryHalf) {
  sb::event_detail::BernsteinRoots<10> b;
  std::vector<double> c(11, 1.0);
  c[3] = std::numeric_limits<double>::quiet_NaN();
  double lo, hi;
  ASSERT_TRUE(b.first_bracket(c.data(), 2.0, lo, hi));
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, 2.0);
}

}  // namespace
