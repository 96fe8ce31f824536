// Estrin's scheme (estrin.hpp) against Horner's rule: exact where every partial sum is an integer
// (so both must give the same double), and within a few units of round-off of the terms' size on
// random polynomials of the degrees the event refinements use, at points inside and outside
// [-1, 1].
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "springblock/integrate/numerics/estrin.hpp"

namespace {

template <int d>
double horner(const double* c, double x) {
  double p = c[d];
  for (int j = d - 1; j >= 0; --j) p = p * x + c[j];
  return p;
}

template <int d>
double size_of_terms(const double* c, double x) {
  double s = 0, xp = 1;
  for (int j = 0; j <= d; ++j) s += std::fabs(c[j] * xp), xp *= x;
  return s;
}

template <int d>
void check_random(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    double c[d + 1];
    for (double& cj : c) cj = u(rng);
    const double x = 1.5 * u(rng);
    const double want = horner<d>(c, x), got = sb::estrin<d>(c, x);
    // Each evaluation is within d units of round-off of the terms' size of the exact value.
    EXPECT_NEAR(got, want, 2.0 * d * 1.2e-16 * size_of_terms<d>(c, x)) << "degree " << d << " trial " << trial;
  }
}

}  // namespace

TEST(Estrin, IntegerPolynomialsAreExact) {
  // 1 + 2x + ... + (d+1) x^d at x = 2 and x = -3: integers far below 2^53.
  const double c[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  for (double x : {2.0, -3.0, 0.0, 1.0}) {
    EXPECT_EQ(sb::estrin<0>(c, x), horner<0>(c, x));
    EXPECT_EQ(sb::estrin<1>(c, x), horner<1>(c, x));
    EXPECT_EQ(sb::estrin<7>(c, x), horner<7>(c, x));
    EXPECT_EQ(sb::estrin<8>(c, x), horner<8>(c, x));
    EXPECT_EQ(sb::estrin<12>(c, x), horner<12>(c, x));
    EXPECT_EQ(sb::estrin<13>(c, x), horner<13>(c, x));
    EXPECT_EQ(sb::estrin<14>(c, x), horner<14>(c, x));
  }
}

TEST(Estrin, AgreesWithHornerToRoundOff) {
  std::mt19937_64 rng(11);
  check_random<7>(rng);
  check_random<8>(rng);
  check_random<12>(rng);
  check_random<13>(rng);
  check_random<14>(rng);
}
