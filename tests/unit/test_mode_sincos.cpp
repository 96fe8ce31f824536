// The modes' own sine and cosine (damped_mode.hpp: small_sincos, mode_sincos) against long double
// libm: every mode evaluation of the exact stepper and the searches goes through them, so they
// must be as accurate as the double libm they replace, at every angle, including next to the
// multiples of pi/2 where the range reduction cancels.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "springblock/integrate/linear/damped_mode.hpp"

namespace {

struct Worst {
  double sin = 0, cos = 0;
  void check(double x) {
    double s, c;
    sb::event_detail::mode_sincos(x, s, c);
    const long double S = sinl(static_cast<long double>(x)), C = cosl(static_cast<long double>(x));
    sin = std::max(sin, static_cast<double>(fabsl(s - S)));
    cos = std::max(cos, static_cast<double>(fabsl(c - C)));
  }
};

TEST(ModeSincos, WithinAnUlpOfOneAtEveryAngle) {
  // Absolute error (sin and cos are at most 1): libm's double sincos is within half an ulp of 1
  // (1.1e-16); the series and the reduction add at most one more rounding or so. 2.5e-16 lets
  // neither a lost term of the series (1/17! ~ 3e-15 at x = 1) nor a one-part pi/2 (6e-11 per
  // quadrant) through.
  Worst w;
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 400000; ++i) w.check(std::copysign(std::pow(10.0, 6.0 * std::fabs(u(gen)) - 1.0), u(gen)));
  for (int k = 1; k < 20000; ++k) {
    const double x = k * (M_PI / 2);
    w.check(x), w.check(std::nextafter(x, 0.0)), w.check(std::nextafter(x, 1e9));
  }
  for (double x : {0.0, -0.0, 1e-300, 0.5, 1.0, std::nextafter(1.0, 2.0), 99999.9, 1e5, 3e7}) w.check(x);
  std::printf("worst absolute error: sin %.3g cos %.3g\n", w.sin, w.cos);
  EXPECT_LE(w.sin, 2.5e-16);
  EXPECT_LE(w.cos, 2.5e-16);
}

TEST(ModeSincos, SmallAnglesKeepSinOddAndCosEven) {
  for (double x : {1e-12, 1e-6, 0.1, 0.75, 1.0}) {
    double s1, c1, s2, c2;
    sb::event_detail::small_sincos(x, s1, c1);
    sb::event_detail::small_sincos(-x, s2, c2);
    EXPECT_EQ(s1, -s2) << x;
    EXPECT_EQ(c1, c2) << x;
  }
}

}  // namespace
