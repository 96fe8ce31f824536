#pragma once
// One table of every user-settable scene field. The command line and scene files both go
// through it, so a field is parsed, unit-converted and documented in exactly one place.
#include <string>
#include <vector>

#include "springblock/scene.hpp"

namespace sb {

struct SceneField {
  std::string key;      // scene-file key; the CLI option is "--" + key with '_' -> '-'
  std::string help;     // one line, with the default and the accepted units
  std::string example;  // e.g. "7.2cm"
};

const std::vector<SceneField>& scene_fields();

// Parse `value` for field `key` and store it in `s`. Throws InputError(key, ...) for an unknown
// key, a malformed value or wrong units. Range checks happen later, in validate().
void set_scene_field(Scene& s, const std::string& key, const std::string& value);

}  // namespace sb
