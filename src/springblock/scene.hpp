#pragma once
// A scene is one configured simulation: physics, surface, run control and the observables
// wanted. It is built from options or a scene file and validated once; everything downstream
// trusts it.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "springblock/materials.hpp"
#include "springblock/model.hpp"
#include "springblock/parameters.hpp"
#include "springblock/run_control.hpp"
#include "springblock/surface.hpp"

namespace sb {

struct Observables {
  bool series = false;                 // keep mu(t), n_sliding(t) of repetition 0
  std::vector<double> stress_times_s;  // per-block stress snapshots of repetition 0
  bool timed_work = false;             // time each kind of work of every repetition (work_profile.hpp)
  bool slip_events = false;            // every repetition's slip events and their sizes (observe/slip_events.hpp)
};

struct Scene {
  MaterialParameters material;
  ChainGeometry geometry;
  FrictionDistribution friction;
  double k_int_scale = 1.0;  // multiplies K_int; 0 decouples the blocks
  PatternSpec pattern;
  BlockMaterials materials;  // per-block fields (materials.hpp); none by default
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

// Build the chain of repetition `rep` of a validated scene (its surface is not checked again):
// contact mask (random surfaces draw theirs from the repetition's stream), micro coefficients
// drawn from the repetition's Gaussian stream.
Chain build_chain(const Scene& s, int rep);

// Seed of repetition `rep` from the scene seed: a SplitMix64 hash, so streams of different
// repetitions are independent and do not depend on which thread runs them.
std::uint64_t rep_seed(std::uint64_t seed, int rep);

// Scenes as JSON (scene_json.cpp, the one place a scene is written). to_json gives the scene
// every results file and series header carries, with its derived parameters, t0 and duration.
void to_json(nlohmann::json& j, const Scene& s);
// The entries of the results schema that repeat a scene's (reps, seed, method, dt, tol,
// modal_max_run, modal_max_groove, stepper, exact_max_run, duration), taken from its JSON `scene`
// under the schema's names.
nlohmann::json schema_entries(const nlohmann::json& scene);
// A mask surface as results record it beside the pattern's text (to_json's "pattern_mask"): its
// source, blocks, contacts, FNV-1a hash, and for a file its path (and its digits when short).
nlohmann::json mask_record(const PatternSpec& p);
// Overlay the keys present in `j` onto `s` (scene files). Unknown keys are an InputError.
void apply_scene_json(Scene& s, const nlohmann::json& j);

}  // namespace sb
