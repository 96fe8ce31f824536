/* NARRATIVE
Claim: A two-level surface has a lower static coefficient than the single-level surface with
the same contact fraction and the same largest groove: nesting grooves puts more contact
points next to a groove edge, where the longitudinal stress concentrates.
Scene: no new simulation. Pairs are formed at run time from the simulated tables: every
multi-level row of tab_pat2 (N = 360, L_x = 7.2 cm) is paired with each tab_pat0 row whose
groove n_g equals the first-level groove and whose printed contact fraction is the same. With
the published tables this yields (6,1) vs (2,6) and (30,1), (30,2) vs (10,30), all at S = 1/4.
Checked: claim C29 on our values for every pair (and the pair list is the one above).
*/
#include <cmath>

#include <nlohmann/json.hpp>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig_p3", "two-level vs one-level at equal contact fraction and first level (reads tab_pat0/2.json)",
      [](const repro::Context&) { return std::vector<repro::LabelledScene>{}; },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        const auto multi = repro::input_document(ctx, "tab_pat2");
        const auto single = repro::input_document(ctx, "tab_pat0");
        nlohmann::json pairs = nlohmann::json::array(), scenes = nlohmann::json::array();
        std::vector<std::string> kept;
        auto keep = [&](const nlohmann::json& rec) {
          const auto id = rec["id"].get<std::string>();
          for (auto& k : kept) if (k == id) return;
          kept.push_back(id);
          scenes.push_back(rec);
        };
        for (const auto& h : multi.at("scenes")) {
          const auto hs = repro::pattern_shape(h["x"]["pattern"].get<std::string>());
          if (hs.grooves.size() < 2) continue;
          for (const auto& s : single.at("scenes")) {
            const auto ss = repro::pattern_shape(s["x"]["pattern"].get<std::string>());
            if (ss.n_p == 0 || ss.grooves.at(0) != hs.grooves.at(0)) continue;
            if (std::abs(s["x"]["S_printed"].get<double>() - h["x"]["S_printed"].get<double>()) > 1e-9) continue;
            pairs.push_back({{"hierarchical", h["id"]}, {"single", s["id"]}, {"first_level", hs.grooves.at(0)},
                             {"S_printed", h["x"]["S_printed_text"]}});
            keep(h), keep(s);
          }
        }
        doc["scenes"] = scenes;
        doc["pairs"] = pairs;
        doc["source"] = {{"targets", {"tab_pat0", "tab_pat2"}}, {"tier", multi.value("tier", "")}};
      });
}
