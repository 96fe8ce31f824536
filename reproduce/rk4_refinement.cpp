/* NARRATIVE
Claim: (ours, an optional study) Refining the paper's RK4 step below h = 1e-4 ms does not make
its first-peak error converge: every stick/slip switch is still resolved to one step.
Scene: the scenes of accuracy_cost (first macroscopic peak on periodic:10,10, N = 360, 3 seeds;
mu_d of the smooth N = 200 chain) with RK4 at h = 5e-8 s and 2.5e-8 s, measured against the same
event reference (tol 1e-12, recomputed here: same seeds, so the same numbers as accuracy_cost's).
Not part of `make reproduce-all`: these two settings cost more than the rest of the
work-precision study together. `make studies` runs it and commits its document under
paper/data/, which figures/accuracy_cost.py draws beside accuracy_cost's settings.
Checked: accuracy_cost's figure and report table show these rows with the commit that made them.
*/
#include "common.hpp"
#include "work_precision.hpp"

int main(int argc, char** argv) {
  const auto settings = repro::work_precision_settings({5e-8, 2.5e-8}, {}, {}, false);
  return repro::run_target(
      argc, argv, "rk4_refinement", "work-precision of RK4 below the paper's step (optional study)",
      [&](const repro::Context& ctx) { return repro::work_precision_plan(ctx, settings); },
      repro::work_precision_finish);
}
