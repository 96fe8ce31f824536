// A closed-form event exactly at a sample time while another run slides, with every number dyadic
// so that the event time and the sample time are the same double: the exact stepper then switches
// and samples at one instant. The sample must see every run where it is, the runs the switch did
// not read included. Chain of 5 blocks, K_s = 1 N/m, v = 1 m/s, F_n = 1 N: block 0 (f_static 0.25)
// slips at t = 0.25 and slides; block 4, whose neighbour stays stuck, feels K_s v t and reaches its
// threshold 0.2578125 at t = 0.2578125 = 264 / 1024, a sample of the spacing 1 / 1024, while block
// 0 still slides. mu(t) at that sample reads block 1's static force, which depends on where
// block 0 is: against Dormand-Prince steps at tol 1e-12 (no closed-form event, no coincidence) the
// series must agree there as at every other sample. Sampling the stale row of block 0 (the switch
// wrote only the runs it read) puts that sample 7e-4 off, and only that one.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/integrate/methods/event_driven.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/state.hpp"

namespace {

std::vector<sb::Sample> series(bool exact, std::vector<double>& log) {
  sb::Chain c = sbtest::hand_chain({1, 1, 1, 1, 1}, 4.0, 2.0, {0.25, 4.0, 4.0, 4.0, 0.2578125},
                                   {0.125, 2.0, 2.0, 2.0, 0.125});
  c.K_s = 1.0, c.v_slider = 1.0, c.m = 1.0 / 1024;
  c.F_n = 1.0;
  for (int i = 0; i < c.N; ++i) c.f_static[i] = c.mu_s[i], c.f_kinetic[i] = c.mu_d[i];
  c.F_load = c.N * c.F_n;
  sb::FrictionObserverConfig cfg;
  cfg.F_load = c.F_load;
  cfg.keep_series = true;
  sb::FrictionObserver obs(cfg);
  sb::State s = sb::State::at_rest(c);
  sb::EventDriven ev(exact ? 1e-8 : 1e-12);
  ev.set_exact_stepper(exact);
  ev.set_switch_log(&log);
  ev.run(c, s, 0.3, 1.0 / 1024, obs);
  return obs.series();
}

TEST(EventAtSample, TheSampleSeesEveryRun) {
  std::vector<double> log_exact, log_dopri;
  const auto exact = series(true, log_exact);
  const auto dopri = series(false, log_dopri);
  const double T = 264.0 / 1024;
  // The coincidence happened: a switch at exactly the sample time, with block 0 still sliding.
  bool switch_at_T = false;
  for (double t : log_exact) switch_at_T = switch_at_T || t == T;
  ASSERT_TRUE(switch_at_T) << "no switch at the sample time: the scene does not test what it should";
  ASSERT_EQ(exact.size(), dopri.size());
  bool seen_T = false;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    ASSERT_EQ(exact[k].t, dopri[k].t);
    seen_T = seen_T || exact[k].t == T;
    if (exact[k].t == T) {
      EXPECT_GT(exact[k].n_sliding, 1) << "block 0 should still slide at T";
    }
    EXPECT_NEAR(exact[k].mu, dopri[k].mu, 1e-7) << "sample at t = " << exact[k].t;
  }
  EXPECT_TRUE(seen_T);
}

}  // namespace
