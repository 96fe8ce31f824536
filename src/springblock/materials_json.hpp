#pragma once
// Per-block fields as scene files hold them and results files record them (materials_json.cpp).
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "springblock/materials.hpp"

namespace sb {

// A scene-file entry that belongs to the per-block fields: "segments" (a list of segments and
// ramps) or "segments.K.MEMBER" (one member of segment K, as a sweep axis names it). Returns false
// for any other key. Throws InputError("segments", ...) for a malformed entry.
bool apply_materials_json(Scene& s, const std::string& key, const nlohmann::json& value);

// What a results file records: the fields' source, the hash of their values, which fields are
// given, and the segments as written.
nlohmann::json materials_json(const Scene& s);

}  // namespace sb
