/* NARRATIVE
Claim: Over single-level patterns the static coefficient, drawn as a map over pawl size n_p and
groove size n_g, falls towards larger grooves at fixed contact fraction and rises where the
pawls are narrower than the grooves (small contact fraction).
Scene: no new simulation. The tpat0 rows simulated by the tab_pat0 target (N = 360,
L_x = 7.2 cm) are rearranged on the n_p x n_g grid; the smooth row is kept apart as the
reference. Each grid cell carries our mean, its standard error and the published value.
Checked: the grid holds every periodic row of tab_pat0 exactly once (the table checks and
claims C20-C22 judge the values themselves).
*/
#include <algorithm>
#include <set>

#include <nlohmann/json.hpp>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig4", "mu_s on the n_p x n_g grid of tpat0 (reads tab_pat0.json)",
      [](const repro::Context&) { return std::vector<repro::LabelledScene>{}; },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        const auto src = repro::input_document(ctx, "tab_pat0");
        std::set<int> nps, ngs;
        nlohmann::json scenes = nlohmann::json::array();
        for (auto rec : src.at("scenes")) {
          const auto shape = repro::pattern_shape(rec.at("x").at("pattern").get<std::string>());
          if (shape.n_p > 0) {
            nps.insert(shape.n_p), ngs.insert(shape.grooves.at(0));
            rec["x"]["n_p"] = shape.n_p, rec["x"]["n_g"] = shape.grooves.at(0);
          }
          scenes.push_back(rec);
        }
        std::vector<int> np(nps.begin(), nps.end()), ng(ngs.begin(), ngs.end());
        auto cell = [&](const char* coef, const char* field) {
          nlohmann::json m = nlohmann::json::array();
          for (int p : np) {
            nlohmann::json row = nlohmann::json::array();
            for (int g : ng) {
              nlohmann::json v = nullptr;
              for (const auto& rec : scenes)
                if (rec["x"].value("n_p", 0) == p && rec["x"].value("n_g", 0) == g) {
                  v = std::string(field) == "published" ? rec["x"]["published"][coef] : rec["result"][coef][field];
                }
              row.push_back(v);
            }
            m.push_back(row);
          }
          return m;
        };
        doc["scenes"] = scenes;
        doc["source"] = {{"target", "tab_pat0"}, {"tier", src.value("tier", "")}, {"method", src.value("method", "")}};
        doc["grid"] = {{"n_p", np}, {"n_g", ng},
                       {"mu_s", cell("mu_s", "mean")}, {"mu_s_sem", cell("mu_s", "sem")},
                       {"mu_s_published", cell("mu_s", "published")},
                       {"mu_d", cell("mu_d", "mean")}, {"mu_d_sem", cell("mu_d", "sem")},
                       {"mu_d_published", cell("mu_d", "published")}};
      });
}
