#include "table_scenes.hpp"

#include <fmt/format.h>

#include <sstream>
#include <string>

#include "springblock/errors.hpp"

namespace repro {

std::vector<TableRow> table_rows(const Context& ctx) {
  if (ctx.opt.table.empty()) throw sb::InputError("table", "this target needs --table published_tab_patN.tsv");
  std::vector<TableRow> rows;
  std::stringstream list(ctx.opt.table);
  for (std::string path; std::getline(list, path, ',');)
    for (auto& r : read_table(path)) rows.push_back(std::move(r));
  return rows;
}

std::vector<LabelledScene> table_scenes(const Context& ctx) {
  std::vector<LabelledScene> out;
  for (const auto& row : table_rows(ctx)) {
    LabelledScene s;
    s.id = row.row_id;
    s.label = row.pattern;
    s.scene = ctx.chain(row.N, fmt::format("{:g}cm", row.L_x_cm), row.pattern);
    s.x = {{"row_id", row.row_id},
           {"pattern", row.pattern},
           {"N", row.N},
           {"L_x_cm", row.L_x_cm},
           {"S_printed", row.S_num / row.S_den},
           {"S_printed_text", fmt::format("{:g}/{:g}", row.S_num, row.S_den)},
           {"published", {{"mu_s", row.mu_s}, {"mu_s_err", row.mu_s_err}, {"mu_d", row.mu_d}, {"mu_d_err", row.mu_d_err}}}};
    out.push_back(s);
  }
  return out;
}

std::vector<LabelledScene> table_scenes_reading(const Context& ctx, const std::vector<std::string>& sources) {
  auto out = table_scenes(ctx);
  // Only the sources given with --input (make gives them all): without one, a row runs here,
  // which is the same simulation.
  const auto given = given_inputs(ctx, sources);
  if (given.empty()) return out;
  for (auto& s : out) s.borrow = find_borrowable(ctx, given, s.scene, scene_seed(ctx.opt.seed, s.id));
  return out;
}

}  // namespace repro
