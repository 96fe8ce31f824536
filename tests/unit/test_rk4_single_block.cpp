// The RK4 reference on one block against the closed-form single-block theory: slip onset,
// duration of the dynamic phase, rest offset and duration of the static phase. RK4 resolves
// switching to one step, so the budget for the slip onset and the dynamic phase is a couple of
// steps. A block stopped up to one step late sits up to a h^2/2 away from the true turning
// point (a = its deceleration there); at the slider's speed v that position error costs up to
// a h^2 / (2 v) of static-phase time: about 67 steps at the paper's h and defaults. This is a
// property of the paper's method, not a tolerance chosen to pass.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/scene.hpp"
#include "springblock/theory.hpp"

using namespace sb;

namespace {

struct SwitchRecorder final : Observer {
  std::vector<double> slip_times, stick_times, stick_offsets;
  int last_dir = 0;
  void sample(const Chain& c, const State& s) override {
    if (s.dir[0] != 0 && last_dir == 0) slip_times.push_back(s.t);
    if (s.dir[0] == 0 && last_dir != 0) {
      stick_times.push_back(s.t);
      // Offset as the paper defines it (x - v t - r0 in its frame, where the slider starts r0
      // ahead): block position minus slider position.
      stick_offsets.push_back(s.u[0] - c.v_slider * s.t);
    }
    last_dir = s.dir[0];
  }
};

Scene one_block(double mu_d) {
  Scene s;
  s.geometry = {1, 2e-4};  // one block of the paper's default l_x = 0.02 cm
  s.friction = {1.0, 0.0, mu_d, 0.0};
  s.material.gamma_per_s = 0;  // the closed form has no damping
  return s;
}

}  // namespace

class SingleBlock : public ::testing::TestWithParam<double> {};

TEST_P(SingleBlock, Rk4MatchesClosedForm) {
  const double mu_d = GetParam(), h = 1e-7;
  Scene sc = one_block(mu_d);
  Chain c = build_chain(sc, 0);
  State st = State::at_rest(c);
  theory::SingleBlock b{c.m, c.K_s, c.v_slider, c.F_n};
  auto cyc = theory::cycle(b, 1.0, mu_d);
  const double t_onset = cyc.r0_m / c.v_slider;
  SwitchRecorder rec;
  Rk4 rk4(h);
  rk4.run(c, st, t_onset + 2.5 * (cyc.T_d_s + cyc.T_s_s), h, rec);
  ASSERT_GE(rec.slip_times.size(), 3u);
  ASSERT_GE(rec.stick_times.size(), 2u);
  // Onset: the threshold is crossed within the step that ends at the recorded time.
  EXPECT_NEAR(rec.slip_times[0], t_onset, 1.5 * h);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(rec.stick_times[k] - rec.slip_times[k], cyc.T_d_s, 2.5 * h) << "cycle " << k;
    // Rest offset: the block overshoots the true stop by at most one step at v ~ a h.
    const double a_stop = std::fabs(c.K_s * cyc.delta_r_m + c.f_kinetic[0]) / c.m;
    const double dx = 0.5 * a_stop * h * h;
    EXPECT_NEAR(rec.stick_offsets[k], cyc.delta_r_m, dx + 1e-12) << "cycle " << k;
    EXPECT_NEAR(rec.slip_times[k + 1] - rec.stick_times[k], cyc.T_s_s, 2.5 * h + dx / c.v_slider)
        << "cycle " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(BothRegimes, SingleBlock, ::testing::Values(0.2, 0.3, 0.5, 0.7, 0.95));
