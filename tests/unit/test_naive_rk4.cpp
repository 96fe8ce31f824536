// bench/naive_rk4, the benchmarks' yardstick for the paper's method, against the allocating
// version of the same scheme (allocating_rk4.hpp) and against sb::Rk4. Its arithmetic is the
// allocating version's, operation for operation, and this test is compiled without floating-point
// contraction (-ffp-contract=off, tests/CMakeLists.txt: a -march=native build could otherwise fuse
// a multiply and an add in one version and not in the other), so the two must give the same
// doubles, not merely close ones: any difference means the rewrite changed the scheme or a
// switching decision. Scenes: small chains from bench_setup.hpp's active state, which sets most
// blocks sliding at once, so stops and re-slips happen from the first steps; the run is cut into
// legs so that a resumed run (s.t > 0) is compared too.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "allocating_rk4.hpp"
#include "bench_setup.hpp"
#include "naive_rk4.hpp"
#include "springblock/integrate/methods/rk4.hpp"

using namespace sb;

namespace {

struct Case {
  int N;
  const char* pattern;
  bench::EffectCase effects;
};

const Case kCases[] = {{40, "smooth", bench::kFull},         {40, "periodic:10,10", bench::kFull},
                       {40, "periodic:10,10", bench::kNoKint}, {40, "smooth", bench::kNoGamma},
                       {60, "periodic:3,2", bench::kNoKintNoGamma}};
constexpr int kLegs = 4;
// The active state keeps these chains switching for about 2000-2500 steps before they settle;
// 4 legs of 500 steps stay within it (every leg switches at least n_contact / 2 times).
constexpr std::int64_t kStepsPerLeg = 500;

std::string name(const Case& k) { return std::string(k.pattern) + " N=" + std::to_string(k.N) + " " + k.effects.name; }

TEST(NaiveRk4, SameDoublesAsTheAllocatingVersion) {
  for (const Case& k : kCases) {
    SCOPED_TRACE(name(k));
    const Scene scene = bench::make_scene(k.N, k.pattern, k.effects);
    const Chain c = build_chain(scene, 0);
    const double h = scene.run.dt_s;
    State a = bench::active_state(c), b = bench::active_state(c);
    for (int leg = 1; leg <= kLegs; ++leg) {
      SCOPED_TRACE("leg " + std::to_string(leg));
      const double t_end = leg * kStepsPerLeg * h;
      const std::int64_t switches_before = a.switches;
      bench::NaiveRk4(h).run(c, a, t_end);
      sbtest::AllocatingRk4(h).run(c, b, t_end);
      ASSERT_EQ(a.t, b.t);
      ASSERT_EQ(a.steps, b.steps);
      ASSERT_EQ(a.rhs_evals, b.rhs_evals);
      ASSERT_EQ(a.switches, b.switches);
      // The comparison means something only if blocks stop and slip in every leg.
      EXPECT_GE(a.switches - switches_before, c.n_contact / 2);
      for (int i = 0; i < c.N; ++i) {
        ASSERT_EQ(a.u[i], b.u[i]) << "block " << i;
        ASSERT_EQ(a.v[i], b.v[i]) << "block " << i;
        ASSERT_EQ(a.dir[i], b.dir[i]) << "block " << i;
      }
    }
    EXPECT_EQ(a.steps, kLegs * kStepsPerLeg);
  }
}

// bench_vs_paper and bench_rk4_kernel check this before timing; here it is checked in every test
// run. sb::Rk4 computes the same forces with another kernel (a mobile mask instead of a branch,
// 1/m as a factor), which rounds differently: the two agree to round-off, with the same phases
// and the same switches.
TEST(NaiveRk4, FollowsTheLibrarysRk4ToRoundOff) {
  for (const Case& k : kCases) {
    SCOPED_TRACE(name(k));
    const Scene scene = bench::make_scene(k.N, k.pattern, k.effects);
    const Chain c = build_chain(scene, 0);
    const double h = scene.run.dt_s, t_end = kLegs * kStepsPerLeg * h;
    State a = bench::active_state(c), b = bench::active_state(c);
    bench::NullObserver obs;
    Rk4(h).run(c, a, t_end, t_end, obs);
    bench::NaiveRk4(h).run(c, b, t_end);
    const bench::StateDeviation d = bench::deviation(c, a, b);
    EXPECT_TRUE(d.roundoff()) << "max|du|/A " << d.rel_u << ", max|dv|/(A w_s) " << d.rel_v << ", "
                              << d.dir_mismatch << " phases differ";
    EXPECT_EQ(a.switches, b.switches);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_GT(b.switches, 0);
  }
}

}  // namespace
