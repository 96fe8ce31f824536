/* NARRATIVE
Claim: None in the paper. The paper does not say how it reads mu_s and mu_d off a trace, how
long it runs, or how converged its step is; this target measures how much those open choices
move our numbers, so a disagreement with a published value can be told apart from a choice.
Scene: three representative surfaces with default parameters: smooth N = 360, L_x = 7.2 cm
(pat0_r01); periodic:10,10 at the same size (pat0_r06); hierarchical:24,8,1 at N = 120,
L_x = 2.4 cm (pat1_r08). Smoke tier: the smooth scene only. For each surface, variants of one
choice at a time around the baseline (mu_s rule slid_or_drop 0.1, samples every 1e-3 ms,
mu_d_skip 0.25 t0, duration 4 t0, the method's default accuracy): the mu_s rule all_slipped,
slid_or_drop at 0.05 and 0.2, and the pure drop rule at 0.05 (no all-slid bound); samples every
1e-2 ms; mu_d_skip 0 and 0.5 t0; duration 3 t0 and 6 t0; and the integrator accuracy tightened (rk4: dt 5e-8 s instead of 1e-7 s; event: tol 1e-10,
two decades below the default 1e-8). Every variant of a surface uses the seed its table row has
in its table, so the repetitions see the same micro coefficients and the differences to the
baseline are paired, free of draw-to-draw noise; the baseline is then the row itself, and
tab_pat0 and tab_pat1 read those rows from here rather than simulate them again.
Checked: the document lists, per surface and choice, the shift of mu_s and mu_d from the
baseline; the report quotes them next to the z values.
Cost: the rule and run-length variants of a surface see one trajectory, so sb::run_ensembles
simulates it once (to 6 t0) and reads every variant off it (trajectory_from in the JSON); the
numbers are bit-identical to separate runs (tests/unit/test_shared_trajectory.cpp). Only the
accuracy and sample-spacing variants are simulations of their own.
*/
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "sensitivity", "how extraction rules, run length and step move mu_s and mu_d",
      [](const repro::Context& ctx) {
        struct Surface { const char* id; int N; const char* length; const char* pattern; const char* row; };
        std::vector<Surface> surfaces = {{"smooth", 360, "7.2cm", "smooth", "pat0_r01"},
                                         {"periodic_10_10", 360, "7.2cm", "periodic:10,10", "pat0_r06"},
                                         {"hier_24_8_1", 120, "2.4cm", "hierarchical:24,8,1", "pat1_r08"}};
        if (ctx.tier.reduced) surfaces.resize(1);
        struct Variant { const char* choice; const char* key; std::string value; };
        const bool rk4 = ctx.method == sb::Method::RK4;
        const std::vector<Variant> variants = {
            {"baseline", "", ""},
            // The loading-phase rule for mu_s: the default (a drop of 0.1 or every contact block
            // slid, whichever first) against its second half alone, other drops, and a drop
            // without the all-slid bound; and the sample spacing used before the default's.
            {"peak_rule", "peak_rule", "all_slipped"}, {"peak_rule", "peak_rule", "slid_or_drop:0.05"},
            {"peak_rule", "peak_rule", "slid_or_drop:0.2"}, {"peak_rule", "peak_rule", "drop:0.05"},
            {"sample_dt", "sample_dt", "1e-2ms"},
            {"mu_d_skip", "mu_d_skip", "0"}, {"mu_d_skip", "mu_d_skip", "0.5"},
            {"duration", "duration", "3t0"}, {"duration", "duration", "6t0"},
            {"accuracy", rk4 ? "dt" : "tol", rk4 ? "5e-8s" : "1e-10"}};
        std::vector<repro::LabelledScene> out;
        for (const auto& s : surfaces)
          for (const auto& v : variants) {
            repro::LabelledScene ls;
            ls.scene = ctx.chain(s.N, s.length, s.pattern);
            // Every variant of a surface with the draws of its table row (the seed the row has
            // in its table): the variants stay paired, and the table reads its row from here.
            ls.scene.seed = repro::scene_seed(ctx.opt.seed, s.row);
            ls.shared_seed = true;
            // The baseline is the paper-length run whatever the tier, so the duration
            // variants bracket it.
            repro::set(ls.scene, "duration", "4t0");
            if (*v.key) {
              // "rule:X" selects the rule with threshold X.
              const auto colon = v.value.find(':');
              repro::set(ls.scene, v.key, v.value.substr(0, colon));
              if (colon != std::string::npos) repro::set(ls.scene, "peak_drop", v.value.substr(colon + 1));
            }
            ls.id = *v.key ? fmt::format("{}__{}={}", s.id, v.key, v.value) : fmt::format("{}__baseline", s.id);
            ls.label = fmt::format("{} ({}), {}", s.pattern, s.row, *v.key ? fmt::format("{} = {}", v.key, v.value) : "baseline");
            ls.x = {{"surface", s.id}, {"row", s.row}, {"choice", v.choice}, {"key", v.key}, {"value", v.value}};
            out.push_back(ls);
          }
        return out;
      },
      [](const repro::Context&, nlohmann::json& doc) {
        nlohmann::json shifts = nlohmann::json::array();
        for (const auto& base : doc["scenes"]) {
          if (base["x"]["choice"] != "baseline") continue;
          for (const auto& v : doc["scenes"]) {
            if (v["x"]["surface"] != base["x"]["surface"] || v["x"]["choice"] == "baseline") continue;
            auto diff = [&](const char* c) -> nlohmann::json {
              const auto& a = v["result"][c]["mean"];
              const auto& b = base["result"][c]["mean"];
              if (a.is_null() || b.is_null()) return nullptr;
              return a.get<double>() - b.get<double>();
            };
            shifts.push_back({{"surface", v["x"]["surface"]}, {"choice", v["x"]["choice"]}, {"key", v["x"]["key"]},
                              {"value", v["x"]["value"]}, {"d_mu_s", diff("mu_s")}, {"d_mu_d", diff("mu_d")}});
          }
        }
        doc["shifts"] = shifts;
      });
}
