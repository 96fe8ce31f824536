// mu(t) inside a quiet phase from the forces the phase knows (QuietRinging, summed by the
// observer's RingingSums) against the forces of the
// rows the same phase writes (write_sample): equal to round-off, sample by sample, through the
// ringing, the modes' cut at the settle scales and stuck blocks whose force changes sign. And
// CommonSlopeSum, the O(1) sum behind it, against the plain sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "hand_chain.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/linear/quiet_ringing.hpp"
#include "springblock/infinity.hpp"
#include "springblock/observe/common_slope_sum.hpp"
#include "springblock/observe/ringing_sums.hpp"
#include "springblock/state.hpp"

namespace {

TEST(CommonSlopeSum, EqualsThePlainSumAtAnyTime) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> a_of(-1.0, 1.0);
  for (double s : {2.5, -0.7, 0.0}) {
    std::vector<double> a(57);
    for (double& x : a) x = a_of(rng);
    a[3] = 0.0;  // a force exactly at zero keeps the slope's sign
    sb::CommonSlopeSum sum;
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

TEST(CommonSlopeSum, SumsOverTimesBetweenCrossingsEqualTheSummedValues) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> a_of(-1.0, 1.0);
  for (double s : {2.5, -0.7, 0.0}) {
    std::vector<double> a(40);
    for (double& x : a) x = a_of(rng);
    sb::CommonSlopeSum sum;
    sum.reset(a.data(), static_cast<int>(a.size()), s);
    int checked = 0;
    for (double tau0 = 0.0; tau0 < 1.0; tau0 += 0.0137) {
      const double dt = 1e-4;
      const long m = 37;
      const int p = sum.crossed(tau0);
      if (sum.crossed(tau0 + (m - 1) * dt) != p) continue;  // a crossing inside: not summable
      double abs_ref = 0, signed_ref = 0, sum_tau = 0;
      for (long j = 0; j < m; ++j) {
        double x, y;
        sum.at(tau0 + j * dt, x, y);
        abs_ref += x, signed_ref += y, sum_tau += tau0 + j * dt;
      }
      double sum_abs, sum_signed;
      sum.sums(p, m, sum_tau, sum_abs, sum_signed);
      EXPECT_NEAR(sum_abs, abs_ref, 1e-12 * (1 + abs_ref)) << "s " << s << " tau0 " << tau0;
      EXPECT_NEAR(sum_signed, signed_ref, 1e-12 * (1 + std::fabs(signed_ref))) << "s " << s << " tau0 " << tau0;
      ++checked;
    }
    EXPECT_GT(checked, 50);
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

// Pawls of 1 to 3 blocks between grooves of 1 to 4 (a pawl between two grooves borders two
// segments), a groove at each chain end, K_int at the paper's scale, damped; at time t, stuck
// blocks stretched either way (some forces negative: they change sign as the slider advances),
// grooves displaced and moving (ringing modes).
struct RingingScene {
  std::vector<std::uint8_t> contact;
  sb::Chain c;
  sb::State s;
};
const std::vector<std::uint8_t> kMixedPawls = {0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0};
// Pawls of one and two blocks only: every contact block borders a groove (no interior force).
const std::vector<std::uint8_t> kEdgePawls = {0, 1, 1, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0};
RingingScene ringing_scene(double t, const std::vector<std::uint8_t>& contact = kMixedPawls) {
  const int N = static_cast<int>(contact.size());
  sb::Chain c = sbtest::hand_chain(contact, 7.3e5, 1e4, std::vector<double>(N, 1e9), std::vector<double>(N, 0.0));
  sb::State s = sb::State::at_rest(c);
  s.t = t;
  for (int i = 0; i < N; ++i) {
    s.u[i] = c.v_slider * s.t + 1e-9 * std::sin(0.7 + 1.3 * i);
    s.v[i] = contact[i] ? 0.0 : 0.03 * std::cos(2.0 + i);
  }
  return {contact, std::move(c), std::move(s)};
}

// The observer's sums at each sample against the forces of the rows the phase writes; with the
// phase's end known (next_threshold), the forces that keep their sign to it are summed once. With
// settled grooves (their records on their paths, their rows written there, as the integrator
// hands them over) the forces beside them are affine, and some of them change sign before the end.
void expect_sums_equal_the_rows(bool end_known, bool settled = false) {
  RingingScene sc = ringing_scene(0.01);
  const std::vector<std::uint8_t>& contact = sc.contact;
  const sb::Chain& c = sc.c;
  const sb::State& s = sc.s;
  const int N = c.N;
  sb::event_detail::RunStore q_store(c);
  sb::event_detail::QuietPhase q(c, q_store);
  sb::event_detail::QuietRinging q_forces(q);
  sb::RingingSums q_sums(q_forces);
  const double dt = 1e-5;
  q_store.shapes().set_sample_dt(dt);
  q.set_sample_scales(1e-14, 1e-10);
  for (int i = 0; settled && i < N;) {
    int j = i;
    while (j < N && !contact[j]) ++j;
    if (j > i) {
      const auto& run = q_store.project(c, {i, j}, s.t, s.u.data(), s.v.data(), nullptr,
                                        sb::event_detail::RunStore::kSettled, false);
      q_store.write_path(run, s.t, sc.s.u.data(), sc.s.v.data());
    }
    i = j + 1;
  }
  q.begin(c, s.t, s.u.data(), s.v.data());
  const double t_end = end_known ? q.next_threshold(c, s.t + 400 * dt).t : sb::kInf;
  int signs_changed = 0;
  std::vector<double> f0(N);
  for (int i = 0; i < N; ++i) f0[i] = contact[i] ? c.driving_force(i, s.u.data(), s.v.data(), s.t) : 0.0;
  sb::State row = s;
  double scale = 0;
  for (int i = 0; i < N; ++i) scale += std::fabs(f0[i]);
  for (int k = 1; k <= 400 && s.t + k * dt < t_end; ++k) {  // 4 ms: the modes ring, decay and are cut
    row.t = s.t + k * dt;
    q.advance_sample(row.t, true);
    double sum_abs, sum_signed;
    q_sums.at(row.t, sum_abs, sum_signed);
    q.write_sample(row.t, row.u.data(), row.v.data(), true);
    double abs_ref, signed_ref;
    sums_from_rows(c, row, abs_ref, signed_ref);
    EXPECT_NEAR(sum_abs, abs_ref, 1e-12 * scale) << "sample " << k;
    EXPECT_NEAR(sum_signed, signed_ref, 1e-12 * scale) << "sample " << k;
    if (k == 400 || !(s.t + (k + 1) * dt < t_end))
      for (int i = 0; i < N; ++i)
        if (contact[i]) signs_changed += (c.driving_force(i, row.u.data(), row.v.data(), row.t) > 0) != (f0[i] > 0);
  }
  EXPECT_GT(signs_changed, 0) << "the scene should make some stuck block's force change sign";
}

TEST(QuietPhaseSums, EqualTheWrittenRowsForces) { expect_sums_equal_the_rows(false); }

TEST(QuietPhaseSums, EqualTheWrittenRowsForcesWithThePhaseEndKnown) { expect_sums_equal_the_rows(true); }

TEST(QuietPhaseSums, EqualTheWrittenRowsForcesBesideSettledGrooves) {
  expect_sums_equal_the_rows(false, true);
  expect_sums_equal_the_rows(true, true);
}

// Blocks of 64 samples summed by window_sums against friction_sums added sample by sample: equal
// to round-off, whether or not some force changes sign in the block, and independent of what was
// sampled before the block. Returns the blocks taken, refused, taken with a force changing sign,
// and taken with the force of a block beside no groove changing sign.
struct WindowCounts {
  int taken = 0, refused = 0, changing = 0, interior_changing = 0;
};
WindowCounts window_sums_against_one_by_one(const std::vector<std::uint8_t>& pawls) {
  const double dt = 1e-5;
  const RingingScene sc = ringing_scene(1000 * dt, pawls);
  const std::vector<std::uint8_t>& contact = sc.contact;
  const sb::Chain& c = sc.c;
  const sb::State& s = sc.s;
  const int N = c.N;
  sb::event_detail::RunStore q_store(c), ref_store(c);
  sb::event_detail::QuietPhase q(c, q_store), ref(c, ref_store);
  sb::event_detail::QuietRinging q_forces(q), ref_forces(ref);
  sb::RingingSums q_sums(q_forces), ref_sums(ref_forces);
  for (auto* st : {&q_store, &ref_store}) st->shapes().set_sample_dt(dt);
  for (auto* p : {&q, &ref}) {
    p->set_sample_scales(1e-14, 1e-10);
    p->begin(c, s.t, s.u.data(), s.v.data());
  }
  double scale = 0;
  for (int i = 0; i < N; ++i)
    if (contact[i]) scale += std::fabs(c.driving_force(i, s.u.data(), s.v.data(), s.t));
  const long n = sb::event_detail::QuietPhase::kSampleBlock;
  WindowCounts count;
  sb::State row = s;
  for (long k0 = 1000; k0 < 1000 + 40 * n; k0 += n) {  // 25 ms: ringing, cut, affine
    double sum_abs, sum_signed;
    const bool ok = q_sums.window(k0, dt, n, sum_abs, sum_signed);
    double abs_ref = 0, signed_ref = 0;
    std::vector<int> sign(N, 0);
    bool sign_kept = true, interior_kept = true;  // every force keeps one sign over the block
    for (long k = k0; k < k0 + n; ++k) {
      row.t = static_cast<double>(k) * dt;
      ref.advance_sample(row.t, true);
      double x, y;
      ref_sums.at(row.t, x, y);
      abs_ref += x, signed_ref += y;
      ref.write_sample(row.t, row.u.data(), row.v.data(), true);
      for (int i = 0; i < N; ++i) {
        if (!contact[i]) continue;
        const int sg = c.driving_force(i, row.u.data(), row.v.data(), row.t) >= 0 ? 1 : -1;
        const bool kept = sign[i] == 0 || sign[i] == sg;
        sign_kept = sign_kept && kept;
        if (i > 0 && i + 1 < N && contact[i - 1] && contact[i + 1]) interior_kept = interior_kept && kept;
        sign[i] = sg;
      }
    }
    if (!ok) {
      ++count.refused;
      continue;
    }
    ++count.taken;
    count.changing += !sign_kept;
    count.interior_changing += !interior_kept;
    // Round-off of sums of ~n samples, relative to their size.
    EXPECT_NEAR(sum_abs, abs_ref, 1e-14 * (std::fabs(abs_ref) + n * scale)) << "block at " << k0;
    EXPECT_NEAR(sum_signed, signed_ref, 1e-14 * (std::fabs(abs_ref) + n * scale)) << "block at " << k0;
    // Sampling other times in between changes nothing.
    q.advance_sample(static_cast<double>(k0 + 3) * dt, true);
    double again_abs, again_signed;
    EXPECT_TRUE(q_sums.window(k0, dt, n, again_abs, again_signed));
    EXPECT_EQ(again_abs, sum_abs);
    EXPECT_EQ(again_signed, sum_signed);
  }
  return count;
}

TEST(QuietPhaseSums, WindowSumsEqualTheSamplesSummedOneByOne) {
  // A force beside no groove is affine: where one crosses zero inside the block, the samples on
  // either side of its crossing are summed apart. Blocks with such a crossing must be among
  // those taken (the scene has them), and none refused.
  const WindowCounts count = window_sums_against_one_by_one(kMixedPawls);
  EXPECT_GT(count.taken, 30);
  EXPECT_EQ(count.refused, 0);
  EXPECT_GT(count.interior_changing, 0) << "the scene should change the sign of a force beside no groove";
}

TEST(QuietPhaseSums, WindowSumsFollowEdgeForcesThatChangeSign) {
  // Every contact block borders a groove: a force whose sign the bounds cannot fix is summed
  // sample by sample inside the block, the rest in closed form. Blocks in which a force does
  // change sign must be among those taken (their |f| sums are checked above), and none refused.
  const WindowCounts count = window_sums_against_one_by_one(kEdgePawls);
  EXPECT_EQ(count.refused, 0);
  EXPECT_GT(count.changing, 0) << "the scene should change the sign of some edge force inside a block";
  EXPECT_GT(count.taken, 30);
}

TEST(QuietPhaseSums, EnvelopeHoldsEverySampleOfItsStretch) {
  // The same scene: bounds on the friction sums over stretches of 16 samples (envelope), from
  // the modes at the stretch's start, against friction_sums at every sample. Every sample must
  // lie within reach of the straight line, and the bounds must be tight enough to pass over
  // samples (what they are for: a reach as large as the sums themselves would hold trivially);
  // a stretch in which a force may change sign is refused.
  const double dt = 1e-5;
  const RingingScene sc = ringing_scene(1000 * dt);
  const sb::Chain& c = sc.c;
  const sb::State& s = sc.s;
  sb::event_detail::RunStore q_store(c);
  sb::event_detail::QuietPhase q(c, q_store);
  sb::event_detail::QuietRinging q_forces(q);
  sb::RingingSums q_sums(q_forces);
  q_store.shapes().set_sample_dt(dt);
  q.set_sample_scales(1e-14, 1e-10);
  q.begin(c, s.t, s.u.data(), s.v.data());
  const long n = 16;
  int taken = 0, refused = 0, tight = 0;
  for (long k0 = 1001; k0 < 1001 + 100 * n; k0 += n) {
    sb::RingingSums::Envelope e{};
    const bool ok = q_sums.envelope(k0, dt, n, e);
    bool refused_here = !ok;
    for (long j = 0; j < n; ++j) {
      const double t = static_cast<double>(k0 + j) * dt;
      q.advance_sample(t, true);
      if (refused_here) continue;
      double x, y;
      q_sums.at(t, x, y);
      const double w = static_cast<double>(j) / static_cast<double>(n - 1);
      EXPECT_LE(std::fabs(x - (e.abs_first + (e.abs_last - e.abs_first) * w)), e.reach) << "sample " << k0 + j;
      EXPECT_LE(std::fabs(y - (e.signed_first + (e.signed_last - e.signed_first) * w)), e.reach) << "sample " << k0 + j;
    }
    if (!ok) {
      ++refused;
      continue;
    }
    ++taken;
    tight += e.reach < 1e-3 * std::fabs(e.abs_last);
  }
  EXPECT_GT(taken, 10);
  EXPECT_GT(tight, 5) << "the bounds should be far inside the sums once the modes have decayed";
  EXPECT_GT(refused, 0) << "a stretch where some force changes sign must be refused";
}

}  // namespace
