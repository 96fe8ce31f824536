#include "springblock/ensemble.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/fan_out.hpp"
#include "springblock/observe/switch_tap.hpp"
#include "springblock/trajectory_spec.hpp"

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

const std::vector<Observable>& observables() {
#define SB_ROW(name, unit, extractor, summary) \
  Observable{#name, unit, &FrictionObserver::extractor, summary, &RunResult::name, &EnsembleResult::name},
  static const std::vector<Observable> table = {SB_OBSERVABLES(SB_ROW)};
#undef SB_ROW
  return table;
}

namespace {

FrictionObserverConfig observer_config(const Scene& scene, const Chain& chain, int rep,
                                       const std::atomic<bool>* interrupt,
                                       std::atomic<std::int64_t>* progress_ns) {
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
  return cfg;
}

// The observables of one repetition; the work counters and times are the caller's.
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

// CPU seconds used by the calling thread so far (a repetition runs on one thread).
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

RunResult run_repetition(const Scene& scene, int rep, const std::atomic<bool>* interrupt,
                         std::atomic<std::int64_t>* progress_ns) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_s();
  const Chain chain = build_chain(scene, rep);
  State state = State::at_rest(chain);
  state.work.timed = scene.observe.timed_work;
  FrictionObserver obs(observer_config(scene, chain, rep, interrupt, progress_ns));
  SlipEventObserver slips;
  SwitchTap with_slips(obs, slips);
  auto integrator = make_integrator(scene.run);
  integrator->run(chain, state, scene.duration(), scene.run.sample_dt_s,
                  scene.observe.slip_events ? static_cast<Observer&>(with_slips) : obs);

  RunResult r = observed(obs, chain, rep);
  if (scene.observe.slip_events) r.slip_events = slips.record();
  r.steps = state.steps;
  r.rhs_evals = state.rhs_evals;
  r.switches = state.switches;
  r.work = state.work;
  r.t_end_s = state.t;
  r.wall_s = seconds_since(wall0);
  r.cpu_s = thread_cpu_s() - cpu0;
  return r;
}

namespace {

// Repetition `rep` of several scenes that share one trajectory (equal TrajectorySpec): simulated
// once, to the longest duration, with one observer per scene behind a FanOut. scenes[0] is the
// longest; it is charged the wall time, the others record 0 (their cost is in its run).
std::vector<RunResult> run_shared_repetition(const std::vector<const Scene*>& scenes, int rep,
                                             const std::atomic<bool>* interrupt,
                                             std::atomic<std::int64_t>* progress_ns) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_s();
  const Scene& longest = *scenes.front();
  const Chain chain = build_chain(longest, rep);
  State state = State::at_rest(chain);
  state.work.timed = longest.observe.timed_work;
  std::vector<FrictionObserver> observers;
  std::vector<SlipEventObserver> slips(scenes.size());
  std::vector<SwitchTap> with_slips;
  observers.reserve(scenes.size());
  with_slips.reserve(scenes.size());
  std::vector<FanOut::View> views;
  for (std::size_t m = 0; m < scenes.size(); ++m) {
    observers.emplace_back(observer_config(*scenes[m], chain, rep, interrupt, m == 0 ? progress_ns : nullptr));
    with_slips.emplace_back(observers.back(), slips[m]);
    Observer* view = scenes[m]->observe.slip_events ? static_cast<Observer*>(&with_slips.back()) : &observers.back();
    views.push_back({view, scenes[m]->duration()});
  }
  auto integrator = make_integrator(longest.run);
  FanOut fan(std::move(views), longest.run.sample_dt_s,
             [&](double t, double t_end) { return integrator->samples_within(t, t_end); });
  integrator->run(chain, state, longest.duration(), longest.run.sample_dt_s, fan);

  std::vector<RunResult> out;
  for (std::size_t m = 0; m < scenes.size(); ++m) {
    RunResult r = observed(observers[m], chain, rep);
    const auto& v = fan.views()[m];
    r.steps = m == 0 ? state.steps : v.steps;
    r.rhs_evals = m == 0 ? state.rhs_evals : v.rhs_evals;
    r.switches = m == 0 ? state.switches : v.switches;
    r.t_end_s = m == 0 ? state.t : std::min(state.t, v.t_end);
    if (scenes[m]->observe.slip_events) r.slip_events = slips[m].record();
    out.push_back(std::move(r));
  }
  out[0].wall_s = seconds_since(wall0);
  out[0].cpu_s = thread_cpu_s() - cpu0;
  out[0].work = state.work;  // like the wall time: the others' work is in this run
  return out;
}

// The per-scene statistics from its repetitions.
void summarize_runs(EnsembleResult& out) {
  std::vector<double> values(out.runs.size());
  for (const auto& o : observables()) {
    for (std::size_t i = 0; i < out.runs.size(); ++i) values[i] = out.runs[i].*o.value;
    out.*o.statistic = summarize(values);
  }
  out.contact_fraction = out.runs.empty() ? 0 : out.runs[0].contact_fraction;
}

// Scenes that see the same trajectory (equal TrajectorySpec) form a group, simulated once by its
// longest member (the first of the longest on a tie). Returns, for each scene k, its group,
// longest first, when k leads it, and nothing for the other members; their trajectory_from in
// `out` names the leader.
std::vector<std::vector<int>> group_by_trajectory(const std::vector<Scene>& scenes, std::vector<EnsembleResult>& out) {
  const int n_scenes = static_cast<int>(scenes.size());
  std::map<TrajectorySpec, std::size_t> group_of;
  std::vector<std::vector<int>> groups;
  for (int k = 0; k < n_scenes; ++k) {
    const auto spec = trajectory_spec(scenes[k]);
    const auto it = spec ? group_of.find(*spec) : group_of.end();
    if (it != group_of.end()) {
      groups[it->second].push_back(k);
      continue;
    }
    if (spec) group_of.emplace(*spec, groups.size());
    groups.push_back({k});
  }
  std::vector<std::vector<int>> members(n_scenes);
  for (auto& g : groups) {
    std::stable_sort(g.begin(), g.end(), [&](int a, int b) { return scenes[a].duration() > scenes[b].duration(); });
    for (int m : g)
      if (m != g.front()) out[m].trajectory_from = g.front();
    members[g.front()] = std::move(g);
  }
  return members;
}

struct Job {
  int scene, rep;
};

// One job per (group, repetition), in scene order: a thread that finishes its last repetition of
// one scene starts on the next scene instead of waiting for the others.
std::vector<Job> make_jobs(const std::vector<Scene>& scenes, const std::vector<std::vector<int>>& members) {
  std::vector<Job> jobs;
  for (int k = 0; k < static_cast<int>(scenes.size()); ++k)
    if (!members[k].empty())
      for (int r = 0; r < scenes[k].reps; ++r) jobs.push_back({k, r});
  return jobs;
}

// Calls `progress` from its own thread about once a second, until destroyed, with the overall
// fraction: each job's simulated time over its duration, weighted by its scene's weight (by
// default reps x duration x N) shared among the scene's repetitions.
class ProgressReporter {
 public:
  ProgressReporter(std::function<void(double, double)> progress, const std::vector<Scene>& scenes,
                   const std::vector<Job>& jobs, const std::vector<double>& weights,
                   const std::vector<std::atomic<std::int64_t>>& progress_ns,
                   std::chrono::steady_clock::time_point wall0)
      : progress_(std::move(progress)), progress_ns_(progress_ns), wall0_(wall0), job_weight_(jobs.size()) {
    if (!progress_) return;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const Scene& sc = scenes[jobs[j].scene];
      const double w = weights.empty() ? sc.reps * sc.duration() * sc.geometry.N : weights[jobs[j].scene];
      job_weight_[j] = w / sc.reps / (sc.duration() * 1e9);
      weight_total_ += w / sc.reps;
    }
    thread_ = std::thread([this] { report(); });
  }
  ~ProgressReporter() {
    {
      std::lock_guard lock(mu_);
      done_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  void report() {
    std::unique_lock lock(mu_);
    while (!cv_.wait_for(lock, std::chrono::seconds(1), [&] { return done_; })) {
      double f = 0;
      for (std::size_t j = 0; j < job_weight_.size(); ++j)
        f += job_weight_[j] * static_cast<double>(progress_ns_[j].load(std::memory_order_relaxed));
      progress_(f / weight_total_, seconds_since(wall0_));
    }
  }

  std::function<void(double, double)> progress_;
  const std::vector<std::atomic<std::int64_t>>& progress_ns_;
  std::chrono::steady_clock::time_point wall0_;
  std::vector<double> job_weight_;
  double weight_total_ = 0;
  std::mutex mu_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

// Threads over the jobs: the most any scene asks for (0 = OpenMP's default), at most one a job.
int pool_threads(const std::vector<Scene>& scenes, std::size_t n_jobs) {
  int threads = 1;
  for (const Scene& sc : scenes) threads = std::max(threads, sc.threads > 0 ? sc.threads : omp_get_max_threads());
  return std::max(1, std::min(threads, static_cast<int>(n_jobs)));
}

// Job `job`: a repetition of a scene of its own, or of a group observed on one run.
void run_job(const std::vector<Scene>& scenes, const std::vector<int>& group, Job job,
             const std::atomic<bool>* interrupt, std::atomic<std::int64_t>* progress_ns,
             std::vector<EnsembleResult>& out) {
  if (group.size() == 1) {
    out[job.scene].runs[job.rep] = run_repetition(scenes[job.scene], job.rep, interrupt, progress_ns);
    return;
  }
  std::vector<const Scene*> views;
  for (int m : group) views.push_back(&scenes[m]);
  auto runs = run_shared_repetition(views, job.rep, interrupt, progress_ns);
  for (std::size_t v = 0; v < group.size(); ++v) out[group[v]].runs[job.rep] = std::move(runs[v]);
}

// Runs every job on `threads` threads; returns which finished (a repetition cut short by an
// interrupt is not a result). An exception may not leave an OpenMP region (that is
// std::terminate): it is recorded, the other threads skip their remaining jobs, and the
// lowest-index one is rethrown afterwards.
std::vector<char> run_jobs(const std::vector<Scene>& scenes, const std::vector<std::vector<int>>& members,
                           const std::vector<Job>& jobs, int threads, const std::atomic<bool>* interrupt,
                           std::vector<std::atomic<std::int64_t>>& progress_ns, std::vector<EnsembleResult>& out) {
  const int n_jobs = static_cast<int>(jobs.size());
  std::vector<char> finished(n_jobs, 0);
  std::vector<std::exception_ptr> errors(n_jobs);
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int j = 0; j < n_jobs; ++j) {
    if ((interrupt && interrupt->load()) || failed.load()) continue;
    try {
      run_job(scenes, members[jobs[j].scene], jobs[j], interrupt, &progress_ns[j], out);
      finished[j] = !(interrupt && interrupt->load());
    } catch (...) {
      errors[j] = std::current_exception();
      failed.store(true);
    }
  }
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return finished;
}

// Counts, statistics and wall time of each scene once its jobs are done.
void finish(const std::vector<Scene>& scenes, const std::vector<std::vector<int>>& members,
            const std::vector<Job>& jobs, const std::vector<char>& finished, int threads,
            std::vector<EnsembleResult>& out) {
  for (std::size_t j = 0; j < jobs.size(); ++j)
    for (int m : members[jobs[j].scene]) out[m].finished_reps += finished[j];
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    EnsembleResult& e = out[k];
    e.interrupted = e.finished_reps < scenes[k].reps;
    e.threads = std::min(threads, std::max(1, scenes[k].reps));
    summarize_runs(e);
    // Pooled with other scenes, a scene has no wall time of its own: its share is its
    // repetitions' time over the threads (for a single scene, its wall time: run_ensembles).
    double rep_s = 0;
    for (const auto& r : e.runs) rep_s += r.wall_s;
    e.wall_s = rep_s / threads;
  }
}

}  // namespace

std::vector<EnsembleResult> run_ensembles(const std::vector<Scene>& scenes, const std::atomic<bool>* interrupt,
                                          std::function<void(double, double)> progress,
                                          const std::vector<double>& weights) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<EnsembleResult> out(scenes.size());
  for (std::size_t k = 0; k < scenes.size(); ++k) out[k].runs.resize(scenes[k].reps);
  const auto members = group_by_trajectory(scenes, out);
  const auto jobs = make_jobs(scenes, members);
  std::vector<std::atomic<std::int64_t>> progress_ns(jobs.size());
  const int threads = pool_threads(scenes, jobs.size());
  std::vector<char> finished;
  {
    ProgressReporter reporter(std::move(progress), scenes, jobs, weights, progress_ns, wall0);
    finished = run_jobs(scenes, members, jobs, threads, interrupt, progress_ns, out);
  }
  finish(scenes, members, jobs, finished, threads, out);
  if (scenes.size() == 1) out[0].wall_s = seconds_since(wall0);
  return out;
}

EnsembleResult ensemble_from_runs(std::vector<RunResult> runs) {
  EnsembleResult e;
  e.runs = std::move(runs);
  e.finished_reps = static_cast<int>(e.runs.size());
  summarize_runs(e);
  return e;
}

EnsembleResult run_ensemble(const Scene& scene, const std::atomic<bool>* interrupt,
                            std::function<void(double, double)> progress) {
  return std::move(run_ensembles({scene}, interrupt, std::move(progress)).front());
}

nlohmann::json json_number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

void to_json(nlohmann::json& j, const Statistic& s) {
  j = {{"mean", json_number(s.mean)}, {"std", json_number(s.std)}, {"sem", json_number(s.sem)}, {"n", s.n}};
}

void to_json(nlohmann::json& j, const WorkProfile& w) {
  j = nlohmann::json::object();
#define SB_COUNT(name, doc) j[#name] = w.name;
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
  if (!w.timed) return;  // no times rather than zeros
#define SB_TIME(name, doc) j[#name] = w.name;
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
}

void to_json(nlohmann::json& j, const RunResult& r) {
  j = {{"rep", r.rep},         {"slipped", r.slipped},     {"window_samples", r.window_samples},
       {"steps", r.steps},     {"rhs_evals", r.rhs_evals}, {"switches", r.switches},
       {"t_end_s", r.t_end_s}, {"wall_s", r.wall_s}, {"cpu_s", r.cpu_s}, {"work", r.work}};
  for (const auto& o : observables()) j[o.name] = json_number(r.*o.value);
  if (r.slip_events) j["slip_events"] = *r.slip_events;
}

namespace {

double json_double(const nlohmann::json& v) { return v.is_null() ? std::nan("") : v.get<double>(); }

}  // namespace

void from_json(const nlohmann::json& j, RunResult& r) {
  r.rep = j.at("rep").get<int>();
  r.slipped = j.at("slipped").get<bool>();
  r.window_samples = j.at("window_samples").get<std::int64_t>();
  r.steps = j.at("steps").get<std::int64_t>();
  r.rhs_evals = j.at("rhs_evals").get<std::int64_t>();
  r.switches = j.at("switches").get<std::int64_t>();
  r.t_end_s = j.at("t_end_s").get<double>();
  r.wall_s = j.at("wall_s").get<double>();
  r.cpu_s = j.at("cpu_s").get<double>();
  r.contact_fraction = json_double(j.value("contact_fraction", nlohmann::json()));
  for (const auto& o : observables()) r.*o.value = json_double(j.at(o.name));
  if (j.contains("slip_events")) r.slip_events = j.at("slip_events").get<SlipEventRecord>();
  const auto& w = j.at("work");
#define SB_COUNT(name, doc) r.work.name = w.at(#name).get<std::int64_t>();
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
  r.work.timed = w.contains("stepping_s");
  if (!r.work.timed) return;
#define SB_TIME(name, doc) r.work.name = w.at(#name).get<double>();
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
}

}  // namespace sb
