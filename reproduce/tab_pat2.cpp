/* NARRATIVE
Claim: Table tpat2 lists one-, two- and three-level hierarchical patterns at N = 360,
L_x = 7.2 cm: a finer level raises the static coefficient over the parent with the same
first-level groove, but a two-level surface has a lower static coefficient than the
single-level one with the same contact fraction and the same largest groove; the dynamic
coefficient stays within a few percent of the smooth value.
Scene: every row of tables/published_tab_pat2.tsv (read at run time, id = row_id), with that
row's N, L_x and hierarchical pattern, default parameters, repetitions and run length from the
tier.
Checked: each of the 34 published numbers with the z rule (label `table`); claims C26-C32 on
our values.
*/
#include "common.hpp"
#include "table_scenes.hpp"

int main(int argc, char** argv) {
  return repro::run_target(argc, argv, "tab_pat2", "table tpat2: hierarchical patterns, N=360", repro::table_scenes);
}
