#include "springblock/sweep/results.hpp"

#include <cmath>
#include <cstdio>

#include "springblock/ensemble.hpp"

namespace sb::sweep {

nlohmann::json scene_line(const std::vector<SweepScene>& scenes, int k, const std::map<int, nlohmann::json>& records,
                          int first_unit) {
  const Scene& scene = scenes[k].scene;
  nlohmann::json runs = nlohmann::json::array();
  double wall_s = 0;
  for (int r = 0; r < scene.reps; ++r) {
    const auto& rec = records.at(first_unit + r);
    wall_s += rec.at("wall_s").get<double>();
    runs.push_back(rec);
  }
  const nlohmann::json scene_json = scene;
  nlohmann::json line = {{"scene", k}, {"varied", scenes[k].varied}};
  for (const auto& o : observables()) {
    std::vector<double> values;
    for (const auto& rec : runs) values.push_back(rec.at(o.name).is_null() ? std::nan("") : rec.at(o.name).get<double>());
    line[o.name] = summarize(values);
  }
  line.update(schema_entries(scene_json));
  line["contact_fraction"] = runs.empty() ? nlohmann::json(nullptr) : runs[0].at("contact_fraction");
  line["wall_s"] = wall_s;
  line["scene_json"] = scene_json;
  line["runs"] = runs;
  return line;
}

std::string results_jsonl(const std::vector<SweepScene>& scenes, const std::map<int, nlohmann::json>& records,
                          const nlohmann::json& header) {
  std::string out = header.dump() + "\n";
  int first = 0;
  for (int k = 0; k < static_cast<int>(scenes.size()); ++k) {
    out += scene_line(scenes, k, records, first).dump() + "\n";
    first += scenes[k].scene.reps;
  }
  return out;
}

namespace {

// A varied value as a person reads it: 1e+06 rather than 1000000.0, and a long string (an inline
// mask has a character per block) cut to its start and length, so a row keeps its columns (the
// JSON keeps every digit and character).
std::string value_text(const nlohmann::json& v) {
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    return s.size() <= 60 ? s : s.substr(0, 40) + "... (" + std::to_string(s.size()) + " characters)";
  }
  if (!v.is_number_float()) return v.dump();
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
  return buf;
}

std::string statistic_text(const nlohmann::json& st) {
  if (st.at("mean").is_null()) return "not measured";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f +- %.4f", st.at("mean").get<double>(),
                st.at("sem").is_null() ? 0.0 : st.at("sem").get<double>());
  return buf;
}

}  // namespace

std::string summary_table(const std::vector<nlohmann::json>& lines) {
  std::string out;
  char buf[512];
  std::snprintf(buf, sizeof buf, "%5s  %-44s  %-18s  %-18s  %4s  %8s\n", "scene", "varied", "mu_s +- sem",
                "mu_d +- sem", "n", "wall_s");
  out += buf;
  for (const auto& l : lines) {
    std::string varied;
    for (auto& [k, v] : l.at("varied").items()) varied += (varied.empty() ? "" : " ") + k + "=" + value_text(v);
    if (varied.empty()) varied = "(base)";
    std::snprintf(buf, sizeof buf, "%5d  %-44s  %-18s  %-18s  %4d  %8.2f\n", l.at("scene").get<int>(),
                  varied.c_str(), statistic_text(l.at("mu_s")).c_str(), statistic_text(l.at("mu_d")).c_str(),
                  l.at("mu_s").at("n").get<int>(), l.at("wall_s").get<double>());
    out += buf;
  }
  return out;
}

}  // namespace sb::sweep
