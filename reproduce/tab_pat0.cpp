/* NARRATIVE
Claim: Table tpat0 lists the macroscopic static and dynamic coefficients of a smooth surface
and of 38 single-level periodic patterns (n_p pawl blocks, n_g groove blocks) at N = 360,
L_x = 7.2 cm: the static coefficient falls with larger grooves at fixed contact fraction and
rises when the pawls are narrower than the grooves; the dynamic coefficient rises only when
the contact fraction is strongly reduced.
Scene: every row of tables/published_tab_pat0.tsv (read at run time, id = row_id), with that
row's N, L_x and pattern, default parameters, repetitions and run length from the tier. Rows
pat0_r01 and pat0_r06 are read from the sensitivity study, which runs their chains with their
own draws (the seed each row has here) to 6 t0 and reads the 4 t0 results off the same
trajectories: the same numbers as a run of their own, without simulating them twice.
Checked: each of the 78 published numbers against ours with the z rule of
tools/check_reproduction.py (label `table`), and claims C14-C17 and C20-C23.
*/
#include "common.hpp"
#include "table_scenes.hpp"

int main(int argc, char** argv) {
  // The rows the sensitivity study runs (to 6 t0, with the rows' own draws) are read from it.
  return repro::run_target(argc, argv, "tab_pat0", "table tpat0: single-level patterns, N=360",
                           [](const repro::Context& ctx) { return repro::table_scenes_reading(ctx, {"sensitivity"}); });
}
