/* NARRATIVE
Claim: For independent blocks (K_int = 0) the macroscopic dynamic coefficient follows the
single-block cycle formula (Eq. 9) averaged over the Gaussian micro coefficients: it equals the
micro mu_d when 2 mu_d >= mu_s and exceeds it below that. Interacting chains, damped or not,
follow the same curve for (mu_d)_m/(mu_s)_m >= 0.5 and depart from it only below 0.5, where
slipping blocks drag their neighbours.
Scene: smooth surface, N = 200, L_x = 4.0 cm, micro mu_s = 1.0(0.1), micro mu_d = r (0.01) for
r in {0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8, 0.9} (smoke tier: 0.2, 0.5, 0.8).
Four data sets: k_int_scale = 0 without damping ("kint0", the ideal case: Eq. 1 behind Eq. 9
has no damping term), k_int_scale = 0 with the default damping 10/ms ("kint0_damped"),
interacting with damping 10/ms ("damped") and interacting with damping 0 ("undamped"). The
caption names the damping only for the interacting sets. We first ran the decoupled set with
the default damping only: with gamma = 10/ms and omega = sqrt(K_s/m) = 6.5e4 /s the damping
ratio is 0.08, enough to shorten each slip and raise (mu_d)_M at r = 0.5 from the predicted
0.504 to 0.55, whereas without damping it gives 0.500. Both are kept so the effect is visible;
claim C10 is judged on the ideal (undamped) set. The theory curve uses one block of mass m, spring K_s, velocity v and normal force
F_load/N, evaluated by sb::theory::mu_d_macro_gaussian on a fine grid of r.
Run length: Eq. 9 is a time average over whole stick-slip cycles of blocks whose phases have
spread out. All blocks start at rest and are loaded alike, so for the first cycles they move
nearly in phase and a short window catches only part of a cycle (at r = 0.2 a 2 t0 run averages
mostly the low-force part of the static phase and gives 0.27 instead of 0.43). A cycle lasts
about 2 (1 - r) t0 (1.8 t0 at r = 0.1), and the 10 % spread of the micro mu_s detunes the
cycles by ~10 %, so ~10 cycles are needed to lose the phase. The rule is therefore a number of
cycles, not a time:
  * interacting sets: the window (from about 1.25 t0, the first macroscopic slip plus the
    0.25 t0 skip) holds as many cycles as a 20 t0 run holds at r = 0.1, about 10.4:
    duration = max(4, 1.25 + 18.75 (1 - r) / 0.9) t0, i.e. 20 t0 at r = 0.1, 11.7 t0 at 0.5,
    4 t0 (the tables' length, 14 cycles) at r = 0.9. Measured against 20 t0 for every r (the
    previous rule, 2.6x the cost of the whole target): the largest shift of mu_d is quoted in
    paper/choices.md and is within the sampling error.
  * K_int = 0 sets: 20 t0 for every r. Their blocks never lose phase (no coupling), so a
    window that is not a whole number of cycles biases mu_d by about -(ramp)/(12 n_cycles)
    (tables/known_deviations.tsv, C12), which only a long window makes negligible; the exact
    per-block solver makes these runs cheap anyway.
Smoke tier: 6 t0 for every set.
Checked: claims C10 (ideal K_int = 0 set within 0.01 of theory), C11 (interacting sets within 0.01 of
theory for r >= 0.5 and outside it somewhere below 0.5), C12 (K_int = 0 never below the micro
mu_d).
*/
#include <algorithm>
#include <string>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common.hpp"
#include "springblock/scene_theory.hpp"
#include "springblock/theory.hpp"

namespace {
const int kN = 200;
const char* kLength = "4cm";

// Run length in t0 (see the narrative): a fixed number of stick-slip cycles for interacting
// chains, 20 t0 for independent blocks.
double run_length_t0(const std::string& set, double r) {
  if (set == "kint0" || set == "kint0_damped") return 20.0;
  return std::max(4.0, 1.25 + 18.75 * (1.0 - r) / 0.9);
}
}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig2", "(mu_d)_M vs (mu_d)_m/(mu_s)_m: theory, K_int=0, interacting with/without damping",
      [](const repro::Context& ctx) {
        std::vector<double> rs = {0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8, 0.9};
        if (ctx.tier.reduced) rs = {0.2, 0.5, 0.8};
        struct Set { const char* id; const char* k_int_scale; const char* damping; };
        const Set sets[] = {{"kint0", "0", "0"}, {"kint0_damped", "0", "10/ms"}, {"damped", "1", "10/ms"},
                           {"undamped", "1", "0"}};
        std::vector<repro::LabelledScene> out;
        for (const auto& set : sets)
          for (double r : rs) {
            repro::LabelledScene s;
            s.id = fmt::format("{}_r{:g}", set.id, r);
            s.label = fmt::format("{}, (mu_d)_m/(mu_s)_m = {:g}", set.id, r);
            s.scene = ctx.chain(kN, kLength);
            repro::set(s.scene, "duration", fmt::format("{:.6g}t0", ctx.tier.reduced ? 6.0 : run_length_t0(set.id, r)));
            repro::set(s.scene, "mu_d", fmt::format("{:g},0.01", r));
            repro::set(s.scene, "k_int_scale", set.k_int_scale);
            repro::set(s.scene, "damping", set.damping);
            s.x = {{"set", set.id}, {"ratio", r}, {"mu_d_m", r}, {"mu_s_m", 1.0}};
            out.push_back(s);
          }
        return out;
      },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        sb::Scene s = ctx.chain(kN, kLength);
        const sb::theory::SingleBlock b = sb::theory::single_block(s);
        nlohmann::json r = nlohmann::json::array(), mu = r;
        for (int i = 5; i <= 100; ++i) {
          const double x = 0.01 * i;
          r.push_back(x);
          mu.push_back(sb::theory::mu_d_macro_gaussian(b, s.friction.mu_s_mean, s.friction.mu_s_sd, x,
                                                       s.friction.mu_d_sd));
        }
        doc["theory"] = {{"ratio", r}, {"mu_d_M", mu}, {"mu_s_m", s.friction.mu_s_mean},
                         {"sigma_s", s.friction.mu_s_sd}, {"sigma_d", s.friction.mu_d_sd},
                         {"source", "sb::theory::mu_d_macro_gaussian, one block on K_s with load F_load/N"}};
      });
}
