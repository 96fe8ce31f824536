// Chains whose blocks differ against the uniform chain, on the event method (exact on both), one
// repetition each, same seed, interleaved in one process so the ratios are side by side:
//  - same motion: every block's slider spring, mass and internal springs doubled by per-block
//    fields (the general path: one shape per run, general modes, weighted projection) against the
//    uniform chain with K_s, m and K_int doubled by its parameters (closed-form modes): the same
//    motion up to round-off (mu_s equal to 10 digits, block steps within 0.1 %), so the ratio is
//    the general path's overhead;
//  - graded friction: micro mu_s ramping 0.8 to 1.2 (friction only: uniform mechanics);
//  - composite: segments of 30 blocks alternating K_int and mass 3 times apart (another motion:
//    stiffer segments move more, so its ratio mixes physics and overhead; counters say how much).
// periodic:10,10, N = 360 (the paper's chain), 0.3 s simulated.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "springblock/ensemble.hpp"
#include "springblock/materials.hpp"

namespace {

sb::Scene base() {
  sb::Scene s;
  s.geometry = {360, 0.072};
  s.pattern = sb::parse_pattern("periodic:10,10");
  s.run.duration_s = 0.3;
  s.rules.mu_d_skip_t0 = 0.01;  // a mu_d window inside 0.3 s
  s.seed = 3;
  s.reps = 1;
  return s;
}

void column(sb::Scene& s, sb::BlockField f, double (*value)(int)) {
  std::vector<double> x(s.geometry.N);
  for (int i = 0; i < s.geometry.N; ++i) x[i] = value(i);
  s.materials.columns[sb::index_of(f)] = x;
  s.materials.source = "bench_materials";
}

void time_repetition(benchmark::State& st, sb::Scene s) {
  sb::validate(s);
  sb::RunResult r;
  for (auto _ : st) {
    r = sb::run_repetition(s, 0);
    benchmark::DoNotOptimize(r.mu_s);
  }
  st.counters["mu_s"] = r.mu_s;
  st.counters["switches"] = static_cast<double>(r.switches);
  st.counters["block_steps"] = static_cast<double>(r.work.block_steps);
}

void bm_uniform(benchmark::State& st) { time_repetition(st, base()); }

void bm_doubled_by_parameters(benchmark::State& st) {
  sb::Scene s = base();
  s.material.G_Pa *= 2, s.material.rho_kg_per_m3 *= 2, s.k_int_scale = 2;
  time_repetition(st, s);
}

void bm_doubled_by_fields(benchmark::State& st) {
  sb::Scene s = base();
  for (sb::BlockField f : {sb::BlockField::KsScale, sb::BlockField::MassScale, sb::BlockField::KIntScale})
    column(s, f, [](int) { return 2.0; });
  time_repetition(st, s);
}

void bm_graded_friction(benchmark::State& st) {
  sb::Scene s = base();
  column(s, sb::BlockField::MuS, [](int i) { return 0.8 + 0.4 * i / 359.0; });
  time_repetition(st, s);
}

void bm_composite(benchmark::State& st) {
  sb::Scene s = base();
  auto scale = [](int i) { return (i / 30) % 2 ? std::sqrt(3.0) : 1.0 / std::sqrt(3.0); };
  column(s, sb::BlockField::KIntScale, scale);
  column(s, sb::BlockField::MassScale, scale);
  time_repetition(st, s);
}

}  // namespace

BENCHMARK(bm_uniform)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_doubled_by_parameters)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_doubled_by_fields)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_graded_friction)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_composite)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
