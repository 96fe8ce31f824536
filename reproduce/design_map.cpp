/* NARRATIVE
Claim: none of the paper's: a design map (issue 17). The paper's single-level surfaces
(table tpat0) sample a few points of the (n_p, n_g) plane; this target fills a grid of it for
the paper's chain, so a user sees where each value of mu_s and mu_d lives before asking
`springblock design` for one. Expected from Sec. III: mu_s falls with larger grooves at fixed
contact fraction and rises as the contact fraction n_p/(n_p+n_g) falls; mu_d rises only when the
contact fraction is strongly reduced.
Scene: N = 360, L_x = 7.2 cm, default parameters; periodic:n_p,n_g for n_p, n_g in
{1, 2, 3, 4, 6, 10, 20, 60} (smoke tier: {1, 3, 10, 60}), full runs of the tier's length.
Cost: 64 scenes x 3 repetitions (smoke: 16 x 2), whatever the tier: the map is an overview, its
standard errors are recorded with it, and `make reproduce-all` must stay short. The design
command's fresh verification, not this map, is what a chosen surface is judged on.
Checked: nothing against the paper (no published map); figures/design_map.py draws it.
*/
#include <algorithm>
#include <fmt/format.h>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(argc, argv, "design_map", "design map: mu_s, mu_d over periodic (n_p, n_g), N=360",
                           [](const repro::Context& ctx) {
                             std::vector<int> sizes = {1, 2, 3, 4, 6, 10, 20, 60};
                             if (ctx.tier.reduced) sizes = {1, 3, 10, 60};
                             const int reps = std::min(ctx.tier.reps, ctx.tier.reduced ? 2 : 3);
                             std::vector<repro::LabelledScene> out;
                             for (int np : sizes)
                               for (int ng : sizes) {
                                 repro::LabelledScene s{fmt::format("periodic_{}_{}", np, ng),
                                                        fmt::format("n_p = {}, n_g = {}", np, ng),
                                                        {{"n_p", np}, {"n_g", ng}, {"S_over_Stot", double(np) / (np + ng)}},
                                                        ctx.chain(360, "7.2cm", fmt::format("periodic:{},{}", np, ng))};
                                 s.scene.reps = reps;
                                 s.keep_runs = false;
                                 out.push_back(std::move(s));
                               }
                             return out;
                           });
}
