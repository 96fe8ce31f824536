/* NARRATIVE
Claim: (a) On a periodic surface with pawls and grooves of equal size, the friction stress
carried by the blocks at the pawl edges grows with the groove size, so slip nucleates there
earlier and the static coefficient falls. (b) Narrow pawls between wide grooves carry a larger
normal load per block, and their edge stress relative to their own threshold is lower, which is
why reducing the contact area can raise the static coefficient again.
Scene: N = 360, L_x = 7.2 cm, default parameters. (a) periodic:n,n for n in {4, 10, 30};
(b) pawls of 10 blocks with grooves of 10, 20 and 30 blocks (periodic:10,10 / 10,20 / 10,30,
contact fractions 1/2, 1/3, 1/4, all rows of tpat0). Snapshots are taken at times fixed in
advance, the same for every scene: t = f t0 for f in {0.1, 0.2, 0.3, 0.4}, with
t0 = (mu_s)_m F_load / (N K_s v) = 0.4 s the smooth-surface loading time. Before any block
slips the total friction equals the total slider force N K_s v t, so the mean load is
mu(t) = f for every pattern. The headline snapshot (the one the checks and the figure use) is
f = 0.2: well inside the loading phase (first slips come at mean loads >= 0.54 in tpat0), and
early enough that the pawl-edge blocks are still below their own thresholds (largest f/F_n
about 0.9 in our test runs); at f = 0.4 the edges
of the larger grooves are already capped at mu_s_i F_n, which hides the growth with n_g.
Stress is sigma_i/P = f_i / (l_x l_y P) of repetition 0; each scene stops at its first
macroscopic slip. Both sigma/P and f/F_n (stress relative to the block's own normal force) are
stored, plus the contact mask for the profile line.
Checked: C18 (mean edge sigma/P of case (a) grows with n_g), C19 (edge f/F_n, i.e. stress
relative to the block's own threshold scale, is lower for narrow pawls n_p = 10, n_g = 30 than
for n_p = n_g = 30 with the same grooves). Edge blocks are contact blocks next to a groove.
*/
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common.hpp"

namespace {
// Fractions of the smooth loading time t0 at which profiles are taken, and the headline one
// (see the narrative).
const std::vector<double> kFractions = {0.1, 0.2, 0.3, 0.4};
constexpr std::size_t kHeadline = 1;

double t0(const repro::Context& ctx) { return ctx.chain(360, "7.2cm").t0_s(); }
}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig3", "stress profiles along patterned surfaces before the first slip",
      [](const repro::Context& ctx) {
        std::vector<double> times;
        for (double f : kFractions) times.push_back(f * t0(ctx));
        struct Case { const char* panel; int n_p, n_g; };
        const Case cases[] = {{"a", 4, 4}, {"a", 10, 10}, {"a", 30, 30}, {"b", 10, 10}, {"b", 10, 20}, {"b", 10, 30}};
        std::vector<repro::LabelledScene> out;
        for (const auto& c : cases) {
          repro::LabelledScene s;
          s.id = fmt::format("{}_periodic_{}_{}", c.panel, c.n_p, c.n_g);
          s.label = fmt::format("({}) n_p = {}, n_g = {}", c.panel, c.n_p, c.n_g);
          s.scene = ctx.chain(360, "7.2cm", fmt::format("periodic:{},{}", c.n_p, c.n_g));
          s.scene.observe.stress_times_s = times;
          s.scene.run.stop_after_mu_s = true;
          s.x = {{"panel", c.panel}, {"n_p", c.n_p}, {"n_g", c.n_g}};
          out.push_back(s);
        }
        return out;
      },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        std::vector<double> times;
        for (double f : kFractions) times.push_back(f * t0(ctx));
        doc["snapshot"] = {{"index", kHeadline}, {"t_s", times[kHeadline]}, {"fraction_of_t0", kFractions[kHeadline]},
                           {"mean_load_mu", kFractions[kHeadline]}, {"times_s", times}, {"fractions_of_t0", kFractions},
                           {"rule", "t = f t0 of the smooth chain, mean load f; headline f = 0.2, before any slip"}};
      });
}
