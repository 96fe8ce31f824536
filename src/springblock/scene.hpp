#pragma once
// A scene is one configured simulation: physics, surface, run control and the observables
// wanted. It is built from options or a scene file and validated once; everything downstream
// trusts it.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "springblock/model.hpp"
#include "springblock/parameters.hpp"
#include "springblock/surface.hpp"

namespace sb {

enum class Method { RK4, Event };
std::string method_name(Method m);
Method parse_method(const std::string& text);  // throws InputError("method")

// How the macroscopic coefficients are read off mu(t). See paper/choices.md.
struct ExtractionRules {
  // Where the loading phase ends; mu_s is the largest mu(t) reached before that moment.
  //  AllSlipped (default): when every contact block has slid at least once, i.e. the whole
  //    surface has moved. Precursor slips of a few blocks, however large their mu drop on a
  //    surface with few contacts, do not end it.
  //  Drop: when mu(t) first falls `peak_drop` below its running maximum. Simple, but on
  //    surfaces with few contact blocks a precursor of 2-5 blocks already drops mu by 0.05.
  enum class PeakRule { AllSlipped, Drop } peak_rule = PeakRule::AllSlipped;
  double peak_drop = 0.05;
  // mu_d averages mu(t) from (first macroscopic slip + skip) to the end of the run,
  // skip in units of the loading time t0 (see RunControl).
  double mu_d_skip_t0 = 0.25;
};

struct RunControl {
  // The event method by default: it locates every stick/slip switch instead of resolving it to
  // one step, and is 7 to 600 times faster than RK4 at the paper's step (README, Cost). RK4 is
  // kept, by name, as the paper's own method.
  Method method = Method::Event;
  double dt_s = 1e-7;        // RK4 step (the paper's 1e-4 ms)
  // event method: relative error tolerance. The default is the loosest decade tolerance whose
  // first-peak error (accuracy_cost: worst of 3 seeds against tol 1e-12) stays below a tenth of
  // the smallest mu_s standard error the reproduction compares (1.4e-3): 5.2e-5 at 1e-8, 1.9e-3
  // at 1e-7 (paper/choices.md, Integration).
  double tol = 1e-8;
  // event method: mobile runs of up to this many blocks are propagated exactly by their modes
  // rather than stepped (0: step every run). The default is the measured optimum (bench_methods).
  int modal_max_run = 2;
  // event method: ringing groove-only runs (no contact block, so no stop to search for; only
  // their stuck neighbours' crossings) of up to this many blocks are propagated by their modes
  // too. Separate from modal_max_run because a groove run has no stop events: it pays off up to
  // much longer runs (bench_methods, modal_groove/*).
  int modal_max_groove = 32;
  // Run length in units of t0 = (mu_s)_m F_n / (K_s v), the time the slider needs to load an
  // average block to its threshold. Scaling with t0 keeps the number of stick-slip cycles the
  // same when the contact fraction (hence F_n) changes. duration_s > 0 overrides.
  double duration_t0 = 4.0;
  double duration_s = 0.0;
  double sample_dt_s = 1e-5;  // spacing of mu(t) samples
  bool stop_after_mu_s = false;  // a scene that only needs mu_s stops at the first slip
};

struct Observables {
  bool series = false;                 // keep mu(t), n_sliding(t) of repetition 0
  std::vector<double> stress_times_s;  // per-block stress snapshots of repetition 0
};

struct Scene {
  MaterialParameters material;
  ChainGeometry geometry;
  FrictionDistribution friction;
  double k_int_scale = 1.0;  // multiplies K_int; 0 decouples the blocks
  PatternSpec pattern;
  RunControl run;
  ExtractionRules rules;
  Observables observe;
  int reps = 20;
  std::uint64_t seed = 1;
  // Threads over repetitions; 0 = all cores (OpenMP's default: OMP_NUM_THREADS if set, else
  // every hardware thread). Never more than the repetitions.
  int threads = 0;

  DerivedParameters derived() const { return derive(material, geometry, k_int_scale); }
  // Loading time t0 for this scene's contact fraction (see RunControl).
  double t0_s() const;
  double duration() const;  // seconds
};

// Throws InputError naming the field, the value and the allowed range.
void validate(const Scene& s);

// Build the chain of repetition `rep`: contact mask (random surfaces draw theirs from the
// repetition's stream), micro coefficients drawn from the repetition's Gaussian stream.
Chain build_chain(const Scene& s, int rep);

// Seed of repetition `rep` from the scene seed: a SplitMix64 hash, so streams of different
// repetitions are independent and do not depend on which thread runs them.
std::uint64_t rep_seed(std::uint64_t seed, int rep);

void to_json(nlohmann::json& j, const Scene& s);
// Overlay the keys present in `j` onto `s` (scene files). Unknown keys are an InputError.
void apply_scene_json(Scene& s, const nlohmann::json& j);

}  // namespace sb
