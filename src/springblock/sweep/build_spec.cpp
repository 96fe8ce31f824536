// The sections of a sweep file, checked: scene entries hold scalars (or the list of segments), axes hold non-empty lists
// of scalars or a range, and nothing else is at the top level. Whether a value suits its field
// is the scene's business (expand.cpp applies it through the scene-file table).
#include "springblock/errors.hpp"
#include "springblock/sweep/tree.hpp"

namespace sb::sweep {
namespace {

bool scalar(const nlohmann::ordered_json& v) { return v.is_string() || v.is_number() || v.is_boolean(); }

nlohmann::json plain(const nlohmann::ordered_json& v) { return nlohmann::json::parse(v.dump()); }

std::vector<Field> scene_entries(const Tree& t, const nlohmann::ordered_json& obj, const std::string& pointer,
                                 const std::string& path) {
  if (!obj.is_object())
    throw InputError(pointer.substr(1), "must be a table of scene fields (" + where(path, t.line(pointer)) + ")");
  std::vector<Field> out;
  for (auto& [key, value] : obj.items()) {
    const int line = t.line(pointer + "/" + key);
    // The one list a scene holds: its per-block segments and ramps (materials_json.hpp).
    if (!scalar(value) && !(key == "segments" && value.is_array()))
      throw InputError(key, "must be a string, number or boolean (" + where(path, line) +
                                "); lists and ranges belong in [axes]");
    out.push_back({key, plain(value), line});
  }
  return out;
}

Axis axis(const Tree& t, const std::string& key, const nlohmann::ordered_json& value, const std::string& path) {
  const int line = t.line("/axes/" + key);
  Axis a{key, {}, line};
  if (value.is_object()) {
    a.values = range_values(key, plain(value), path, line);
  } else if (value.is_array()) {
    for (auto& v : value) {
      if (!scalar(v)) throw InputError(key, "axis values must be strings, numbers or booleans (" + where(path, line) + ")");
      a.values.push_back(plain(v));
    }
  } else {
    throw InputError(key, "an axis must be a list of values or a range {from, to, steps} (" + where(path, line) + ")");
  }
  if (a.values.empty()) throw InputError(key, "an axis needs at least one value (" + where(path, line) + ")");
  return a;
}

}  // namespace

Spec build_spec(const Tree& t, const std::string& path) {
  Spec s;
  s.path = path;
  if (!t.root.is_object()) throw InputError("sweep", "'" + path + "' must hold one table/object");
  // Nothing in it is a slip of the pen more often than a request for the default scene.
  if (t.root.empty())
    throw InputError("sweep", "'" + path + "' holds no base, scenes or axes; give at least one (an empty [base] "
                              "runs the default scene)");
  for (auto& [section, value] : t.root.items()) {
    const std::string p = "/" + section;
    if (section == "base") {
      s.base = scene_entries(t, value, p, path);
    } else if (section == "scenes") {
      if (!value.is_array()) throw InputError("scenes", "must be a list of tables (" + where(path, t.line(p)) + ")");
      for (std::size_t i = 0; i < value.size(); ++i)
        s.scenes.push_back(scene_entries(t, value[i], p + "/" + std::to_string(i), path));
    } else if (section == "axes") {
      if (!value.is_object()) throw InputError("axes", "must be a table (" + where(path, t.line(p)) + ")");
      for (auto& [key, v] : value.items()) s.axes.push_back(axis(t, key, v, path));
    } else {
      throw InputError(section, "unknown section (" + where(path, t.line(p)) +
                                    "); a sweep file has base, scenes and axes");
    }
  }
  return s;
}

}  // namespace sb::sweep
