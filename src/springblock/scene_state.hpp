#pragma once
// A scene's complete state, every field as it is held, for a copy of the scene in another
// process (Python's pickle). Unlike the results JSON (to_json: what a reader needs, in SI units,
// with derived numbers, a mask file named by its path), this reads back to a scene equal field
// for field, so it runs bit-identically. The mask travels as its blocks, the materials as their
// columns and segments: nothing is read from a file again.
#include <nlohmann/json_fwd.hpp>

#include "springblock/scene.hpp"

namespace sb {

nlohmann::json scene_state(const Scene& s);
// Throws InputError("state") when `j` is not a state scene_state wrote.
Scene scene_from_state(const nlohmann::json& j);

}  // namespace sb
