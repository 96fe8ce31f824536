// Cost of the RK4 kernel per block and step: sb::Rk4 (all four compile-time effect
// specialisations) against the paper's method written plainly (naive_rk4.hpp: every block at
// every stage, no quiet-phase jump, no specialisation), on smooth and grooved chains.
// Each iteration restarts a short run from the same active state (see bench_setup.hpp), so
// every iteration does identical work and the rate counters are exact.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bench_setup.hpp"
#include "naive_rk4.hpp"
#include "springblock/integrate/methods/rk4.hpp"

namespace sb::bench {
namespace {

constexpr int kSteps = 256;  // per iteration: long enough to amortise run()'s set-up
const char* const kPatterns[] = {"smooth", "periodic:10,10", "hierarchical:60,6,1"};
const int kSizes[] = {200, 360};

struct Case {
  int N;
  std::string pattern;
  EffectCase effects;
  bool naive;
};

State run_once(const Case& k, const Chain& c, const State& init, double h) {
  State s = init;
  if (k.naive) {
    NaiveRk4(h).run(c, s, kSteps * h);
  } else {
    NullObserver obs;
    const double t_end = kSteps * h;
    Rk4(h).run(c, s, t_end, t_end, obs);
  }
  return s;
}

void bm_kernel(benchmark::State& st, Case k) {
  const Scene scene = make_scene(k.N, k.pattern, k.effects);
  const Chain c = build_chain(scene, 0);
  const State init = active_state(c);
  const double h = scene.run.dt_s;
  // The rate counters assume every iteration steps kSteps times; a quiet jump would break that.
  const State probe = run_once(k, c, init, h);
  if (probe.steps != kSteps) {
    st.SkipWithError("the quiet-phase jump fired: the starting state is not active enough");
    return;
  }
  for (auto _ : st) {
    State s = run_once(k, c, init, h);
    benchmark::DoNotOptimize(s.u.data());
    benchmark::ClobberMemory();
  }
  const double block_steps = static_cast<double>(k.N) * kSteps;
  // Inverted rate: seconds per block-step (summarize.py prints it in ns).
  st.counters["s_per_block_step"] =
      benchmark::Counter(block_steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.counters["rhs_evals"] = static_cast<double>(probe.rhs_evals);
  st.counters["switches_per_block_step"] = static_cast<double>(probe.switches) / block_steps;
}

// The plain implementation must follow sb::Rk4's trajectory to roundoff, or the comparison
// is meaningless. Returns false (and says why) if it does not.
bool check_same_trajectory() {
  bool ok = true;
  for (int N : kSizes)
    for (const char* p : kPatterns)
      for (const EffectCase& e : {kFull, kNoKint, kNoGamma, kNoKintNoGamma}) {
        const Scene scene = make_scene(N, p, e);
        const Chain c = build_chain(scene, 0);
        const State init = active_state(c);
        const State a = run_once({N, p, e, false}, c, init, scene.run.dt_s);
        const State b = run_once({N, p, e, true}, c, init, scene.run.dt_s);
        const StateDeviation d = deviation(c, a, b);
        const bool same = d.roundoff() && a.steps == b.steps && a.switches == b.switches;
        std::printf("check %-20s N=%d %-12s max|du|/A = %.1e  max|dv|/(A w_s) = %.1e  "
                    "dir mismatches %d  switches %lld/%lld  steps %lld %s\n",
                    p, N, e.name, d.rel_u, d.rel_v, d.dir_mismatch, static_cast<long long>(a.switches),
                    static_cast<long long>(b.switches), static_cast<long long>(a.steps), same ? "ok" : "DIFFERENT");
        ok = ok && same;
      }
  return ok;
}

void register_all() {
  for (int N : kSizes)
    for (const char* p : kPatterns) {
      for (const EffectCase& e : {kFull, kNoKint, kNoGamma, kNoKintNoGamma})
        benchmark::RegisterBenchmark(("rk4/fast/" + std::string(e.name) + "/" + p + "/N:" + std::to_string(N)).c_str(),
                                     bm_kernel, Case{N, p, e, false});
      benchmark::RegisterBenchmark(("rk4/naive/full/" + std::string(p) + "/N:" + std::to_string(N)).c_str(),
                                   bm_kernel, Case{N, p, kFull, true});
    }
}

}  // namespace
}  // namespace sb::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (!sb::bench::check_same_trajectory()) {
    std::fprintf(stderr, "plain and fast RK4 disagree beyond roundoff; not benchmarking\n");
    return 1;
  }
  sb::bench::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
