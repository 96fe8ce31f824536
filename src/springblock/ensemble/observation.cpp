#include "springblock/ensemble/observation.hpp"

#include <ctime>

namespace sb::ensemble_detail {

FrictionObserverConfig observer_config(const Scene& scene, const Chain& chain, int rep,
                                       const std::atomic<bool>* interrupt,
                                       std::atomic<std::int64_t>* progress_ns) {
  const auto d = scene.derived();
  FrictionObserverConfig cfg;
  cfg.F_load = chain.F_load;
  cfg.peak_rule = scene.rules.peak_rule;
  cfg.peak_drop = scene.rules.peak_drop;
  cfg.peak_drop_fraction = scene.rules.peak_drop_fraction;
  cfg.peak_event_fraction = scene.rules.peak_event_fraction;
  cfg.mu_d_skip_s = scene.rules.mu_d_skip_t0 * scene.t0_s();
  cfg.block_area_P = d.l_x_m * scene.material.l_y_m * scene.material.P_Pa;
  cfg.keep_series = scene.observe.series && rep == 0;
  cfg.stop_after_mu_s = scene.run.stop_after_mu_s;
  if (rep == 0) cfg.stress_times_s = scene.observe.stress_times_s;
  cfg.interrupt = interrupt;
  cfg.progress_ns = progress_ns;
  return cfg;
}

RunResult observed(const FrictionObserver& obs, const Chain& chain, int rep) {
  RunResult r;
  r.rep = rep;
  r.slipped = obs.slipped();
  for (const auto& o : observables()) r.*o.value = (obs.*o.extract)();
  r.window_samples = obs.window_samples();
  r.contact_fraction = static_cast<double>(chain.n_contact) / chain.N;
  r.series = obs.series();
  r.stress = obs.stress();
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace sb::ensemble_detail
