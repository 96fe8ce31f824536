#pragma once
// Scenes for the published tables: one scene per TSV row, keyed by row_id, built from the row's
// own N, L_x and pattern. The rows are read at run time so the TSV is the single source.
#include <vector>

#include "common.hpp"

namespace repro {

// The rows of --table, which may list several TSV files separated by commas (the studies read
// all three appendix tables).
std::vector<TableRow> table_rows(const Context& ctx);
std::vector<LabelledScene> table_scenes(const Context& ctx);
// The same, with every row that one of `sources` ran with the row's own draws read from its
// document (where given with --input; make gives it) instead of run again: the same simulation,
// so the same numbers.
std::vector<LabelledScene> table_scenes_reading(const Context& ctx, const std::vector<std::string>& sources);

}  // namespace repro
