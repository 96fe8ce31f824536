/* NARRATIVE
Claim: Keeping the first-level (largest) groove fixed and adding finer levels raises the
static coefficient over the single-level parent; the dynamic coefficient rises slightly as
contact shrinks (N = 120, L_x = 2.4 cm).
Scene: no new simulation. The tpat1 rows simulated by the tab_pat1 target are grouped by their
first-level groove size (8, 24, 40 blocks), parent first, children in table order, each with
its contact mask for the groove-profile sketch.
Checked: every tab_pat1 row appears in exactly one group whose parent is the single-level
pattern; claims C25, C28 and C31 judge the values.
*/
#include <map>

#include <nlohmann/json.hpp>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig_p2", "tpat1 grouped by first-level groove (reads tab_pat1.json)",
      [](const repro::Context&) { return std::vector<repro::LabelledScene>{}; },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        const auto src = repro::input_document(ctx, "tab_pat1");
        std::map<int, nlohmann::json> groups;
        nlohmann::json scenes = nlohmann::json::array();
        for (auto rec : src.at("scenes")) {
          const auto shape = repro::pattern_shape(rec.at("x").at("pattern").get<std::string>());
          rec["x"]["first_level"] = shape.grooves.at(0);
          rec["x"]["levels"] = shape.grooves;
          auto& g = groups[shape.grooves.at(0)];
          if (g.is_null()) g = {{"first_level", shape.grooves.at(0)}, {"parent", nullptr}, {"ids", nlohmann::json::array()}};
          if (shape.grooves.size() == 1) g["parent"] = rec["id"];
          g["ids"].push_back(rec["id"]);
          scenes.push_back(rec);
        }
        nlohmann::json list = nlohmann::json::array();
        for (auto& [level, g] : groups) list.push_back(g);
        doc["scenes"] = scenes;
        doc["groups"] = list;
        doc["source"] = {{"target", "tab_pat1"}, {"tier", src.value("tier", "")}, {"method", src.value("method", "")}};
      });
}
