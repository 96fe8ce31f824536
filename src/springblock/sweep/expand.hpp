#pragma once
// The scenes of a sweep: every listed scene (or the base alone) times every combination of the
// axes, each a validated Scene. Expanded the same way on every rank, so a scene's index names
// the same scene everywhere.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/scene.hpp"
#include "springblock/sweep/spec.hpp"

namespace sb::sweep {

struct SweepScene {
  Scene scene;
  nlohmann::json varied;  // the entries of its [[scenes]] table and its axis values, by key
};

// Throws InputError naming the field and the line of the sweep file that set it (for a range
// error found by validate(), the line of the value that set the named field), before anything
// is run. The scenes are ordered: listed scene slowest, then the axes in file order.
std::vector<SweepScene> expand(const Spec& spec);

// A digest of the expanded scenes (their full JSON): a checkpoint written for other scenes is
// refused on resume.
std::string fingerprint(const std::vector<SweepScene>& scenes);

}  // namespace sb::sweep
