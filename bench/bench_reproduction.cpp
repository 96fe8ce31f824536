// Where a reproduction's time goes: one repetition of representative scenes of the paper tier
// (4 t0, the tables' run length; fig2's chains at their own length), each split into its loading
// phase (up to the first macroscopic slip, stop_after_mu_s) and the whole run. Counters: the
// stick/slip switches of the run and the wall time per switch. The switch count is a property of
// the dynamics, not of the method (RK4 at the paper's step finds the same number to 3 %,
// README, Cost), so a run's cost is switches x (time per switch): the events themselves set the
// floor, and the time per switch is what an integrator can still win.
#include <benchmark/benchmark.h>

#include <string>

#include "springblock/ensemble.hpp"
#include "springblock/scene_fields.hpp"

namespace {

struct Case {
  const char* name;
  const char* N;
  const char* length;
  const char* pattern;
  const char* mu_d;
  const char* duration;
};

// Table rows of every kind and fig2's dearest interacting chains.
const Case kCases[] = {
    {"tpat0_smooth", "360", "7.2cm", "smooth", "0.5,0.01", "4t0"},
    {"tpat0_10_10", "360", "7.2cm", "periodic:10,10", "0.5,0.01", "4t0"},
    {"tpat0_1_8", "360", "7.2cm", "periodic:1,8", "0.5,0.01", "4t0"},
    {"tpat1_24_8_1", "120", "2.4cm", "hierarchical:24,8,1", "0.5,0.01", "4t0"},
    {"tpat2_20_1", "360", "7.2cm", "hierarchical:20,1", "0.5,0.01", "4t0"},
    {"fig2_r0.9", "200", "4cm", "smooth", "0.9,0.01", "4t0"},
    {"fig2_r0.1", "200", "4cm", "smooth", "0.1,0.01", "20t0"},
};

sb::Scene scene(const Case& c, bool loading_only) {
  sb::Scene s;
  for (auto [k, v] : {std::pair{"N", c.N}, {"length", c.length}, {"pattern", c.pattern}, {"mu_d", c.mu_d},
                      {"duration", c.duration}, {"seed", "3"}, {"reps", "1"}})
    sb::set_scene_field(s, k, v);
  s.run.stop_after_mu_s = loading_only;
  sb::validate(s);
  return s;
}

void bm_phase(benchmark::State& st, const Case& c, bool loading_only) {
  const auto s = scene(c, loading_only);
  sb::RunResult r;
  for (auto _ : st) {
    r = sb::run_repetition(s, 0);
    benchmark::DoNotOptimize(r.mu_s);
  }
  st.counters["switches"] = static_cast<double>(r.switches);
  st.counters["steps"] = static_cast<double>(r.steps);
  st.counters["s_per_switch"] = benchmark::Counter(r.switches > 0 ? static_cast<double>(r.switches) : 1.0,
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
  st.counters["simulated_s"] = r.t_end_s;
}

const int registered = [] {
  for (const auto& c : kCases)
    for (bool loading : {true, false})
      benchmark::RegisterBenchmark((std::string("reproduction/") + c.name + (loading ? "/loading" : "/run")).c_str(),
                                   bm_phase, c, loading)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
