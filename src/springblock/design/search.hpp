#pragma once
// The multi-fidelity search: successive halving (Karnin, Koren & Somekh, ICML 2013; Jamieson &
// Talwalkar, AISTATS 2016) over the candidates of a design space. Rung 0 gives every candidate
// `screen_reps` cheap repetitions (stopped at the first slip when the query needs only mu_s, or
// when mu_s alone can already rank); each later rung keeps the best 1/eta of the survivors by
// their score so far and adds repetitions until each has `growth` times as many. Every rung is
// one call of run_ensembles (one thread pool, each (candidate, repetition) a job) with its own
// scene seed, so the repetitions of different rungs are independent and the result does not
// depend on the thread count.
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "springblock/design/space.hpp"
#include "springblock/design/target.hpp"
#include "springblock/ensemble.hpp"
#include "springblock/scene.hpp"

namespace sb::design {

struct SearchOptions {
  int screen_reps = 1;  // repetitions of every candidate in rung 0
  int eta = 4;          // each rung keeps ceil(1/eta) of the survivors
  int growth = 2;       // ... and multiplies their repetitions by this
  int max_reps = 16;    // no rung goes beyond this many repetitions per candidate
  int final_pool = 15;  // halving stops once this many candidates survive
  // From the contact-fraction classes (classes.hpp), when they ran: each candidate's class mu_d
  // (NaN: none), used for the mu_d part of the score until the candidate's own mu_d is measured,
  // less `prior_margin`; and the CPU seconds of one full repetition they measured, which sets the
  // cut before the first rung of full runs (see successive_halving).
  std::vector<double> mu_d_prior;
  double prior_margin = 0;
  double full_rep_cpu_s = 0;
};

// Everything measured on one candidate, over all the rungs it took part in.
struct Estimate {
  std::vector<double> mu_s, mu_d, ratio;  // one per repetition with a defined value
  int reps = 0;                           // repetitions run (defined or not)
  int last_rung = -1;                     // -1: never run
  double cpu_s = 0;
  Statistic stat(Quantity q) const;
};

struct RungReport {
  int candidates = 0, reps_added = 0, reps_total = 0;
  bool stop_after_mu_s = false;
  std::uint64_t seed = 0;
  double wall_s = 0, cpu_s = 0;
};

struct SearchResult {
  std::vector<Estimate> estimates;  // one per candidate, same order
  std::vector<RungReport> rungs;
  std::vector<int> ranking;         // the final rung's survivors, best first
  bool interrupted = false;
};

// Called with a stage label ("rung 2: 47 candidates x 2 reps") and run_ensembles' progress.
using StageProgress = std::function<void(const std::string& stage, double fraction, double elapsed_s)>;

// Runs a stage's scenes with run_ensembles in chunks of at most `chunk` scenes (the same results
// as one call: each scene's seeds do not depend on its neighbours), calling `progress` with the
// stage's fraction and elapsed time. Why chunks: run_ensembles measures progress in simulated
// time over each scene's duration, and a scene stopped at its first slip ends at a quarter of it,
// so within one call the fraction, and the ETA from it, would be off by that factor; counting
// finished chunks is not.
std::vector<EnsembleResult> run_stage(const std::vector<Scene>& scenes, const std::atomic<bool>* interrupt,
                                      const StageProgress& progress, const std::string& label, std::size_t chunk = 200);

// The seed of a stage of a design query from the user's seed: rung k uses stage k + 1, the
// verification stage kVerifyStage, so no two stages share a repetition's stream.
constexpr int kVerifyStage = 1000;
std::uint64_t stage_seed(std::uint64_t user_seed, int stage);

// `base` is the validated scene of the query (chain, material, run control, threads, seed).
// `alive`: the candidates rung 0 starts from (indices; empty = all of them).
SearchResult successive_halving(const Scene& base, const std::vector<Candidate>& candidates, const Target& target,
                                const SearchOptions& options, const std::atomic<bool>* interrupt = nullptr,
                                const StageProgress& progress = {}, std::vector<int> alive = {});

// The scene of one candidate in a stage: the base scene with its pattern, reps and seed.
Scene candidate_scene(const Scene& base, const Candidate& c, int reps, std::uint64_t seed, bool stop_after_mu_s);

// The score (target.hpp) of an estimate; parts of the target the estimate has not measured yet
// (mu_d after a rung stopped at the first slip) count as met: an optimistic score, so a rung
// that measured only mu_s drops only candidates that mu_s alone rules out. With a class prior
// (`prior` finite), an unmeasured mu_d counts as the prior's distance to the mu_d interval less
// `margin` (never below 0): optimistic by the margin.
double optimistic_score(const Target& t, const Estimate& e, double prior = std::nan(""), double margin = 0);

}  // namespace sb::design
