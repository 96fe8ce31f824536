// Long runs keep the energy balance and do not drift. The stability tier runs 1e6 RK4 steps
// (~1 s); the develop tier (1e8 steps, several minutes) runs only with SPRINGBLOCK_DEVELOP=1
// in the environment, because tests/CMakeLists.txt labels this whole executable `stability`.
#include <cstdlib>

#include "stability_support.hpp"

namespace {

class LongRun : public ::testing::TestWithParam<sb::Method> {};

// Energy balance of `steps` steps of N = 10 with groove blocks (never fully stuck, so RK4 does
// every step). Reported: relative error of the balance and the drift of the mean stretch
// (u_i - v t), which is bounded by the static thresholds if nothing drifts.
void long_run(sb::Method m, double steps, double tol) {
  auto s = sbtest::base_scene(m, 10);
  s.pattern = sb::parse_pattern("periodic:2,1");
  s.run.sample_dt_s = 10 * s.run.dt_s;  // (omega_max * 10 h)^2 / 12 ~ 1e-3 at the top mode
  std::string why;
  auto integ = sbtest::try_make(s.run, why);
  if (!integ) GTEST_SKIP() << why;
  const sb::Chain c = sb::build_chain(s, 0);
  const auto r = sbtest::run_case(*integ, c, sb::State::at_rest(c), steps * s.run.dt_s, s.run.sample_dt_s);
  sbtest::expect_invariants(r, c);
  double max_stretch = 0;
  for (int i = 0; i < c.N; ++i) max_stretch = std::max(max_stretch, std::fabs(r.state.u[i] - c.v_slider * r.state.t));
  std::printf("[long] %s %.0e steps: energy rel.err %.2e, work %.3e, final max |u - v t| %.3g m "
              "(static bound %.3g m)\n", integ->name().c_str(), steps, r.energy.relative_error(),
              r.energy.work_in, max_stretch, 2 * c.F_load / c.K_s);
  EXPECT_LE(r.energy.relative_error(), tol);
  // No drift: the blocks follow the slider within the distance at which the slider spring alone
  // would hold the whole load.
  EXPECT_LE(max_stretch, 2 * c.F_load / c.K_s);
}

TEST_P(LongRun, MillionSteps) { long_run(GetParam(), 1e6, 5e-3); }

TEST_P(LongRun, HundredMillionSteps) {
  if (!std::getenv("SPRINGBLOCK_DEVELOP")) GTEST_SKIP() << "develop tier: set SPRINGBLOCK_DEVELOP=1";
  long_run(GetParam(), 1e8, 5e-3);
}

INSTANTIATE_TEST_SUITE_P(Methods, LongRun, sbtest::kMethods, sbtest::method_label);

}  // namespace
