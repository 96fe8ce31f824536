#pragma once
// Shared support of the reproduction drivers. Each driver (one per figure or table) only
// decides WHICH scenes to simulate and what their plot coordinates are; this module owns the
// command line, the tiers, running the scenes with progress, and the one JSON file per target.
//
// Output contract (<out>/<target>.json), relied on by the checker and the figure scripts:
//   {target, tier, method, method_requested, reps, provenance, wall_seconds,
//    scenes: [{id, label, x: {...}, result: <ensemble_json without runs' provenance>,
//              series?: {t_s, mu, mu_signed, n_sliding, stride},
//              stress?: [{t_s, sigma_over_P, f_over_Fn}], contact_mask?: "0101...",
//              trajectory_from?: id of the scene whose simulation this one was read off}],
//    ...target-specific blocks (theory, critical, pairs, groups)}
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "springblock/scene.hpp"

namespace repro {

// A tier trades statistics for time. `paper` matches the paper's ~20 repetitions; `quick` keeps
// the same run length with fewer repetitions (the checker's Student-t tolerance accounts for
// that); `smoke` exists only to test the pipeline end to end and its numbers mean little.
struct Tier {
  std::string name;
  int reps;
  double duration_t0;  // run length in loading times t0 (see sb::RunControl)
  bool reduced;        // drivers may thin their parameter sweeps
};
const std::vector<Tier>& tiers();           // paper, quick, smoke
Tier tier_named(const std::string& name);  // throws sb::InputError("tier")

struct Options {
  std::string target;
  std::string tier = "paper";
  std::string out = ".";
  std::string method = "event";  // its name (normalised by make_context); the document also
                                 // writes it as method_requested, kept for the output contract
                                 // now that no method falls back to another
  int threads = 0;
  std::uint64_t seed = 1;
  std::string table;                // published_tab_pat*.tsv (table drivers)
  std::vector<std::string> inputs;  // other targets' JSON (derived figures)
  std::string only;                 // comma-separated scene ids to keep (debugging a subset)
  std::string layout;               // pattern layout for every scene (empty: the library's default)
  std::string command_line;
};

// What a driver hands back: scenes with stable ids, a human label and plot coordinates.
struct LabelledScene {
  std::string id, label;
  nlohmann::json x = nlohmann::json::object();
  sb::Scene scene;
  // By default every scene gets its own seed, derived from --seed and its id, so different
  // scenes are statistically independent (as separate runs in the paper are). A driver that
  // compares variants of one scene sets this to keep --seed for all of them: the variants then
  // see the same micro coefficients and their differences are paired.
  bool shared_seed = false;
  // The per-repetition records in the document (result.runs). A study that only needs each
  // scene's statistics drops them to keep its committed document small.
  bool keep_runs = true;
  // The scene's full echo (result.scene) and contact mask. A study of many variants of scenes
  // whose every field but those in x is the default drops them; x and the document's header
  // then record its parameters.
  bool keep_scene_echo = true;
  // Borrowed scenes are not simulated here: their result is another target's record (given with
  // --input) of the same simulation, found with find_borrowable(). With trace set, repetition 0
  // is simulated once more with the source's seed to keep its mu(t) series, and must give the
  // source's repetition-0 numbers to the last bit (the proof that it is the same trajectory).
  struct Borrow {
    std::string target, id;  // empty target: simulate
    bool trace = false;
  } borrow = {};
};

class Context {
 public:
  Context(Options o, Tier t, sb::Method m) : opt(std::move(o)), tier(std::move(t)), method(m) {}
  // Defaults of the paper plus this run's method, tier repetitions and length, seed, threads.
  sb::Scene base_scene() const;
  // base_scene() with N blocks over `length` (e.g. "7.2cm") and a surface pattern.
  sb::Scene chain(int N, const std::string& length, const std::string& pattern = "smooth") const;
  const Options opt;
  const Tier tier;
  const sb::Method method;  // --method
};

// The seed a scene with this id gets from --seed (a driver that pairs its scenes with another
// target's uses the other scene's id).
std::uint64_t scene_seed(std::uint64_t seed, const std::string& id);

// Set scene fields through the library's field table, so units and checks stay in one place.
void set(sb::Scene& s, const std::string& key, const std::string& value);

// One row of a published_tab_pat*.tsv, columns by header name.
struct TableRow {
  std::string row_id, pattern;
  int N = 0;
  double L_x_cm = 0, S_num = 0, S_den = 1, mu_s = 0, mu_s_err = 0, mu_d = 0, mu_d_err = 0;
};
std::vector<TableRow> read_table(const std::string& path);  // throws std::runtime_error

nlohmann::json read_json(const std::string& path);  // throws std::runtime_error

// The document of another target given with --input (matched by its "target" key).
// The document stays cached for the life of the process: hold the reference, not a temporary's part.
const nlohmann::json& input_document(const Context& ctx, const std::string& target);  // throws InputError

// Those of `targets` whose document was given with --input (for a driver that reads another
// target's records where they are at hand and simulates the same thing itself otherwise).
std::vector<std::string> given_inputs(const Context& ctx, const std::vector<std::string>& targets);

// The record of another --input target that simulated the same thing as `scene`: every field of
// the scene definition equal except the seed (ours derives from our own scene id), and the same
// contact mask (so periodic:6,6 and hierarchical:6 match when they lay out the same surface).
// Returns {target, id}, or an empty target when none of the listed targets has one.
LabelledScene::Borrow find_borrowable(const Context& ctx, const std::vector<std::string>& targets,
                                      const sb::Scene& scene);
// The same, but only a record whose seed is `seed` as well: the very simulation the caller would
// run itself (same definition, same draws), so borrowing it changes none of its numbers.
LabelledScene::Borrow find_borrowable(const Context& ctx, const std::vector<std::string>& targets,
                                      const sb::Scene& scene, std::uint64_t seed);

// Groove sizes of a pattern spec: periodic:NP,NG -> {NG} (and n_p), hierarchical:G1,G2 -> {G1,G2}.
struct PatternShape {
  int n_p = 0;
  std::vector<int> grooves;
};
PatternShape pattern_shape(const std::string& spec);

using PlanFn = std::function<std::vector<LabelledScene>(const Context&)>;
// Called after the scenes ran, to add target-specific blocks to the document.
using FinishFn = std::function<void(const Context&, nlohmann::json& doc)>;

// The whole driver: parse options (exit 2 on bad ones), plan, run with progress and ETA,
// write <out>/<target>.json atomically. Returns the process exit code.
int run_target(int argc, char** argv, const std::string& target, const std::string& summary,
               const PlanFn& plan, const FinishFn& finish = {});

}  // namespace repro
