#include "springblock/ensemble.hpp"

#include <omp.h>

#include <algorithm>
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

namespace {

// The per-scene statistics from its repetitions.
void summarize_runs(EnsembleResult& out) {
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
}

}  // namespace

std::vector<EnsembleResult> run_ensembles(const std::vector<Scene>& scenes, const std::atomic<bool>* interrupt,
                                          std::function<void(double, double)> progress,
                                          const std::vector<double>& weights) {
  const auto wall0 = std::chrono::steady_clock::now();
  const int n_scenes = static_cast<int>(scenes.size());
  std::vector<EnsembleResult> out(n_scenes);
  // One job per (scene, repetition), in that order: a thread that finishes its last repetition
  // of one scene starts on the next scene instead of waiting for the others.
  struct Job {
    int scene, rep;
  };
  std::vector<Job> jobs;
  for (int k = 0; k < n_scenes; ++k) {
    out[k].runs.resize(scenes[k].reps);
    for (int r = 0; r < scenes[k].reps; ++r) jobs.push_back({k, r});
  }
  const int n_jobs = static_cast<int>(jobs.size());
  std::vector<std::atomic<std::int64_t>> progress_ns(n_jobs);
  std::vector<char> finished(n_jobs, 0);
  // Progress: each scene's fraction of simulated time, weighted (by default by reps x duration x N).
  std::vector<double> job_weight(n_jobs);
  double weight_total = 0;
  for (int j = 0; j < n_jobs; ++j) {
    const Scene& sc = scenes[jobs[j].scene];
    const double w = weights.empty() ? sc.reps * sc.duration() * sc.geometry.N : weights[jobs[j].scene];
    job_weight[j] = w / sc.reps / (sc.duration() * 1e9);
    weight_total += w / sc.reps;
  }

  std::mutex mu;
  std::condition_variable cv;
  bool done = false;
  std::thread reporter;
  if (progress) {
    reporter = std::thread([&] {
      std::unique_lock lock(mu);
      while (!cv.wait_for(lock, std::chrono::seconds(1), [&] { return done; })) {
        double f = 0;
        for (int j = 0; j < n_jobs; ++j)
          f += job_weight[j] * static_cast<double>(progress_ns[j].load(std::memory_order_relaxed));
        progress(f / weight_total, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
      }
    });
  }

  int threads = 1;
  for (const Scene& sc : scenes) threads = std::max(threads, sc.threads > 0 ? sc.threads : omp_get_max_threads());
  threads = std::max(1, std::min(threads, n_jobs));
  // An exception may not leave an OpenMP region (that is std::terminate): record it, let the
  // other threads skip their remaining repetitions, and rethrow the lowest-index one afterwards.
  std::vector<std::exception_ptr> errors(n_jobs);
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int j = 0; j < n_jobs; ++j) {
    if ((interrupt && interrupt->load()) || failed.load()) continue;
    const Job job = jobs[j];
    try {
      out[job.scene].runs[job.rep] = run_repetition(scenes[job.scene], job.rep, interrupt, &progress_ns[j]);
      // A repetition cut short by an interrupt is not a result.
      finished[j] = !(interrupt && interrupt->load());
    } catch (...) {
      errors[j] = std::current_exception();
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
  for (int j = 0; j < n_jobs; ++j) out[jobs[j].scene].finished_reps += finished[j];
  for (int k = 0; k < n_scenes; ++k) {
    EnsembleResult& e = out[k];
    e.interrupted = e.finished_reps < scenes[k].reps;
    e.threads = std::min(threads, std::max(1, scenes[k].reps));
    summarize_runs(e);
    // Pooled with other scenes, a scene has no wall time of its own: its share is its
    // repetitions' time over the threads (for a single scene, its wall time below).
    double rep_s = 0;
    for (const auto& r : e.runs) rep_s += r.wall_s;
    e.wall_s = rep_s / threads;
  }
  if (n_scenes == 1) out[0].wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return out;
}

EnsembleResult run_ensemble(const Scene& scene, const std::atomic<bool>* interrupt,
                            std::function<void(double, double)> progress) {
  return std::move(run_ensembles({scene}, interrupt, std::move(progress)).front());
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
