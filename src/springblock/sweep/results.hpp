#pragma once
// A sweep's results: one JSON line per scene (its statistics over its repetitions in repetition
// order, so the numbers do not depend on the order units finished in) after a header line; and
// the summary table printed on stdout. A scene's line is made from the few numbers per repetition
// its statistics need (SceneNumbers) and, in the complete file, its runs: the unit records,
// spliced in as text read back from the checkpoint one at a time, so no scene's records are ever
// held together in memory.
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "springblock/sweep/expand.hpp"

namespace sb::sweep {

// What a scene's statistics need from each repetition, indexed by repetition.
struct SceneNumbers {
  std::vector<std::vector<double>> values;  // [observable of observables()][rep]; NaN where null
  std::vector<double> wall_s;               // [rep]
  nlohmann::json contact_fraction;          // repetition 0's
};

// The numbers of a unit record that its scene's statistics need, as a short JSON array (every
// observable of observables(), null where undefined; wall_s; contact_fraction): what a worker
// sends beside the record's text, so the coordinator parses nine numbers, not the record.
nlohmann::json record_numbers(const nlohmann::json& record);
// Keeps repetition `rep`'s numbers (record_numbers).
void take_numbers(SceneNumbers& numbers, int rep, const nlohmann::json& record_numbers);

// Scene k's line without its runs: scene, varied, the statistics of every observable
// (mean/std/sem/n, null where undefined), reps, seed, method, dt, duration (the results schema's
// entries), contact fraction, wall_s (its units' wall time summed in repetition order) and the
// full scene.
nlohmann::json scene_statistics(const std::vector<SweepScene>& scenes, int k, const SceneNumbers& numbers);

// Writes scene k's complete line and its '\n' to `out`: `statistics` (scene_statistics) with
// "runs", the records of its `reps` repetitions in repetition order (record(r) returns one as
// the checkpoint holds it), fetched and written one at a time. The text is what dumping the line
// with the records parsed into it would give.
void write_scene_line(std::ostream& out, const nlohmann::json& statistics, int reps,
                      const std::function<std::string(int rep)>& record);

// The summary table: a heading, then one row per scene (what varies, mu_s and mu_d with their
// standard errors, n, wall time) from its line (with or without runs).
std::string summary_heading();
std::string summary_row(const nlohmann::json& scene_line);

}  // namespace sb::sweep
