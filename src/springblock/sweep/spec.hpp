#pragma once
// A sweep file, as read: a base scene, an optional list of scenes overlaid on it, and axes whose
// values multiply every listed scene. Keys are scene-file keys (scene_fields.hpp), so a sweep can
// vary any field a scene file can set; every entry remembers its line in the file so that an
// error names the field and where it was written.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sb::sweep {

struct Field {
  std::string key;
  nlohmann::json value;  // string, number or boolean, as a scene file holds it
  int line = 0;          // 1-based line in the sweep file; 0 when unknown
};

struct Axis {
  std::string key;
  std::vector<nlohmann::json> values;  // a list, or a range already expanded (range.hpp)
  int line = 0;
};

struct Spec {
  std::string path;                       // for messages
  std::vector<Field> base;                // [base]: applied to every scene first
  std::vector<std::vector<Field>> scenes; // [[scenes]]: each overlaid on the base; none = the base alone
  std::vector<Axis> axes;                 // [axes]: the cartesian product, first axis slowest
};

// Reads FILE by its extension (.toml or .json). Throws InputError naming the field and its line:
// a malformed file, an unknown section, a value of the wrong type, an empty axis or bad range.
Spec read_spec(const std::string& path);
Spec parse_toml(const std::string& text, const std::string& path);
Spec parse_json(const std::string& text, const std::string& path);

// "FILE line L" (or just FILE when the line is unknown): how messages point into the file.
std::string where(const std::string& path, int line);

// The values of a range object {from, to, steps[, scale = "linear" | "log"]} (both ends
// included). Integer ends with a linear range that lands on integers give integers, so a range
// can vary N or reps. Throws InputError(key) with `line` for a malformed range.
std::vector<nlohmann::json> range_values(const std::string& key, const nlohmann::json& range,
                                         const std::string& path, int line);

}  // namespace sb::sweep
