// A plain fixed-step RK4, written here and sharing nothing with the library's integrators, against
// the event method on a graded chain (micro mu_s rising from 0.8 to 1.2 along 100 blocks, smooth
// surface, each repetition to its first macroscopic slip), on a composite one (springs and masses
// of their own) and on the uniform chain: mu_s, the largest sampled friction up to the first
// sample at which every contact block has slid once. Only the chain (stiffnesses, masses, draws)
// is the library's, from build_chain.
// Two checks. Ensemble level, as stated before the runs: two independent ensembles (different
// seeds), 20 repetitions each, must agree within 3 combined standard errors sqrt(sem_a^2 + sem_b^2);
// at N = 100 that tolerance is a few percent of mu_s (printed), all such a check can resolve.
// Paired: the same 20 chains under both methods; their mean difference must be within 3 standard
// errors of the paired differences (or below 1e-4), those must resolve 0.15 % of mu_s, and no
// chain may differ by more than 0.005.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/model.hpp"

using namespace sb;

namespace {

// One repetition to the end of the loading phase; returns mu_s. The chain's springs and masses
// are read block by block, so a composite chain runs through the same lines.
double plain_rk4_mu_s(const Chain& c, double h, double sample_dt) {
  const std::int64_t stride = std::llround(sample_dt / h);  // mu(t) sampled on the library's grid
  const int N = c.N;
  std::vector<double> ks(N, c.K_s), kint(N, c.K_int), m(N, c.m);
  if (!c.blocks.uniform()) ks = c.blocks.K_s, kint = c.blocks.K_int, m = c.blocks.m;
  std::vector<double> u(N, 0), v(N, 0), us(N), vs(N), ku(N), kv(N), su(N), sv(N);
  std::vector<int> dir(N, 0), slid(N, 0);
  auto force = [&](const std::vector<double>& x, const std::vector<double>& y, int i, double t) {
    double f = ks[i] * (c.v_slider * t - x[i]) - m[i] * c.gamma * y[i];
    if (i > 0) f += kint[i - 1] * (x[i - 1] - x[i]);
    if (i + 1 < N) f += kint[i] * (x[i + 1] - x[i]);
    return f;
  };
  auto rhs = [&](const std::vector<double>& x, const std::vector<double>& y, double t) {
    for (int i = 0; i < N; ++i) {
      const bool stuck = c.contact[i] && dir[i] == 0;
      ku[i] = stuck ? 0.0 : y[i];
      kv[i] = stuck ? 0.0 : (force(x, y, i, t) - (c.contact[i] ? dir[i] * c.f_kinetic[i] : 0.0)) / m[i];
    }
  };
  // While every block is stuck at rest (u = v = 0) the pull grows as K_s v t: jump to the last
  // sample before the weakest block's threshold (nothing else happens before it). That sample
  // is the loading ramp's highest and is counted: on a smooth chain it is often mu_s itself.
  double t_first = 1e300, pull_rate = 0;  // pull_rate: d/dt of sum |f| while all are stuck
  for (int i = 0; i < N; ++i)
    if (c.contact[i]) {
      t_first = std::min(t_first, c.f_static[i] / (ks[i] * c.v_slider));
      pull_rate += ks[i] * c.v_slider;
    }
  std::int64_t n = (static_cast<std::int64_t>(t_first / h) - 1) / stride * stride;
  double mu_max = pull_rate * (n * h) / c.F_load;
  int n_slid = 0;
  for (;; ++n) {
    const double t = n * h;
    rhs(u, v, t);
    // Element by element, not vector=: that is a memmove, which the sanitizer build intercepts.
    for (int i = 0; i < N; ++i) su[i] = ku[i], sv[i] = kv[i];
    for (double stage : {0.5 * h, 0.5 * h, h}) {
      for (int i = 0; i < N; ++i) us[i] = u[i] + stage * ku[i], vs[i] = v[i] + stage * kv[i];
      rhs(us, vs, t + stage);
      const double w = stage == h ? 1.0 : 2.0;
      for (int i = 0; i < N; ++i) su[i] += w * ku[i], sv[i] += w * kv[i];
    }
    for (int i = 0; i < N; ++i) u[i] += h / 6 * su[i], v[i] += h / 6 * sv[i];
    const double t1 = (n + 1) * h;
    bool sample = (n + 1) % stride == 0;
    double friction = 0;  // sum of |f_i|: static = the pull, kinetic = against the motion (mu(t)'s modulus)
    for (int i = 0; i < N; ++i) {
      if (!c.contact[i]) continue;
      if (dir[i] != 0 && v[i] * dir[i] <= 0) v[i] = 0, dir[i] = 0;
      const double F = force(u, v, i, t1);
      if (dir[i] == 0 && std::fabs(F) > c.f_static[i]) {
        dir[i] = F > 0 ? 1 : -1;
        if (!slid[i]) slid[i] = 1, ++n_slid;
      }
      friction += std::fabs(dir[i] == 0 ? F : dir[i] * c.f_kinetic[i]);
    }
    if (sample) mu_max = std::max(mu_max, friction / c.F_load);
    // Loading ends at the first sample at which every contact block has slid, that sample
    // included (the library's all-slipped rule).
    if (sample && n_slid == c.n_contact) return mu_max;
  }
}

struct Ensemble {
  double mean = 0, sem = 0, largest = 0;  // largest: the largest |x|
};

Ensemble stats(const std::vector<double>& x) {
  Ensemble e;
  const double n = static_cast<double>(x.size());
  for (double y : x) e.mean += y / n, e.largest = std::max(e.largest, std::fabs(y));
  double ss = 0;
  for (double y : x) ss += (y - e.mean) * (y - e.mean);
  e.sem = std::sqrt(ss / (n - 1) / n);
  return e;
}

// The two checks on scene s (its seed for the paired one, seed 202 for the independent ensemble).
void check_against_plain_rk4(const Scene& s) {
  const auto event = run_ensemble(s);
  ASSERT_EQ(event.mu_s.n, 20);

  // Ensemble level: an independent ensemble, so the combined standard error is the right one.
  Scene other = s;
  other.seed = 202;
  std::vector<double> independent;
  for (int rep = 0; rep < other.reps; ++rep)
    independent.push_back(plain_rk4_mu_s(build_chain(other, rep), other.run.dt_s, other.run.sample_dt_s));
  const Ensemble rk4 = stats(independent);
  const double combined = std::hypot(event.mu_s.sem, rk4.sem);
  EXPECT_NEAR(rk4.mean, event.mu_s.mean, 3 * combined)
      << "plain RK4 " << rk4.mean << " +- " << rk4.sem << ", event " << event.mu_s.mean << " +- " << event.mu_s.sem;
  std::printf("mu_s, independent ensembles: plain RK4 %.4f +- %.4f, event %.4f +- %.4f, tolerance %.4f\n", rk4.mean,
              rk4.sem, event.mu_s.mean, event.mu_s.sem, 3 * combined);

  // The same chains (same draws) under both: the paired differences are integration error alone.
  // Samples every 1e-2 ms: on a coarse grid a sample more or less in the loading phase, or one
  // sample's time off, moves mu_s by up to a few hundredths, so a fault there shows here first.
  // The plain RK4 takes h/2: its own error is then small enough (spread of the differences under
  // 6e-4 on the composite chain, 1e-4 on the others) that a chain 0.005 off is a real difference.
  Scene coarse = s;
  coarse.run.sample_dt_s = 1e-5;
  const auto event_coarse = run_ensemble(coarse);
  std::vector<double> diff;
  for (int rep = 0; rep < coarse.reps; ++rep)
    diff.push_back(plain_rk4_mu_s(build_chain(coarse, rep), coarse.run.dt_s / 2, coarse.run.sample_dt_s) -
                   event_coarse.runs[rep].mu_s);
  const Ensemble d = stats(diff);
  std::printf("mu_s, same chains: plain RK4 - event %+.6f +- %.6f, largest %.6f\n", d.mean, d.sem, d.largest);
  EXPECT_LT(std::fabs(d.mean), std::max(3 * d.sem, 1e-4)) << "paired: " << d.mean << " +- " << d.sem;
  EXPECT_LT(3 * d.sem, 0.001) << "the paired check cannot resolve a 0.15 % difference";
  EXPECT_LT(d.largest, 0.005) << "a chain's mu_s differs by more than the plain RK4's own error";
}

Scene chain_of_100() {
  Scene s;
  s.geometry = {100, 0.02};  // the paper's block size, l_x = 0.02 cm
  s.run.stop_after_mu_s = true;
  s.reps = 20;
  s.seed = 101;
  s.rules.peak_rule = ExtractionRules::PeakRule::AllSlipped;
  return s;
}

}  // namespace

TEST(PlainRk4, AgreesWithTheEventMethodOnAGradedChain) {
  Scene s = chain_of_100();
  s.materials.segments.push_back({BlockField::MuS, 0, -1, true, 0, 0.8, 1.2});
  validate(s);
  check_against_plain_rk4(s);
}

// Composite: segments of 5 blocks alternate soft and hard, internal springs and masses 3 times
// apart (soft 1/sqrt(3), hard sqrt(3) of the uniform chain's), slider springs 1.5 times apart: the
// event method's own modes for every run of blocks that differ. Smooth, as the graded chain: the
// plain RK4's jump over the loading assumes every block starts stuck.
TEST(PlainRk4, AgreesWithTheEventMethodOnACompositeChain) {
  Scene s = chain_of_100();
  std::vector<double> scale(100), k_s(100);
  for (int i = 0; i < 100; ++i) {
    const bool hard = (i / 5) % 2 == 1;
    scale[i] = hard ? std::sqrt(3.0) : 1.0 / std::sqrt(3.0);
    k_s[i] = hard ? 1.2 : 0.8;
  }
  s.materials.columns[index_of(BlockField::KIntScale)] = scale;
  s.materials.columns[index_of(BlockField::MassScale)] = scale;
  s.materials.columns[index_of(BlockField::KsScale)] = k_s;
  s.materials.source = "test: composite";
  validate(s);
  check_against_plain_rk4(s);
}

// The uniform chain: a difference on the other two that shows here as well is not the materials'.
TEST(PlainRk4, AgreesWithTheEventMethodOnAUniformChain) {
  Scene s = chain_of_100();
  validate(s);
  check_against_plain_rk4(s);
}
