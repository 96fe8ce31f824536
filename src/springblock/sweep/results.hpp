#pragma once
// A sweep's results from its unit records: one JSON line per scene (its statistics over its
// repetitions in repetition order, so the numbers do not depend on the order units finished in),
// after a header line; and the summary table printed on stdout.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/sweep/expand.hpp"

namespace sb::sweep {

// Scene k's line: scene, varied, the statistics of every observable (mean/std/sem/n, null where
// undefined), reps, seed, method, dt, duration (the results schema's entries), contact fraction,
// wall_s (its units' wall time summed), the full scene and its runs (the unit records).
nlohmann::json scene_line(const std::vector<SweepScene>& scenes, int k, const std::map<int, nlohmann::json>& records,
                          int first_unit);

// The results file: `header` then one line per scene.
std::string results_jsonl(const std::vector<SweepScene>& scenes, const std::map<int, nlohmann::json>& records,
                          const nlohmann::json& header);

// One row per scene: what varies, mu_s and mu_d with their standard errors, n, wall time.
std::string summary_table(const std::vector<nlohmann::json>& scene_lines);

}  // namespace sb::sweep
