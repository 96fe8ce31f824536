/* NARRATIVE
Claim: Table tpat1 lists one-, two- and three-level hierarchical patterns at N = 120,
L_x = 2.4 cm with first-level grooves of 8, 24 and 40 blocks: each added finer level raises
the static coefficient over its parent, and the dynamic coefficient rises as contact shrinks.
Scene: every row of tables/published_tab_pat1.tsv (read at run time, id = row_id), with that
row's N, L_x and hierarchical pattern (groove sizes largest first), default parameters,
repetitions and run length from the tier.
Checked: each of the 30 published numbers with the z rule (label `table`); claims C25, C27,
C28, C31 on our values.
*/
#include "common.hpp"
#include "table_scenes.hpp"

int main(int argc, char** argv) {
  // The rows the sensitivity study runs (to 6 t0, with the rows' own draws) are read from it.
  return repro::run_target(argc, argv, "tab_pat1", "table tpat1: hierarchical patterns, N=120",
                           [](const repro::Context& ctx) { return repro::table_scenes_reading(ctx, {"sensitivity"}); });
}
