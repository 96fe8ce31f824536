/* NARRATIVE
Claim: Changing the block length l_x at fixed N changes K_int/K_s = 3 (N-1)/N (l_z/l_x)^2. While
K_int > K_s the macroscopic static coefficient is flat (and lower for larger N, as in fig_s1);
it rises once the two stiffnesses become comparable. The macroscopic dynamic coefficient grows
slowly as K_int/K_s is lowered, in both regimes.
Scene: smooth surfaces at N in {50, 100, 200} (smoke tier: 50, 100). For each N, l_x is chosen
so that K_int/K_s takes the values 300, 100, 30, 10, 3, 1, 0.3, 0.1, 0.03 (smoke tier: 100, 10,
1, 0.1), i.e. l_x = l_z sqrt(3 (N-1) / (N ratio)), L_x = N l_x. Default parameters otherwise.
The loading time t0 = (mu_s)_m P l_z / (G v) = 0.4 s does not depend on l_x, so every scene
runs the same simulated time.
Checked: claims C05 (mu_s constant within 3 % for K_int/K_s > 1), C06 (mu_s rises below ~1),
C07 (mu_d does not fall as K_int/K_s is lowered), C08 (larger N has lower plateau mu_s).
*/
#include <cmath>
#include <fmt/format.h>

#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(
      argc, argv, "fig_s2", "mu_s, mu_d vs K_int/K_s by varying l_x at fixed N",
      [](const repro::Context& ctx) {
        std::vector<int> Ns = {50, 100, 200};
        std::vector<double> ratios = {300, 100, 30, 10, 3, 1, 0.3, 0.1, 0.03};
        if (ctx.tier.reduced) Ns = {50, 100}, ratios = {100, 10, 1, 0.1};
        const double l_z_cm = 0.1;
        std::vector<repro::LabelledScene> out;
        for (int N : Ns)
          for (double ratio : ratios) {
            const double l_x_cm = l_z_cm * std::sqrt(3.0 * (N - 1) / (N * ratio));
            repro::LabelledScene s;
            s.id = fmt::format("N{}_ratio{:g}", N, ratio);
            s.label = fmt::format("N = {}, K_int/K_s = {:g}", N, ratio);
            s.scene = ctx.chain(N, fmt::format("{:.9g}cm", N * l_x_cm));
            const auto d = s.scene.derived();
            s.x = {{"N", N}, {"l_x_cm", l_x_cm}, {"K_int_over_K_s", d.K_int_N_per_m / d.K_s_N_per_m},
                   {"target_ratio", ratio}};
            out.push_back(s);
          }
        return out;
      });
}
