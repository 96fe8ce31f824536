// RK4's end-of-step switch screen (rk4.cpp) may only skip steps on which the exact stick/slip
// rules would change nothing: with it and without it, every run must be the same to the last
// bit (positions, velocities, switch history, mu_s, mu_d), through loading, the first slip and
// the dynamic phase, with and without internal springs and damping.
#include <gtest/gtest.h>

#include <string>

#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {

struct ScreenRun {
  State state;
  double mu_s, mu_d;
};

ScreenRun run(const Scene& sc, bool screen) {
  const Chain c = build_chain(sc, 0);
  State s = State::at_rest(c);
  FrictionObserverConfig cfg;
  cfg.F_load = c.F_load;
  cfg.mu_d_skip_s = 0.0;
  FrictionObserver obs(cfg);
  Rk4 rk4(sc.run.dt_s);
  rk4.set_switch_screen(screen);
  rk4.run(c, s, sc.duration(), sc.run.sample_dt_s, obs);
  return {s, obs.mu_s(), obs.mu_d()};
}

void expect_screen_changes_nothing(const std::string& pattern, const std::string& k_int_scale,
                                   const std::string& damping) {
  Scene sc;
  set_scene_field(sc, "N", "12");
  set_scene_field(sc, "length", "0.24cm");
  set_scene_field(sc, "pattern", pattern);
  set_scene_field(sc, "k_int_scale", k_int_scale);
  set_scene_field(sc, "damping", damping);
  set_scene_field(sc, "method", "rk4");
  set_scene_field(sc, "dt", "4e-7s");
  set_scene_field(sc, "duration", "1.4t0");
  sc.seed = 5;
  const ScreenRun a = run(sc, true), b = run(sc, false);
  EXPECT_GT(b.state.switches, 12) << "the run must reach its dynamic phase";
  EXPECT_EQ(a.state.switches, b.state.switches);
  EXPECT_EQ(a.state.steps, b.state.steps);
  EXPECT_EQ(a.state.u, b.state.u);
  EXPECT_EQ(a.state.v, b.state.v);
  EXPECT_EQ(a.state.dir, b.state.dir);
  EXPECT_EQ(a.mu_s, b.mu_s);
  EXPECT_EQ(a.mu_d, b.mu_d);
}

}  // namespace

TEST(Rk4Screen, ChangesNothingCoupledDampedWithGrooves) { expect_screen_changes_nothing("periodic:2,1", "1", "10/ms"); }
TEST(Rk4Screen, ChangesNothingCoupledUndamped) { expect_screen_changes_nothing("smooth", "1", "0"); }
TEST(Rk4Screen, ChangesNothingUncoupled) { expect_screen_changes_nothing("smooth", "0", "10/ms"); }
