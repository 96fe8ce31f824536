/* NARRATIVE
Claim: On a smooth surface the total friction force divided by the load first grows linearly
while the slider loads the chain, peaks at the first macroscopic slip (this peak is the static
coefficient) and then fluctuates irregularly in stick-slip; its time average over the sliding
phase is the dynamic coefficient, clearly below the peak. The number of sliding blocks jumps
at each slip event.
Scene: smooth surface, N = 200 blocks, L_x = 4.0 cm (l_x = 0.02 cm), default parameters
(G = 5 MPa, E = 15 MPa, rho = 1.2 g/cm3, P = 1 MPa, gamma = 10/ms, v = 0.05 cm/s, l_y = 1 cm,
l_z = 0.1 cm, micro mu_s = 1.0(0.1), mu_d = 0.50(0.01)); repetitions and run length from the
tier; mu(t) and the sliding count of repetition 0 are kept as the plotted series. The scene is
fig_s1's default_N200 (its L_x = 200 x 0.02 cm): its statistics are read from fig_s1's record
(same tier, repro::find_borrowable), and only repetition 0 runs again, with fig_s1's seed, for
its trace, which must reproduce that record's repetition 0 to the last bit.
Checked: claim C09 (first peak above the sliding-phase mean, judged on every repetition's
mu_s and mu_d); the series exists, starts at mu = 0 and its maximum equals repetition 0's mu_s.
*/
#include "common.hpp"

int main(int argc, char** argv) {
  return repro::run_target(argc, argv, "fig1", "mu(t) and sliding count, smooth N=200, L_x=4cm",
                           [](const repro::Context& ctx) {
                             repro::LabelledScene s{"smooth_N200", "smooth, N=200, L_x=4.0 cm", {}, ctx.chain(200, "4cm")};
                             // Without fig_s1's document (--input; make gives it) it runs here.
                             if (!repro::given_inputs(ctx, {"fig_s1"}).empty())
                               s.borrow = repro::find_borrowable(ctx, {"fig_s1"}, s.scene);
                             if (s.borrow.target.empty()) s.scene.observe.series = true;
                             else s.borrow.trace = true;
                             s.x = {{"N", 200}, {"L_x_cm", 4.0}};
                             return std::vector<repro::LabelledScene>{s};
                           });
}
