#include "springblock/sweep/expand.hpp"

#include <map>

#include "springblock/errors.hpp"
#include "springblock/fnv1a.hpp"

namespace sb::sweep {
namespace {

// Applies one entry through the scene-file table, with the line added to any complaint.
void apply(Scene& s, const std::string& key, const nlohmann::json& value, int line, const std::string& path,
           std::map<std::string, int>& line_of) {
  try {
    apply_scene_json(s, nlohmann::json{{key, value}});
  } catch (const InputError& e) {
    throw InputError(e.field, std::string(e.what()).substr(e.field.size() + 2) + " (" + where(path, line) + ")");
  }
  line_of[key] = line;
}

std::string label(const nlohmann::json& varied) {
  std::string out;
  for (auto& [k, v] : varied.items()) out += (out.empty() ? "" : ", ") + k + " = " + v.dump();
  return out.empty() ? "the base scene" : out;
}

SweepScene make_scene(const Spec& spec, const std::vector<Field>& listed, const std::vector<std::size_t>& pick) {
  SweepScene out{Scene{}, nlohmann::json::object()};
  std::map<std::string, int> line_of;
  for (const Field& f : spec.base) apply(out.scene, f.key, f.value, f.line, spec.path, line_of);
  for (const Field& f : listed) {
    apply(out.scene, f.key, f.value, f.line, spec.path, line_of);
    out.varied[f.key] = f.value;
  }
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const Axis& axis = spec.axes[a];
    apply(out.scene, axis.key, axis.values[pick[a]], axis.line, spec.path, line_of);
    out.varied[axis.key] = axis.values[pick[a]];
  }
  try {
    validate(out.scene);
  } catch (const InputError& e) {
    auto it = line_of.find(e.field);
    const std::string at = it != line_of.end() ? where(spec.path, it->second) : spec.path + ", default value";
    throw InputError(e.field, std::string(e.what()).substr(e.field.size() + 2) + " (" + at + "; scene " +
                                  label(out.varied) + ")");
  }
  return out;
}

}  // namespace

std::vector<SweepScene> expand(const Spec& spec) {
  const std::vector<std::vector<Field>> listed = spec.scenes.empty() ? std::vector<std::vector<Field>>{{}} : spec.scenes;
  std::size_t combinations = 1;
  for (const Axis& a : spec.axes) combinations *= a.values.size();
  if (listed.size() * combinations > 1000000)
    throw InputError("axes", "the sweep has " + std::to_string(listed.size() * combinations) +
                                 " scenes; at most 1000000 (" + spec.path + ")");
  std::vector<SweepScene> out;
  for (const auto& scene : listed) {
    std::vector<std::size_t> pick(spec.axes.size(), 0);
    for (std::size_t c = 0; c < combinations; ++c) {
      // The last axis varies fastest: an odometer over the axes' indices.
      std::size_t rest = c;
      for (std::size_t a = spec.axes.size(); a-- > 0;) {
        pick[a] = rest % spec.axes[a].values.size();
        rest /= spec.axes[a].values.size();
      }
      out.push_back(make_scene(spec, scene, pick));
    }
  }
  return out;
}

std::string fingerprint(const std::vector<SweepScene>& scenes) {
  Fnv1a64 h;  // over the scenes' JSON
  for (const auto& s : scenes) h.add(nlohmann::json(s.scene).dump());
  return h.hex();
}

}  // namespace sb::sweep
