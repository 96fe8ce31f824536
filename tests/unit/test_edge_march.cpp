// EdgeMarch's first threshold crossing of a sum of damped modes (edge_march.hpp), against a
// reference that shares only the closed form of one mode (DampedMode::eval) with it: a dense
// scan and bisection to adjacent doubles. Both senses, damped, undamped and overdamped modes, crossings on a falling
// affine part (the slope's sign differs from the rising case), and a near-grazing touch.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "springblock/integrate/linear/edge_march.hpp"

namespace {

using sb::event_detail::DampedMode;
using sb::event_detail::EdgeMarch;

struct Signal {
  double a, b;
  std::vector<double> w, q0, p0;
  std::vector<DampedMode> modes;
  // F summed in the order EdgeMarch documents for every such sum (edge_march.cpp, weighted):
  // mode k in lane k % 4, the lanes added pairwise, then the affine part. The crossed end it
  // returns must reach the threshold by this very sum, to the last bit.
  double F(double tau) const {
    double d[4] = {};
    for (std::size_t k = 0; k < modes.size(); ++k) {
      double q, qd;
      modes[k].eval(q0[k], p0[k], tau, q, qd);
      d[k % 4] += w[k] * q;
    }
    return (a + b * tau) + ((d[0] + d[1]) + (d[2] + d[3]));
  }
  // How far round-off in F moves its root at tau: the magnitude of the summed terms over |dF|,
  // times the unit round-off (a root can be located no better than that, by any method).
  double root_noise(double tau) const {
    double scale = std::fabs(a) + std::fabs(b * tau), dF = b;
    for (std::size_t k = 0; k < modes.size(); ++k) {
      double q, qd;
      modes[k].eval(q0[k], p0[k], tau, q, qd);
      scale += std::fabs(w[k] * q);
      dF += w[k] * qd;
    }
    return 1.1e-16 * scale / std::fabs(dF);
  }
};

double measure(double F, EdgeMarch::Sense s) { return s == EdgeMarch::Sense::Abs ? std::fabs(F) : F; }

// The first crossing by brute force: scan at 1/200 of the fastest period, then bisect the first
// bracket until its ends are adjacent doubles. Returns the crossed end.
double reference(const Signal& sig, EdgeMarch::Sense sense, double fs, double limit) {
  double omega_max = 0;
  for (const auto& m : sig.modes) omega_max = std::max(omega_max, std::sqrt(m.omega2));
  const double h = 2 * M_PI / omega_max / 200;
  double lo = 0;
  for (double t = h;; t += h) {
    const double hi = std::min(t, limit);
    if (measure(sig.F(hi), sense) >= fs) {
      double a = lo, b = hi;
      while (std::nextafter(a, b) < b) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        (measure(sig.F(mid), sense) >= fs ? b : a) = mid;
      }
      return b;
    }
    if (hi >= limit) return std::numeric_limits<double>::infinity();
    lo = hi;
  }
}

double march(const Signal& sig, EdgeMarch::Sense sense, double fs, double limit) {
  EdgeMarch m;
  for (std::size_t k = 0; k < sig.modes.size(); ++k) m.add_mode(sig.w[k], sig.modes[k], static_cast<int>(k));
  m.finish();
  m.set_sense(sense, false);
  m.set_affine(sig.a, sig.b);
  return m.first_crossing(sig.q0.data(), sig.p0.data(), fs, limit, 0.0);
}

TEST(EdgeMarch, FirstCrossingEqualsTheBruteForceRootToRoundOff) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int found = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Signal s;
    const int n = 1 + trial % 4;
    // Damping from none to overdamped across the trials; frequencies over a decade.
    const double gamma = (trial % 5 == 0) ? 0.0 : std::pow(10.0, 1.0 + 3.0 * (u(rng) + 1) / 2);
    for (int k = 0; k < n; ++k) {
      const double omega = 1e3 * std::pow(10.0, (u(rng) + 1) / 2);
      s.modes.push_back({0.5 * gamma, omega * omega});
      s.w.push_back(u(rng));
      s.q0.push_back(1e-3 * u(rng));
      s.p0.push_back(omega * 1e-3 * u(rng));
    }
    // Rising or falling affine part; the threshold above the start so tau = 0 is no event.
    s.b = (trial % 2 ? 1.0 : -1.0) * std::fabs(u(rng)) * 0.5;
    s.a = 0.2 * u(rng);
    const auto sense = trial % 3 == 0 ? EdgeMarch::Sense::Upper : EdgeMarch::Sense::Abs;
    const double fs = measure(s.F(0), sense) + 1e-3 + 0.01 * std::fabs(u(rng));
    const double limit = 0.05;
    const double want = reference(s, sense, fs, limit);
    const double got = march(s, sense, fs, limit);
    if (std::isinf(want)) {
      EXPECT_TRUE(std::isinf(got)) << "trial " << trial << ": a crossing at " << got << " where none is";
      continue;
    }
    ++found;
    ASSERT_TRUE(std::isfinite(got)) << "trial " << trial << ": crossing at " << want << " missed";
    // The crossed end: the threshold is reached there, and the root lies within round-off before it.
    EXPECT_GE(measure(s.F(got), sense), fs) << "trial " << trial;
    // Two brackets of round-off width (4e-16 t each) plus 8 units of F's round-off moved to t.
    EXPECT_NEAR(got, want, 8e-16 * want + 8 * s.root_noise(want)) << "trial " << trial;
  }
  EXPECT_GT(found, 100);  // a third of the trials must cross, or the test would only probe misses
}

TEST(EdgeMarch, NearGrazingTouchIsFoundOrProvablyAbsent) {
  // One undamped mode on a constant, F = a + A sin(omega t): the threshold just below the
  // maximum a + A (a touch far narrower than the march's grid step, at the closed-form
  // t = asin((fs - a) / A) / omega) or just above it (no crossing ever).
  const double a = 0.5, A = 1e-2, omega = 1e3;
  for (const double margin : {-1e-9, -1e-6, -1e-3, 1e-9, 1e-6}) {
    Signal s{a, 0.0, {1.0}, {0.0}, {A * omega}, {DampedMode{0.0, omega * omega}}};
    const double fs = a + A + margin;
    const double got = march(s, EdgeMarch::Sense::Upper, fs, 0.01);
    if (margin > 0) {
      EXPECT_TRUE(std::isinf(got)) << margin;
    } else {
      ASSERT_TRUE(std::isfinite(got)) << margin;
      EXPECT_NEAR(got, std::asin((fs - a) / A) / omega, 1e-12) << margin;
      EXPECT_GE(s.F(got), fs) << margin;
    }
  }
}

}  // namespace
