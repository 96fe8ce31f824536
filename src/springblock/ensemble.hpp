#pragma once
// Repetitions of one scene with independent seeded draws, run in parallel over repetitions.
// Repetition r always uses the stream rep_seed(seed, r) and its result is stored at index r,
// so the summary is identical whatever the thread count.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "springblock/observables.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/observe/slip_events.hpp"
#include "springblock/scene.hpp"
#include "springblock/work_profile.hpp"

namespace sb {

struct RunResult {
  int rep = 0;
  bool slipped = false;  // a first macroscopic slip was found before the end of the run
  // One value per observable of observables.hpp: mu_s, mu_s_signed, t_peak_s, t_slip_s, max_mu,
  // mu_d, mu_d_signed.
#define SB_VALUE(name, unit, extractor, summary) double name = 0;
  SB_OBSERVABLES(SB_VALUE)
#undef SB_VALUE
  std::int64_t window_samples = 0;
  std::int64_t steps = 0, rhs_evals = 0, switches = 0;
  WorkProfile work;  // where the work went (times only with scene.observe.timed_work)
  double t_end_s = 0;
  double wall_s = 0;
  // CPU time of the thread that ran it: unlike the wall time, not stretched by other load on the
  // machine (what the cost-against-N study fits).
  double cpu_s = 0;
  double contact_fraction = 0;
  std::vector<Sample> series;            // repetition 0 only, when asked
  std::vector<StressSnapshot> stress;    // repetition 0 only, when asked
  std::optional<SlipEventRecord> slip_events;  // every repetition, when the scene observes them
};

struct Statistic {
  double mean = 0, std = 0, sem = 0;
  int n = 0;  // repetitions that contributed (those with a defined value)
};
Statistic summarize(const std::vector<double>& values);

struct EnsembleResult {
  std::vector<RunResult> runs;
  // The statistic over the repetitions of each observable of observables.hpp.
#define SB_STATISTIC(name, unit, extractor, summary) Statistic name;
  SB_OBSERVABLES(SB_STATISTIC)
#undef SB_STATISTIC
  double contact_fraction = 0;
  double wall_s = 0;
  int threads = 1;
  bool interrupted = false;
  int finished_reps = 0;
  // Index (into run_ensembles' scenes) of the scene whose simulation this scene was observed
  // on, or -1 if it ran its own. Such a scene's repetitions record no wall time (their cost is
  // the other scene's) and work counters up to their own last sample.
  int trajectory_from = -1;
};

// The observables of observables.hpp as a table, for the code that treats them all alike: the
// extraction from the observer, the statistics and the JSON.
struct Observable {
  const char* name;  // the JSON key
  const char* unit;  // "" for a friction coefficient
  double (FrictionObserver::*extract)() const;
  Summary summary;
  double RunResult::*value;
  Statistic EnsembleResult::*statistic;
};
const std::vector<Observable>& observables();

// Runs one repetition (used by the ensemble, the tests and the benchmarks).
RunResult run_repetition(const Scene& scene, int rep, const std::atomic<bool>* interrupt = nullptr,
                         std::atomic<std::int64_t>* progress_ns = nullptr);

// `progress` (optional) is called about once a second with the fraction of simulated time done
// and the elapsed wall seconds, from the calling thread, which runs no repetition: it deals them
// to the thread pool (pool/) and waits. The callback should be quick: the next repetition is
// dealt after it returns.
EnsembleResult run_ensemble(const Scene& scene, const std::atomic<bool>* interrupt = nullptr,
                            std::function<void(double fraction, double elapsed_s)> progress = {});

// Several scenes on one thread pool: every (scene, repetition) is one job, so no thread
// idles at the end of a scene while another finishes its last repetition. Each scene's result
// is what run_ensemble would give it (same seeds, same order); its wall_s is its share, the sum
// of its repetitions' wall times over the threads. `progress` gets the overall fraction,
// each scene weighted by `weights` (default: reps x duration x N).
// Scenes with equal trajectory specs (trajectory_spec.hpp: they differ only in extraction
// rules, run length or kept observables, and do not stop at their first slip) share one
// simulation: the longest runs, the others observe it (observe/fan_out.hpp) and name it in
// trajectory_from.
std::vector<EnsembleResult> run_ensembles(const std::vector<Scene>& scenes,
                                          const std::atomic<bool>* interrupt = nullptr,
                                          std::function<void(double fraction, double elapsed_s)> progress = {},
                                          const std::vector<double>& weights = {});

// The ensemble of `runs` (repetition r at index r, all finished) as run_ensemble returns it,
// statistics included; wall_s and threads are the caller's. For repetitions run elsewhere
// (springblock run under mpirun) and sent back as JSON (from_json below).
EnsembleResult ensemble_from_runs(std::vector<RunResult> runs);

// A number for the results JSON: null where it is not finite (never a NaN in a results file).
nlohmann::json json_number(double x);
void to_json(nlohmann::json& j, const Statistic& s);
void to_json(nlohmann::json& j, const WorkProfile& w);
void to_json(nlohmann::json& j, const RunResult& r);
// The inverse of to_json(RunResult) plus "contact_fraction" (null reads back as NaN); the series
// and stress snapshots are not carried (the slip events are).
void from_json(const nlohmann::json& j, RunResult& r);

// A repetition's slip events as JSON columns, one entry per event in time order: t_start_s,
// duration_s, blocks, episodes, slip_m; unfinished (an event was under way at the end of the run,
// not recorded) and, then, under_way: its t_start_s, blocks, episodes and the slip_m of its
// finished episodes. slip_event_json.cpp.
void to_json(nlohmann::json& j, const SlipEventRecord& r);
void from_json(const nlohmann::json& j, SlipEventRecord& r);
// Over the repetitions that recorded slip events (null if none did): the statistic of the events
// per repetition, the number of events of each size in blocks (sizes that occur, ascending), and
// how many repetitions ended inside an event.
nlohmann::json slip_event_summary(const EnsembleResult& e);

}  // namespace sb
