// Dormand-Prince's error estimate (step/dopri5.hpp) over several spans: it is the largest of the
// spans' errors, and a NaN in any span's stages makes it NaN, so the step control rejects the
// trial (a max that drops a NaN would let a NaN state through error control).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/integrate/methods/step_control.hpp"
#include "springblock/integrate/step/dopri5.hpp"

namespace {

using sb::event_detail::Dopri5;

struct Trial {
  sb::Chain c = sbtest::hand_chain(std::vector<std::uint8_t>(9, 1), 2e4, 1e4, std::vector<double>(9, 1.0),
                                   std::vector<double>(9, 0.5));
  // Two sliding runs, blocks 1-3 and 5-7, between stuck blocks.
  std::vector<sb::event_detail::BlockRange> spans{{1, 4}, {5, 8}};
  std::vector<double> u = std::vector<double>(9, 0.0), v = std::vector<double>(9, 0.0);
  std::vector<double> mobile = std::vector<double>(9, 0.0), f_kin = std::vector<double>(9, 0.0);
  Trial() {
    for (const auto& sp : spans)
      for (int i = sp.lo; i < sp.hi; ++i) {
        mobile[i] = 1.0;
        f_kin[i] = c.f_kinetic[i];
        v[i] = 1e-3 * (1 + i);
      }
  }
  // The error of one trial of size h from (u, v) at t = 0.
  double error(double h) {
    Dopri5 dp(c.N);
    const sb::event_detail::StepControl control(c, 1e-8);
    dp.set_frozen(u.data(), spans);
    dp.first_stage<true, true>(c, spans, u.data(), v.data(), 0.0, mobile.data(), f_kin.data());
    return dp.attempt<true, true>(c, spans, u.data(), v.data(), 0.0, h, mobile.data(), f_kin.data(), control.atol_u(),
                                  control.atol_v(), control.rtol());
  }
};

TEST(Dopri5Error, IsFiniteAndShrinksWithTheStep) {
  Trial trial;
  const double big = trial.error(1e-6), small = trial.error(1e-7);
  ASSERT_TRUE(std::isfinite(big));
  ASSERT_TRUE(std::isfinite(small));
  EXPECT_GT(big, 0.0);
  EXPECT_LT(small, big);  // a fifth-order estimate falls steeply with h
}

TEST(Dopri5Error, NaNInAnySpanRejectsTheStep) {
  for (int block : {2, 6}) {  // in the first span, then in the last
    Trial trial;
    trial.v[block] = std::numeric_limits<double>::quiet_NaN();
    const double err = trial.error(1e-7);
    EXPECT_TRUE(std::isnan(err)) << "NaN at block " << block << " gave error " << err;
    EXPECT_FALSE(sb::event_detail::StepControl::acceptable(err)) << "NaN at block " << block;
  }
}

}  // namespace
