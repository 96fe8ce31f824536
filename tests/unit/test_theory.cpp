// Tests of the closed-form single-block theory. Every check compares against something computed
// by a different route: finite differences of x(t), an independent RK4 stick-slip integration,
// limits of the formulas, closed-form normal moments, and Monte Carlo sampling.
#include "springblock/theory.hpp"

#include <gtest/gtest.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using sb::theory::cycle;
using sb::theory::mu_d_macro_gaussian;
using sb::theory::SingleBlock;
using sb::theory::x_sliding;
using sb::theory::xdot_sliding;

// The paper's default block: N = 200, L_x = 4 cm, l_y = 1 cm, l_z = 0.1 cm, rho = 1.2 g/cm^3,
// G = 5 MPa, P = 1 MPa, v = 0.05 cm/s, converted to SI by hand.
SingleBlock default_block() {
  const double Lx = 0.04, ly = 0.01, lz = 0.001, lx = Lx / 200.0;
  const double rho = 1200.0, G = 5e6, P = 1e6, N = 200.0;
  return SingleBlock{rho * lx * ly * lz, G * ly * Lx / (lz * N), 5e-4, P * Lx * ly / N};
}

// Same block pulled so fast that the arctan argument in T_d is of order one; at the default
// velocity it is ~1e4 and T_d ~ pi/omega regardless of the details, which would hide errors.
SingleBlock fast_block() {
  SingleBlock b = default_block();
  b.v_m_per_s = 10.0;
  return b;
}

double omega_of(const SingleBlock& b) { return std::sqrt(b.k_N_per_m / b.m_kg); }

TEST(Theory, DefaultBlockIsThePapersBlock) {
  const SingleBlock b = default_block();
  EXPECT_NEAR(b.m_kg, 2.4e-6, 1e-18);
  EXPECT_NEAR(b.k_N_per_m, 1e4, 1e-8);
  EXPECT_NEAR(b.F_n_N, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(b.v_m_per_s, 5e-4);
}

// ------------------------------------------------------------------------------------------
// x(t) solves the sliding equation of motion.

TEST(Theory, SlidingSolutionSatisfiesEquationOfMotion) {
  for (const SingleBlock& b : {default_block(), fast_block()}) {
    for (double mu_d : {0.0, 0.3, 0.5, 0.8}) {
      const double mu_s = 1.0, w = omega_of(b), v = b.v_m_per_s;
      const double r0 = mu_s * b.F_n_N / b.k_N_per_m;
      const double A = (mu_s - mu_d) * b.F_n_N / b.k_N_per_m;
      const double Td = cycle(b, mu_s, mu_d).T_d_s;
      // Central differences with h = 1e-3/omega: truncation ~ (omega h)^2/12 ~ 1e-7 and
      // round-off ~ eps / (omega h)^2 ~ 2e-10, both relative to the acceleration scale
      // omega^2 (A + v/omega); 2e-6 leaves a wide margin yet a wrong mu_d term (size
      // 2 mu_d F_n / m) or a wrong sign in eq2 is orders of magnitude larger.
      const double h = 1e-3 / w;
      const double acc_scale = w * w * (A + v / w);
      const double vel_scale = w * (A + v / w);
      for (double frac : {0.05, 0.2, 0.4, 0.6, 0.8, 0.95}) {
        const double t = frac * Td;
        const double xm = x_sliding(b, mu_s, mu_d, t - h), x0 = x_sliding(b, mu_s, mu_d, t),
                     xp = x_sliding(b, mu_s, mu_d, t + h);
        const double xdd_fd = (xp - 2.0 * x0 + xm) / (h * h);
        const double rhs = -w * w * (x0 - v * t - r0) - mu_d * b.F_n_N / b.m_kg;
        EXPECT_NEAR(xdd_fd, rhs, 2e-6 * acc_scale) << "mu_d=" << mu_d << " t/Td=" << frac;
        const double xd_fd = (xp - xm) / (2.0 * h);
        EXPECT_NEAR(xdot_sliding(b, mu_s, mu_d, t), xd_fd, 2e-6 * vel_scale);
      }
      // Released from rest at the origin, with the net force (mu_s - mu_d) F_n at t = 0.
      EXPECT_EQ(x_sliding(b, mu_s, mu_d, 0.0), 0.0);
      EXPECT_EQ(xdot_sliding(b, mu_s, mu_d, 0.0), 0.0);
      const double hh = 1e-4 / w;  // one-sided: x(h) ~ a h^2 / 2 near rest
      const double a0 = 2.0 * x_sliding(b, mu_s, mu_d, hh) / (hh * hh);
      EXPECT_NEAR(a0, (mu_s - mu_d) * b.F_n_N / b.m_kg, 1e-3 * acc_scale);
    }
  }
}

TEST(Theory, VelocityVanishesExactlyAtTdAndIsPositiveBefore) {
  for (const SingleBlock& b : {default_block(), fast_block()}) {
    for (double mu_d : {0.0, 0.2, 0.5, 0.9, 1.0}) {
      const double mu_s = 1.0;
      const auto c = cycle(b, mu_s, mu_d);
      const double A = (mu_s - mu_d) * b.F_n_N / b.k_N_per_m;
      const double vel_scale = b.v_m_per_s + A * c.omega;
      EXPECT_NEAR(xdot_sliding(b, mu_s, mu_d, c.T_d_s), 0.0, 1e-12 * vel_scale);
      for (int j = 1; j < 1000; ++j) {
        const double t = c.T_d_s * j / 1000.0;
        ASSERT_GT(xdot_sliding(b, mu_s, mu_d, t), 0.0) << "mu_d=" << mu_d << " j=" << j;
      }
      // Just past T_d the free solution would move backwards: T_d is the first stop. (With
      // mu_d = mu_s the velocity only touches zero after one full period.)
      if (mu_d < mu_s) {
        EXPECT_LT(xdot_sliding(b, mu_s, mu_d, c.T_d_s * 1.001), 0.0);
      }
      // eq5 from the trajectory itself.
      const double dr = x_sliding(b, mu_s, mu_d, c.T_d_s) - b.v_m_per_s * c.T_d_s - c.r0_m;
      EXPECT_NEAR(dr, c.delta_r_m, 1e-12 * c.r0_m);
    }
  }
}

// ------------------------------------------------------------------------------------------
// Independent stick-slip integration with a fixed-step RK4.

struct SimCycle {
  double T_d, delta_r, T_s, mean_abs_F_stat_over_Fn, mean_abs_F_over_Fn;
};

// Spring from the slider (at v t) to the block, friction mu_d F_n against the motion while
// sliding; sliding ends when the velocity crosses zero, sticking ends when the spring force
// reaches mu_s F_n. The spring offset is chosen so the run starts exactly at slip onset.
std::vector<SimCycle> simulate(const SingleBlock& b, double mu_s, double mu_d, int n_cycles,
                               int steps_per_period, int stick_steps) {
  const double k = b.k_N_per_m, m = b.m_kg, v = b.v_m_per_s, Fn = b.F_n_N;
  const double e_start = mu_s * Fn / k;  // extension at which the block first lets go
  const double h = 2.0 * std::numbers::pi * std::sqrt(m / k) / steps_per_period;
  const double h_stick = e_start / v / stick_steps;
  auto ext = [&](double t, double x) { return e_start + v * t - x; };
  auto acc = [&](double t, double x) { return (k * ext(t, x) - mu_d * Fn) / m; };
  // One RK4 step of length dt for x'' = acc(t, x), x' = u.
  auto rk4 = [&](double t, double x, double u, double dt, double& xo, double& uo) {
    const double k1x = u, k1u = acc(t, x);
    const double k2x = u + 0.5 * dt * k1u, k2u = acc(t + 0.5 * dt, x + 0.5 * dt * k1x);
    const double k3x = u + 0.5 * dt * k2u, k3u = acc(t + 0.5 * dt, x + 0.5 * dt * k2x);
    const double k4x = u + dt * k3u, k4u = acc(t + dt, x + dt * k3x);
    xo = x + dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    uo = u + dt / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
  };

  std::vector<SimCycle> out;
  double t_on = 0.0, x = 0.0;
  for (int c = 0; c < n_cycles; ++c) {
    SimCycle sc{};
    // Sliding, local time tau from this onset.
    double tau = 0.0, u = 0.0;
    for (long n = 0;; ++n) {
      tau = static_cast<double>(n) * h;
      double xn = 0.0, un = 0.0;
      rk4(t_on + tau, x, u, h, xn, un);
      if (n > 0 && un <= 0.0) {
        // The stop lies inside this step: bisect the step length, re-integrating from the step
        // start each time, so the event is located to RK4 accuracy rather than to h.
        double lo = 0.0, hi = h;
        for (int it = 0; it < 200 && hi - lo > 0.0; ++it) {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          double xm = 0.0, um = 0.0;
          rk4(t_on + tau, x, u, mid, xm, um);
          (um > 0.0 ? lo : hi) = mid;
        }
        double xs = 0.0, us = 0.0;
        rk4(t_on + tau, x, u, lo, xs, us);
        x = xs;
        tau += lo;
        break;
      }
      x = xn;
      u = un;
    }
    sc.T_d = tau;
    const double t_stop = t_on + tau;
    sc.delta_r = -ext(t_stop, x);  // block minus slider minus r0 is minus the extension
    // Sticking: x is frozen, the static force equals the spring force; step in time until it
    // reaches mu_s F_n and integrate |force| with the trapezoid rule.
    const double e0 = ext(t_stop, x);
    double integral = 0.0, s = 0.0;
    for (long n = 0;; ++n) {
      const double s0 = static_cast<double>(n) * h_stick, s1 = s0 + h_stick;
      const double e_a = e0 + v * s0, e_b = e0 + v * s1;
      if (k * e_b >= mu_s * Fn) {
        // The extension is linear in time while stuck, so the crossing is found exactly.
        const double ds = (mu_s * Fn / k - e_a) / v;
        integral += 0.5 * k * (std::abs(e_a) + mu_s * Fn / k) * ds;
        s = s0 + ds;
        break;
      }
      integral += 0.5 * k * (std::abs(e_a) + std::abs(e_b)) * h_stick;
    }
    sc.T_s = s;
    sc.mean_abs_F_stat_over_Fn = s > 0.0 ? integral / (s * Fn) : std::numeric_limits<double>::quiet_NaN();
    sc.mean_abs_F_over_Fn = (mu_d * Fn * sc.T_d + integral) / (Fn * (sc.T_d + sc.T_s));
    out.push_back(sc);
    t_on = t_stop + s;
  }
  return out;
}

TEST(Theory, CycleMatchesIndependentRK4StickSlip) {
  // Tolerances from the step sizes. With omega h = 2 pi / 4000 = 1.6e-3, RK4's global error is
  // ~ (omega h)^4 ~ 6e-12 of the oscillation amplitude; event location by bisection adds
  // nothing at that level. Round-off in absolute time (t up to ~2 s against T_d ~ 5e-5 s)
  // contributes eps * t / T_d ~ 1e-11. We allow 1e-8 relative (three decades of margin).
  // The stick phase uses stick_steps = 2e5 per r0/v; the trapezoid rule is exact on linear
  // pieces and errs only on the step where the force changes sign, by at most
  // k v h_stick^2 / 4, i.e. a relative error below 1 / stick_steps^2 ~ 3e-11.
  const int steps_per_period = 4000, stick_steps = 200000, n_cycles = 3;
  const double rel = 1e-8;
  for (const SingleBlock& b : {default_block(), fast_block()}) {
    for (double mu_d : {0.1, 0.3, 0.5, 0.7}) {
      const double mu_s = 1.0;
      const auto th = cycle(b, mu_s, mu_d);
      const auto sims = simulate(b, mu_s, mu_d, n_cycles, steps_per_period, stick_steps);
      ASSERT_EQ(static_cast<int>(sims.size()), n_cycles);
      double sum_t = 0.0, sum_f = 0.0;
      for (int c = 0; c < n_cycles; ++c) {
        const SimCycle& s = sims[static_cast<std::size_t>(c)];
        SCOPED_TRACE(::testing::Message() << "v=" << b.v_m_per_s << " mu_d=" << mu_d << " cycle " << c);
        EXPECT_NEAR(s.T_d, th.T_d_s, rel * th.T_d_s);
        EXPECT_NEAR(s.delta_r, th.delta_r_m, rel * th.r0_m);
        EXPECT_NEAR(s.T_s, th.T_s_s, rel * th.T_s_s);
        EXPECT_NEAR(s.mean_abs_F_stat_over_Fn, th.F_stat_mean_over_Fn, rel);
        EXPECT_NEAR(s.mean_abs_F_over_Fn, th.mu_d_macro, rel);
        sum_t += s.T_d + s.T_s;
        sum_f += s.mean_abs_F_over_Fn * (s.T_d + s.T_s);
      }
      // Whole-run time average over all cycles.
      EXPECT_NEAR(sum_f / sum_t, th.mu_d_macro, rel);
    }
  }
}

// ------------------------------------------------------------------------------------------
// Properties of eq9.

TEST(Theory, BranchesOfEq9JoinSmoothlyAtHalf) {
  for (const SingleBlock& b : {default_block(), fast_block()}) {
    for (double mu_s : {0.2, 1.0, 3.0}) {
      const double half = 0.5 * mu_s;
      const double f_half = cycle(b, mu_s, half).mu_d_macro;
      EXPECT_DOUBLE_EQ(f_half, half);
      // Left of the kink the excess term is quadratic in the distance, so the left slope tends
      // to 1 (the right branch's slope) with an error linear in delta.
      for (double rel_d : {1e-2, 1e-3, 1e-4}) {
        const double d = rel_d * mu_s;
        const double left = cycle(b, mu_s, half - d).mu_d_macro;
        const double right = cycle(b, mu_s, half + d).mu_d_macro;
        EXPECT_NEAR((f_half - left) / d, 1.0, 10.0 * rel_d);
        EXPECT_NEAR((right - f_half) / d, 1.0, 1e-9);
      }
    }
  }
}

TEST(Theory, MacroCoefficientNeverBelowMicroscopic) {
  for (const SingleBlock& b : {default_block(), fast_block()}) {
    for (double mu_s : {0.05, 0.5, 1.0, 2.5}) {
      for (int j = 0; j <= 200; ++j) {
        const double mu_d = mu_s * j / 200.0;
        const auto c = cycle(b, mu_s, mu_d);
        EXPECT_GE(c.mu_d_macro, mu_d);
        if (2.0 * mu_d >= mu_s) {
          EXPECT_EQ(c.mu_d_macro, mu_d);
        } else {
          EXPECT_GT(c.mu_d_macro, mu_d);
        }
        // eq7 (time-weighted phases) and eq9 are the same number.
        const double eq7 = (mu_d * c.T_d_s + c.F_stat_mean_over_Fn * c.T_s_s) / (c.T_d_s + c.T_s_s);
        EXPECT_NEAR(c.mu_d_macro, eq7, 1e-13 * mu_s);
        // The static mean of |force| can never exceed the threshold.
        EXPECT_LE(c.F_stat_mean_over_Fn, mu_s * (1.0 + 1e-15));
      }
    }
  }
}

TEST(Theory, StaticMeanMatchesDirectAverageOfSpringForce) {
  // Midpoint rule on |k (v s - delta_r)| over [0, T_s]; with 1e5 points its error is
  // dominated by the kink and is below 1e-9 relative.
  const SingleBlock b = default_block();
  for (double mu_d : {0.0, 0.1, 0.25, 0.45, 0.5, 0.6, 0.95}) {
    const auto c = cycle(b, 1.0, mu_d);
    const int n = 100000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) * c.T_s_s / n;
      sum += std::abs(b.k_N_per_m * (b.v_m_per_s * s - c.delta_r_m));
    }
    EXPECT_NEAR(sum / n / b.F_n_N, c.F_stat_mean_over_Fn, 1e-8) << mu_d;
  }
}

TEST(Theory, EqualCoefficientsAndTinyVelocity) {
  const SingleBlock b = default_block();
  const auto c = cycle(b, 0.7, 0.7);
  EXPECT_EQ(c.T_s_s, 0.0);
  EXPECT_EQ(c.mu_d_macro, 0.7);
  EXPECT_NEAR(c.T_d_s, 2.0 * std::numbers::pi / c.omega, 1e-15);

  // v -> 0: T_d -> pi / omega, the static fraction -> 1, and eq9 tends to
  // mu_d + (mu_s - 2 mu_d)^2 / (2 (mu_s - mu_d)); nothing may become NaN.
  for (double v : {1e-12, 1e-300, 5e-324}) {
    SingleBlock s = b;
    s.v_m_per_s = v;
    for (double mu_d : {0.0, 0.3, 0.5, 1.0}) {
      const auto t = cycle(s, 1.0, mu_d);
      EXPECT_FALSE(std::isnan(t.T_d_s) || std::isnan(t.T_s_s) || std::isnan(t.mu_d_macro) ||
                   std::isnan(t.F_stat_mean_over_Fn) || std::isnan(t.delta_r_m));
      const double lim = mu_d < 0.5 ? mu_d + (1.0 - 2.0 * mu_d) * (1.0 - 2.0 * mu_d) / (2.0 * (1.0 - mu_d))
                                    : mu_d;
      EXPECT_NEAR(t.mu_d_macro, lim, 1e-12) << v << " " << mu_d;
      if (mu_d < 1.0) {
        EXPECT_NEAR(t.T_d_s * t.omega, std::numbers::pi, 1e-6);
      }
      EXPECT_FALSE(std::isnan(x_sliding(s, 1.0, mu_d, t.T_d_s)));
      EXPECT_FALSE(std::isnan(xdot_sliding(s, 1.0, mu_d, t.T_d_s)));
    }
  }
}

TEST(Theory, RejectsInvalidInput) {
  const SingleBlock b = default_block();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(cycle(b, 0.5, 0.6), std::invalid_argument);
  EXPECT_THROW(cycle(b, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(cycle(b, -1.0, -2.0), std::invalid_argument);
  EXPECT_THROW(cycle(b, 1.0, -0.1), std::invalid_argument);
  EXPECT_THROW(cycle(b, nan, 0.1), std::invalid_argument);
  EXPECT_THROW(cycle(b, 1.0, nan), std::invalid_argument);
  EXPECT_THROW(cycle(b, inf, 0.1), std::invalid_argument);
  for (int field = 0; field < 4; ++field) {
    for (double bad : {0.0, -1.0, nan, inf}) {
      SingleBlock s = b;
      double* p[] = {&s.m_kg, &s.k_N_per_m, &s.v_m_per_s, &s.F_n_N};
      *p[field] = bad;
      EXPECT_THROW(cycle(s, 1.0, 0.3), std::invalid_argument) << field << " " << bad;
      EXPECT_THROW(x_sliding(s, 1.0, 0.3, 1e-6), std::invalid_argument);
      EXPECT_THROW(xdot_sliding(s, 1.0, 0.3, 1e-6), std::invalid_argument);
      EXPECT_THROW(mu_d_macro_gaussian(s, 1.0, 0.1, 0.3, 0.01), std::invalid_argument);
    }
  }
  EXPECT_THROW(x_sliding(b, 1.0, 0.3, nan), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, -0.1, 0.3, 0.01), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, 0.3, -0.01), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, nan, 0.1, 0.3, 0.01), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, 0.3, inf), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 0.0, 0.0, 0.3, 0.01), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, -0.3, 0.0), std::invalid_argument);
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, 0.3, 0.01, 0.0), std::invalid_argument);
}

// ------------------------------------------------------------------------------------------
// Gaussian average.

double point_value(const SingleBlock& b, double mu_s, double mu_d) {
  return cycle(b, mu_s, std::min(mu_d, mu_s)).mu_d_macro;
}

TEST(TheoryGaussian, ZeroSpreadIsThePointValue) {
  const SingleBlock b = default_block();
  for (double md : {0.0, 0.2, 0.3, 0.5, 0.7, 1.0, 1.3}) {
    EXPECT_EQ(mu_d_macro_gaussian(b, 1.0, 0.0, md, 0.0), point_value(b, 1.0, md)) << md;
  }
  // Tiny but non-zero spreads take the quadrature paths (1-D and 2-D). Away from the clip the
  // point function is C1, so the deviation is O(sd^2) and far below the tolerance.
  for (double md : {0.2, 0.3, 0.45, 0.7}) {
    const double p = point_value(b, 1.0, md);
    EXPECT_NEAR(mu_d_macro_gaussian(b, 1.0, 1e-6, md, 0.0), p, 1e-9) << md;
    EXPECT_NEAR(mu_d_macro_gaussian(b, 1.0, 0.0, md, 1e-6), p, 1e-9) << md;
    EXPECT_NEAR(mu_d_macro_gaussian(b, 1.0, 1e-6, md, 1e-6), p, 1e-9) << md;
  }
}

// Monte Carlo with the stated draw policy: negative draws are redrawn, mu_d clipped to mu_s.
void expect_matches_monte_carlo(double ms, double ss, double md, double sd) {
  const SingleBlock b = default_block();
  std::mt19937_64 rng(20160603);
  std::normal_distribution<double> ns(ms, ss > 0.0 ? ss : 1.0), nd(md, sd > 0.0 ? sd : 1.0);
  auto draw = [&](std::normal_distribution<double>& n, double mean, double s, bool strict) {
    if (s == 0.0) return mean;
    for (;;) {
      const double x = n(rng);
      if (strict ? x > 0.0 : x >= 0.0) return x;
    }
  };
  const long n = 1000000;
  double sum = 0.0, sum2 = 0.0;
  for (long i = 0; i < n; ++i) {
    const double a = draw(ns, ms, ss, true), d = draw(nd, md, sd, false);
    const double f = point_value(b, a, d);
    sum += f;
    sum2 += f * f;
  }
  const double mean = sum / n;
  const double se = std::sqrt(std::max(sum2 / n - mean * mean, 0.0) / (n - 1));
  const double q = mu_d_macro_gaussian(b, ms, ss, md, sd);
  EXPECT_NEAR(q, mean, 5.0 * se + 1e-12)
      << "means " << ms << "," << md << " sds " << ss << "," << sd << " se=" << se;
}

TEST(TheoryGaussian, AgreesWithMonteCarlo) {
  expect_matches_monte_carlo(1.0, 0.1, 0.3, 0.01);
  expect_matches_monte_carlo(1.0, 0.1, 0.45, 0.1);  // straddles the kink at mu_s / 2
  expect_matches_monte_carlo(1.0, 0.2, 0.9, 0.2);   // clip mu_d = mu_s active
  expect_matches_monte_carlo(0.3, 0.3, 0.2, 0.2);   // truncation at 0 active for both
  expect_matches_monte_carlo(1.0, 0.1, 0.4, 0.0);   // 1-D over mu_s
  expect_matches_monte_carlo(1.0, 0.0, 0.5, 0.2);   // 1-D over mu_d, both kinks inside
}

TEST(TheoryGaussian, ClipRegimeMatchesClosedFormNormalMoment) {
  // With sd_d = 0 and mean_d well above mean_s / 2 every block is in the regime
  // 2 mu_d >= mu_s (up to a >= 6 sd tail), so the average is E[min(mean_d, mu_s)], which for a
  // normal mu_s is r - [(r - m) Phi(z) + s phi(z)], z = (r - m) / s.
  const SingleBlock b = default_block();
  const double m = 1.0, s = 0.1;
  for (double r : {0.8, 0.9, 1.0, 1.1, 1.3}) {
    const double z = (r - m) / s;
    const double expected = r - ((r - m) * gsl_cdf_ugaussian_P(z) + s * gsl_ran_ugaussian_pdf(z));
    EXPECT_NEAR(mu_d_macro_gaussian(b, m, s, r, 0.0), expected, 1e-9) << r;
  }
}

void recording_handler(const char*, const char*, int, int) {}

TEST(TheoryGaussian, ReportsQuadratureFailureAndRestoresGslHandler) {
  const SingleBlock b = default_block();
  gsl_error_handler_t* before = gsl_set_error_handler(&recording_handler);
  // A relative tolerance far below double precision cannot be met: GSL signals round-off,
  // which must surface as an exception rather than the default abort().
  EXPECT_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, 0.3, 0.01, 1e-18), std::runtime_error);
  EXPECT_NO_THROW(mu_d_macro_gaussian(b, 1.0, 0.1, 0.3, 0.01));
  // Whatever handler the caller had installed is back in place afterwards.
  EXPECT_EQ(gsl_set_error_handler(before), &recording_handler);
}

TEST(TheoryGaussian, ContinuousAndMonotoneAcrossRatio) {
  const SingleBlock b = default_block();
  std::vector<double> r, g;
  for (int i = 10; i <= 100; ++i) {
    r.push_back(i / 100.0);
    g.push_back(mu_d_macro_gaussian(b, 1.0, 0.1, r.back(), 0.01));
  }
  for (std::size_t i = 0; i + 1 < g.size(); ++i) {
    // |d mu_M / d mu_d| <= 1 pointwise (slope -1/2 at mu_d = 0, 1 in the upper regime, 0 when
    // clipped), so the average cannot jump by more than the step.
    EXPECT_LE(std::abs(g[i + 1] - g[i]), 0.01 * (1.0 + 1e-6)) << r[i];
    // Decreasing in the lower regime (point minimum at 1 - 1/sqrt(2) ~ 0.29), increasing
    // above it, with a band around the minimum left unchecked.
    if (r[i + 1] <= 0.25 + 1e-12) {
      EXPECT_LT(g[i + 1], g[i]) << r[i];
    }
    if (r[i] >= 0.35 - 1e-12) {
      EXPECT_GT(g[i + 1], g[i]) << r[i];
    }
    // Never below the mean of the clipped microscopic coefficient: mu_d - mu_s is normal with
    // spread S = sqrt(0.1^2 + 0.01^2) (truncation at 0 is >= 10 sd away here), so
    // E[min(mu_d, mu_s)] = mean_d - [(mean_d - 1) Phi(z) + S phi(z)], z = (mean_d - 1) / S.
    const double S = std::hypot(0.1, 0.01), z = (r[i] - 1.0) / S;
    const double e_min = r[i] - ((r[i] - 1.0) * gsl_cdf_ugaussian_P(z) + S * gsl_ran_ugaussian_pdf(z));
    EXPECT_GE(g[i], e_min - 1e-9) << r[i];
  }
  // The averaged minimum stays near the point minimum.
  const auto it = std::min_element(g.begin(), g.end());
  EXPECT_NEAR(r[static_cast<std::size_t>(it - g.begin())], 1.0 - 1.0 / std::sqrt(2.0), 0.03);
}

}  // namespace
