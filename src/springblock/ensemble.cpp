#include "springblock/ensemble.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "springblock/integrate/integrator.hpp"

namespace sb {

Statistic summarize(const std::vector<double>& values) {
  Statistic s;
  double sum = 0;
  for (double x : values)
    if (std::isfinite(x)) sum += x, ++s.n;
  if (s.n == 0) {
    s.mean = s.std = s.sem = std::nan("");
    return s;
  }
  s.mean = sum / s.n;
  double ss = 0;
  for (double x : values)
    if (std::isfinite(x)) ss += (x - s.mean) * (x - s.mean);
  s.std = s.n > 1 ? std::sqrt(ss / (s.n - 1)) : 0.0;  // sample standard deviation
  s.sem = s.std / std::sqrt(static_cast<double>(s.n));
  return s;
}

RunResult run_repetition(const Scene& scene, int rep, const std::atomic<bool>* interrupt,
                         std::atomic<std::int64_t>* progress_ns) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Chain chain = build_chain(scene, rep);
  State state = State::at_rest(chain);
  const auto d = scene.derived();
  FrictionObserverConfig cfg;
  cfg.F_load = chain.F_load;
  cfg.peak_rule = scene.rules.peak_rule;
  cfg.peak_drop = scene.rules.peak_drop;
  cfg.mu_d_skip_s = scene.rules.mu_d_skip_t0 * scene.t0_s();
  cfg.block_area_P = d.l_x_m * scene.material.l_y_m * scene.material.P_Pa;
  cfg.keep_series = scene.observe.series && rep == 0;
  cfg.stop_after_mu_s = scene.run.stop_after_mu_s;
  if (rep == 0) cfg.stress_times_s = scene.observe.stress_times_s;
  cfg.interrupt = interrupt;
  cfg.progress_ns = progress_ns;
  FrictionObserver obs(cfg);
  auto integrator = make_integrator(scene.run);
  integrator->run(chain, state, scene.duration(), scene.run.sample_dt_s, obs);

  RunResult r;
  r.rep = rep;
  r.slipped = obs.slipped();
  r.mu_s = obs.mu_s();
  r.max_mu = obs.max_mu();
  r.t_peak_s = obs.t_peak();
  r.t_slip_s = obs.t_slip();
  r.mu_d = obs.mu_d();
  r.mu_d_signed = obs.mu_d_signed();
  r.window_samples = obs.window_samples();
  r.steps = state.steps;
  r.rhs_evals = state.rhs_evals;
  r.switches = state.switches;
  r.t_end_s = state.t;
  r.contact_fraction = static_cast<double>(chain.n_contact) / chain.N;
  r.series = obs.series();
  r.stress = obs.stress();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return r;
}

EnsembleResult run_ensemble(const Scene& scene, const std::atomic<bool>* interrupt,
                            std::function<void(double, double)> progress) {
  const auto wall0 = std::chrono::steady_clock::now();
  EnsembleResult out;
  out.runs.resize(scene.reps);
  std::vector<std::atomic<std::int64_t>> progress_ns(scene.reps);
  std::vector<char> finished(scene.reps, 0);
  const double total_ns = scene.duration() * 1e9 * scene.reps;

  std::mutex mu;
  std::condition_variable cv;
  bool done = false;
  std::thread reporter;
  if (progress) {
    reporter = std::thread([&] {
      std::unique_lock lock(mu);
      while (!cv.wait_for(lock, std::chrono::seconds(1), [&] { return done; })) {
        double ns = 0;
        for (auto& p : progress_ns) ns += static_cast<double>(p.load(std::memory_order_relaxed));
        progress(ns / total_ns,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
      }
    });
  }

  const int threads = scene.threads > 0 ? scene.threads : omp_get_max_threads();
  out.threads = std::min(threads, scene.reps);
  // An exception may not leave an OpenMP region (that is std::terminate): record it, let the
  // other threads skip their remaining repetitions, and rethrow the lowest-index one afterwards.
  std::vector<std::exception_ptr> errors(scene.reps);
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(out.threads)
  for (int rep = 0; rep < scene.reps; ++rep) {
    if ((interrupt && interrupt->load()) || failed.load()) continue;
    try {
      out.runs[rep] = run_repetition(scene, rep, interrupt, &progress_ns[rep]);
      // A repetition cut short by an interrupt is not a result.
      finished[rep] = !(interrupt && interrupt->load());
    } catch (...) {
      errors[rep] = std::current_exception();
      failed.store(true);
    }
  }
  {
    std::lock_guard lock(mu);
    done = true;
  }
  cv.notify_all();
  if (reporter.joinable()) reporter.join();

  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  for (char f : finished) out.finished_reps += f;
  out.interrupted = out.finished_reps < scene.reps;
  std::vector<double> ms, md, mds, tp;
  for (auto& r : out.runs) {
    ms.push_back(r.mu_s);
    md.push_back(r.mu_d);
    mds.push_back(r.mu_d_signed);
    tp.push_back(r.t_peak_s);
  }
  out.mu_s = summarize(ms);
  out.mu_d = summarize(md);
  out.mu_d_signed = summarize(mds);
  out.t_peak_s = summarize(tp);
  out.contact_fraction = out.runs.empty() ? 0 : out.runs[0].contact_fraction;
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return out;
}

void to_json(nlohmann::json& j, const Statistic& s) {
  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  j = {{"mean", num(s.mean)}, {"std", num(s.std)}, {"sem", num(s.sem)}, {"n", s.n}};
}

void to_json(nlohmann::json& j, const RunResult& r) {
  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  j = {{"rep", r.rep},           {"slipped", r.slipped},     {"mu_s", num(r.mu_s)},
       {"t_peak_s", r.t_peak_s}, {"t_slip_s", num(r.t_slip_s)}, {"max_mu", r.max_mu},
       {"mu_d", num(r.mu_d)},    {"mu_d_signed", num(r.mu_d_signed)},
       {"window_samples", r.window_samples}, {"steps", r.steps}, {"rhs_evals", r.rhs_evals},
       {"switches", r.switches}, {"t_end_s", r.t_end_s},     {"wall_s", r.wall_s}};
}

}  // namespace sb
