// mu(t) inside a quiet phase from the modes (QuietPhase::friction_sums) against the forces of the
// rows the same phase writes (write_sample): equal to round-off, sample by sample, through the
// ringing, the modes' cut at the settle scales and stuck blocks whose force changes sign. And
// CommonSlopeSum, the O(1) sum behind it, against the plain sum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/integrate/linear/common_slope_sum.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/state.hpp"

namespace {

TEST(CommonSlopeSum, EqualsThePlainSumAtAnyTime) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> a_of(-1.0, 1.0);
  for (double s : {2.5, -0.7, 0.0}) {
    std::vector<double> a(57);
    for (double& x : a) x = a_of(rng);
    a[3] = 0.0;  // a force exactly at zero keeps the slope's sign
    sb::event_detail::CommonSlopeSum sum;
    sum.reset(a.data(), static_cast<int>(a.size()), s);
    // Times in any order, before, between and after the sign changes.
    for (double tau : {0.0, 1.0, 0.05, 0.3, 0.31, 0.001, 2.0, 0.7}) {
      double abs_ref = 0, signed_ref = 0;
      for (double x : a) abs_ref += std::fabs(x + s * tau), signed_ref += x + s * tau;
      double sum_abs, sum_signed;
      sum.at(tau, sum_abs, sum_signed);
      EXPECT_NEAR(sum_abs, abs_ref, 1e-13 * (1 + abs_ref)) << "s " << s << " tau " << tau;
      EXPECT_NEAR(sum_signed, signed_ref, 1e-13 * (1 + std::fabs(signed_ref))) << "s " << s << " tau " << tau;
    }
  }
}

// Sum of |f| and f over the contact blocks from positions, as FrictionObserver::sample does.
void sums_from_rows(const sb::Chain& c, const sb::State& s, double& sum_abs, double& sum_signed) {
  sum_abs = sum_signed = 0;
  for (int i = 0; i < c.N; ++i) {
    if (!c.contact[i]) continue;
    const double f = c.driving_force(i, s.u.data(), s.v.data(), s.t);
    sum_abs += std::fabs(f), sum_signed += f;
  }
}

TEST(QuietPhaseSums, EqualTheWrittenRowsForces) {
  // Pawls of 1 to 3 blocks between grooves of 1 to 4 (a pawl between two grooves borders two
  // segments), a groove at each chain end, K_int at the paper's scale, damped.
  const std::vector<std::uint8_t> contact = {0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0};
  const int N = static_cast<int>(contact.size());
  const sb::Chain c = sbtest::hand_chain(contact, 7.3e5, 1e4, std::vector<double>(N, 1e9), std::vector<double>(N, 0.0));
  sb::State s = sb::State::at_rest(c);
  s.t = 0.01;
  // Stuck blocks stretched either way (some forces negative: they change sign as the slider
  // advances), grooves displaced and moving (ringing modes).
  for (int i = 0; i < N; ++i) {
    s.u[i] = c.v_slider * s.t + 1e-9 * std::sin(0.7 + 1.3 * i);
    s.v[i] = contact[i] ? 0.0 : 0.03 * std::cos(2.0 + i);
  }
  sb::event_detail::QuietPhase q(c);
  const double dt = 1e-5;
  q.set_sample_dt(dt);
  q.set_sample_scales(1e-14, 1e-10);
  q.begin(c, s.t, s.u.data(), s.v.data());
  int signs_changed = 0;
  std::vector<double> f0(N);
  for (int i = 0; i < N; ++i) f0[i] = contact[i] ? c.driving_force(i, s.u.data(), s.v.data(), s.t) : 0.0;
  sb::State row = s;
  double scale = 0;
  for (int i = 0; i < N; ++i) scale += std::fabs(f0[i]);
  for (int k = 1; k <= 400; ++k) {  // 4 ms: the modes ring, decay and are cut
    row.t = s.t + k * dt;
    q.advance_sample(row.t, true);
    double sum_abs, sum_signed;
    q.friction_sums(row.t, sum_abs, sum_signed);
    q.write_sample(row.t, row.u.data(), row.v.data(), true);
    double abs_ref, signed_ref;
    sums_from_rows(c, row, abs_ref, signed_ref);
    EXPECT_NEAR(sum_abs, abs_ref, 1e-12 * scale) << "sample " << k;
    EXPECT_NEAR(sum_signed, signed_ref, 1e-12 * scale) << "sample " << k;
    if (k == 400)
      for (int i = 0; i < N; ++i)
        if (contact[i]) signs_changed += (c.driving_force(i, row.u.data(), row.v.data(), row.t) > 0) != (f0[i] > 0);
  }
  EXPECT_GT(signs_changed, 0) << "the scene should make some stuck block's force change sign";
}

}  // namespace
