// The one place a scene is written: the JSON every results file and series header carries, and
// the entries the results schema repeats from it. Scene files are read back here too.
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/errors.hpp"
#include "springblock/materials_json.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/surface_mask.hpp"

namespace sb {
namespace {

// Masks up to this many blocks are recorded digit by digit even when read from a file; longer
// ones by their counts and hash, which tie a result to its surface as surely.
constexpr std::size_t kRecordedDigits = 10000;

}  // namespace

// A file's path says nothing of what the file held when the run was made; its blocks do.
nlohmann::json mask_record(const PatternSpec& p) {
  nlohmann::json j{{"source", p.mask_path.empty() ? "inline" : "file"},
                   {"blocks", p.mask.size()},
                   {"contacts", std::count(p.mask.begin(), p.mask.end(), std::uint8_t{1})},
                   {"fnv1a64", mask_hash(p.mask)}};
  if (!p.mask_path.empty()) {
    j["path"] = p.mask_path;
    if (p.mask.size() <= kRecordedDigits) j["mask"] = mask_digits(p.mask);
  }
  return j;
}

void to_json(nlohmann::json& j, const Scene& s) {
  j = nlohmann::json{{"material", s.material},
                     {"geometry", s.geometry},
                     {"friction", s.friction},
                     {"k_int_scale", s.k_int_scale},
                     {"pattern", s.pattern.text()},
                     {"layout", s.pattern.layout_text()},
                     {"materials", materials_json(s)},
                     {"derived", s.derived()},
                     {"method", method_name(s.run.method)},
                     {"dt_s", s.run.dt_s},
                     {"tol", s.run.tol},
                     {"modal_max_run", s.run.modal_max_run},
                     {"modal_max_groove", s.run.modal_max_groove},
                     {"stepper", stepper_name(s.run.stepper)},
                     {"exact_max_run", s.run.exact_max_run},
                     {"duration_s", s.duration()},
                     {"t0_s", s.t0_s()},
                     {"sample_dt_s", s.run.sample_dt_s},
                     {"stop_after_mu_s", s.run.stop_after_mu_s},
                     {"peak_rule", peak_rule_name(s.rules.peak_rule)},
                     {"peak_drop", s.rules.peak_drop},
                     {"peak_drop_fraction", s.rules.peak_drop_fraction},
                     {"peak_event_fraction", s.rules.peak_event_fraction},
                     {"mu_d_skip_t0", s.rules.mu_d_skip_t0},
                     {"reps", s.reps},
                     {"seed", s.seed}};
  if (s.pattern.kind == SurfaceKind::Mask) j["pattern_mask"] = mask_record(s.pattern);
  if (!s.observe.stress_times_s.empty()) j["stress_times_s"] = s.observe.stress_times_s;
}

nlohmann::json schema_entries(const nlohmann::json& scene) {
  // The results schema's own names for these (dt, duration) are older than the scene's.
  return {{"reps", scene.at("reps")},
          {"seed", scene.at("seed")},
          {"method", scene.at("method")},
          {"dt", scene.at("dt_s")},
          {"tol", scene.at("tol")},
          {"modal_max_run", scene.at("modal_max_run")},
          {"modal_max_groove", scene.at("modal_max_groove")},
          {"stepper", scene.at("stepper")},
          {"exact_max_run", scene.at("exact_max_run")},
          {"duration", scene.at("duration_s")}};
}

void apply_scene_json(Scene& s, const nlohmann::json& j) {
  if (!j.is_object()) throw InputError("scene", "a scene file must hold one JSON object");
  for (auto& [key, value] : j.items()) {
    if (apply_materials_json(s, key, value)) continue;
    std::string text;
    if (value.is_string()) text = value.get<std::string>();
    else if (value.is_number_integer()) text = std::to_string(value.get<long long>());
    else if (value.is_number()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", value.get<double>());
      text = buf;
    } else if (value.is_boolean()) text = value.get<bool>() ? "true" : "false";
    else throw InputError(key, "must be a string, number or boolean");
    set_scene_field(s, key, text);
  }
}

}  // namespace sb
