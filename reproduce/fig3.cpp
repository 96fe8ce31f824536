/* NARRATIVE
Claim: (a) On a periodic surface with pawls and grooves of equal size, the friction stress
carried by the blocks at the pawl edges grows with the groove size, so slip nucleates there
earlier and the static coefficient falls. (b) Narrow pawls between wide grooves carry a larger
normal load per block, and their edge stress relative to their own threshold is lower, which is
why reducing the contact area can raise the static coefficient again.
Scene: N = 360, L_x = 7.2 cm, default parameters. (a) periodic:n,n for n in {4, 10, 30};
(b) pawls of 10 blocks with grooves of 10, 20 and 30 blocks (periodic:10,10 / 10,20 / 10,30,
contact fractions 1/2, 1/3, 1/4, all rows of tpat0). The snapshot time is fixed in advance, the
same for every scene: t_snap = 0.4 t0, with t0 = (mu_s)_m F_load / (N K_s v) the smooth-surface
loading time. Before any block slips the total friction equals the total slider force
N K_s v t, so the mean load mu(t_snap) = 0.4 for every pattern: about three quarters of the
lowest first peak in tpat0 (0.541), i.e. in the loading phase before the macroscopic slip.
Stress is sigma_i/P = f_i / (l_x l_y P) of repetition 0; each scene stops at its first
macroscopic slip. Both sigma/P and f/F_n (stress relative to the block's own normal force) are
stored, plus the contact mask for the profile line.
Checked: C18 (edge sigma/P of case (a) grows with n_g), C19 (in case (b) the edge f/F_n falls
as the pawls become relatively narrower); the snapshot lies before every scene's first slip.
*/
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "common.hpp"

namespace {
// Fraction of the smooth loading time t0 at which the profiles are taken (see the narrative).
constexpr double kSnapshotFraction = 0.4;

double snapshot_time(const repro::Context& ctx) { return kSnapshotFraction * ctx.chain(360, "7.2cm").t0_s(); }
}  // namespace

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig3", "stress profiles along patterned surfaces before the first slip",
      [](const repro::Context& ctx) {
        const double t = snapshot_time(ctx);
        struct Case { const char* panel; int n_p, n_g; };
        const Case cases[] = {{"a", 4, 4}, {"a", 10, 10}, {"a", 30, 30}, {"b", 10, 10}, {"b", 10, 20}, {"b", 10, 30}};
        std::vector<repro::LabelledScene> out;
        for (const auto& c : cases) {
          repro::LabelledScene s;
          s.id = fmt::format("{}_periodic_{}_{}", c.panel, c.n_p, c.n_g);
          s.label = fmt::format("({}) n_p = {}, n_g = {}", c.panel, c.n_p, c.n_g);
          s.scene = ctx.chain(360, "7.2cm", fmt::format("periodic:{},{}", c.n_p, c.n_g));
          s.scene.observe.stress_times_s = {t};
          s.scene.run.stop_after_mu_s = true;
          s.x = {{"panel", c.panel}, {"n_p", c.n_p}, {"n_g", c.n_g}};
          out.push_back(s);
        }
        return out;
      },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        doc["snapshot"] = {{"t_s", snapshot_time(ctx)}, {"fraction_of_t0", kSnapshotFraction},
                           {"mean_load_mu", kSnapshotFraction},
                           {"rule", "t = 0.4 t0 of the smooth chain: mean load 0.4, before the first slip"}};
      });
}
