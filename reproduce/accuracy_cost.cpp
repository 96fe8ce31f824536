/* NARRATIVE
Claim: (ours, not the paper's) The paper integrates with fixed-step RK4 at h = 1e-4 ms and
resolves every stick/slip switch to one step, so refining h does not converge switching times at
fourth order. This target measures what each digit of accuracy costs: error against wall time
and against right-hand-side evaluations, for RK4 at h = 4, 2 and 1 x 1e-7 s (the paper's step and
coarser), for the event method's Dormand-Prince stepper over a range of tolerances (every decade
from 1e-6 to 1e-8, which brackets its default: the loosest decade whose first-peak error is below
a tenth of the smallest mu_s standard error of the reproduction), and for its exact stepper, the
default, which moves sliding runs by their modes and has no step-size error (its tolerance only
sets when a ringing groove counts as settled, and the tolerance of the Dormand-Prince steps of
runs longer than exact_max_run); it takes no right-hand-side evaluations, so panel (b) draws its
error level as a dashed line instead of points. RK4 below the paper's step
(0.5 and 0.25 x 1e-7 s) costs more than everything else here together; it is the optional study
rk4_refinement (`make studies`, committed under paper/data/), drawn in the same figure.
Scene: (A) first macroscopic peak, N = 360, L_x = 7.2 cm, periodic:10,10 (grooves keep RK4 from
jumping over quiet phases), each repetition stopped at its first macroscopic slip, mu(t) sampled
every 1e-6 s, the same seeds for every method. Before chaos sets in the peak is a deterministic
function of the seed, so its per-seed error against a converged reference is a clean measure of
integration error. (B) full runs of the smooth N = 200, L_x = 4 cm chain of fig1: the dynamic
phase is chaotic, so per-seed mu_d values decorrelate between methods; the meaningful error is the
ensemble mean of mu_d against the reference, in units of its standard error.
(C) cost against chain size: the event method at its defaults (exact stepper) on smooth, periodic:10,10
and hierarchical:60,6,1 chains of N = 90 to 2,880 blocks at the paper's block size (L_x = N x
0.2 mm), a fixed 2 s simulated, one repetition each; the exponent of wall time per simulated
second against N is fitted per surface (reproduce/cost_scaling.cpp, block "scaling").
Reference: the event method's Dormand-Prince stepper at tol 1e-12, independent of the exact
stepper; its own convergence is shown by the same stepper at tol 1e-11 (listed as "reference
check").
Checked: the reference check differs from the reference by far less than any setting's error;
every setting that could not run is listed under "failed" with its reason rather than dropped.
*/
#include "common.hpp"
#include "cost_scaling.hpp"
#include "work_precision.hpp"

int main(int argc, char** argv) {
  const auto settings =
      repro::work_precision_settings({4e-7, 2e-7, 1e-7}, {1e-4, 1e-6, 1e-7, 1e-8, 1e-10}, {1e-6, 1e-8, 1e-10}, true);
  return repro::run_target(
      argc, argv, "accuracy_cost", "work-precision: RK4 steps and event tolerances; event cost against N",
      [&](const repro::Context& ctx) {
        // The scaling study first: its largest chains are the longest jobs of the pool, which
        // runs jobs in order; started last they would leave a thread idle at the end.
        auto scenes = repro::cost_scaling_plan(ctx);
        for (auto& s : repro::work_precision_plan(ctx, settings)) scenes.push_back(std::move(s));
        return scenes;
      },
      [](const repro::Context& ctx, nlohmann::json& doc) {
        repro::work_precision_finish(ctx, doc);
        repro::cost_scaling_finish(ctx, doc);
      });
}
