#include "springblock/sweep/results.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "springblock/ensemble.hpp"

namespace sb::sweep {

nlohmann::json record_numbers(const nlohmann::json& record) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& o : observables()) out.push_back(record.at(o.name));
  out.push_back(record.at("wall_s"));
  out.push_back(record.at("contact_fraction"));
  return out;
}

void take_numbers(SceneNumbers& numbers, int rep, const nlohmann::json& record_numbers) {
  const auto& obs = observables();
  if (numbers.values.empty()) numbers.values.resize(obs.size());
  for (std::size_t o = 0; o < obs.size(); ++o) {
    auto& v = numbers.values[o];
    if (static_cast<int>(v.size()) <= rep) v.resize(rep + 1, std::nan(""));
    const auto& x = record_numbers.at(o);
    v[rep] = x.is_null() ? std::nan("") : x.get<double>();
  }
  if (static_cast<int>(numbers.wall_s.size()) <= rep) numbers.wall_s.resize(rep + 1, 0.0);
  numbers.wall_s[rep] = record_numbers.at(obs.size()).get<double>();
  if (rep == 0) numbers.contact_fraction = record_numbers.at(obs.size() + 1);
}

nlohmann::json scene_statistics(const std::vector<SweepScene>& scenes, int k, const SceneNumbers& numbers) {
  const nlohmann::json scene_json = scenes[k].scene;
  nlohmann::json line = {{"scene", k}, {"varied", scenes[k].varied}};
  const auto& obs = observables();
  for (std::size_t o = 0; o < obs.size(); ++o) line[obs[o].name] = summarize(numbers.values.at(o));
  line.update(schema_entries(scene_json));
  line["contact_fraction"] = numbers.contact_fraction;
  double wall_s = 0;
  for (double w : numbers.wall_s) wall_s += w;
  line["wall_s"] = wall_s;
  line["scene_json"] = scene_json;
  return line;
}

void write_scene_line(std::ostream& out, const nlohmann::json& statistics, int reps,
                      const std::function<std::string(int rep)>& record) {
  // The runs' place in the line's text (keys sorted, as nlohmann::json dumps them) is found by a
  // stand-in value no scene field can hold: a lone control character.
  nlohmann::json line = statistics;
  line["runs"] = "\x01";
  const std::string text = line.dump();
  const std::string mark = R"("runs":"\u0001")";
  const auto at = text.find(mark);
  if (at == std::string::npos || text.find(mark, at + 1) != std::string::npos)
    throw std::logic_error("scene line: the runs' place is not unique");
  out.write(text.data(), static_cast<std::streamsize>(at));
  out << "\"runs\":[";
  for (int r = 0; r < reps; ++r) out << (r ? "," : "") << record(r);
  out << ']';
  out.write(text.data() + at + mark.size(), static_cast<std::streamsize>(text.size() - at - mark.size()));
  out << '\n';
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

std::string summary_heading() {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%5s  %-44s  %-18s  %-18s  %4s  %8s\n", "scene", "varied", "mu_s +- sem",
                "mu_d +- sem", "n", "wall_s");
  return buf;
}

std::string summary_row(const nlohmann::json& l) {
  std::string varied;
  for (auto& [k, v] : l.at("varied").items()) varied += (varied.empty() ? "" : " ") + k + "=" + value_text(v);
  if (varied.empty()) varied = "(base)";
  char buf[512];
  std::snprintf(buf, sizeof buf, "%5d  %-44s  %-18s  %-18s  %4d  %8.2f\n", l.at("scene").get<int>(), varied.c_str(),
                statistic_text(l.at("mu_s")).c_str(), statistic_text(l.at("mu_d")).c_str(),
                l.at("mu_s").at("n").get<int>(), l.at("wall_s").get<double>());
  return buf;
}

}  // namespace sb::sweep
