// Wall time of one whole repetition of the smooth N = 360 chain, where the quiet-phase jump
// carries the run. The jump cannot be switched off from outside sb::Rk4, so its effect is
// reported as steps spanned (duration / dt) over steps actually taken (State::steps).
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench_setup.hpp"
#include "springblock/ensemble.hpp"

namespace sb::bench {
namespace {

void bm_repetition(benchmark::State& st) {
  const Scene scene = make_scene(360, "smooth", kFull);
  RunResult r;
  for (auto _ : st) {
    r = run_repetition(scene, 0);
    benchmark::DoNotOptimize(r.mu_s);
  }
  const double spanned = std::llround(scene.duration() / scene.run.dt_s);
  st.counters["steps_taken"] = static_cast<double>(r.steps);
  st.counters["steps_spanned"] = spanned;
  st.counters["jump_ratio"] = spanned / static_cast<double>(r.steps);
  st.counters["switches"] = static_cast<double>(r.switches);
}
BENCHMARK(bm_repetition)->Name("ensemble/repetition/smooth/N:360")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sb::bench

BENCHMARK_MAIN();
