#include "springblock/design/query_text.hpp"

#include <algorithm>

#include "springblock/errors.hpp"
#include "springblock/materials.hpp"

namespace sb::design {
namespace {

Quantity parse_quantity_name(const std::string& field, const std::string& text) {
  if (text == "mu_s") return Quantity::MuS;
  if (text == "mu_d") return Quantity::MuD;
  if (text == "ratio") return Quantity::Ratio;
  throw InputError(field, "'" + text + "' is not a quantity; expected mu_s, mu_d or ratio");
}

}  // namespace

void complete_query(Query& q, const QueryText& t) {
  q.space.given = parse_candidates(t.candidates);
  q.base.pattern.kind = SurfaceKind::Smooth;  // validated as smooth; every candidate sets its own
  validate(q.base);
  // Per-block friction and springs may ride along; a contact field would replace every candidate.
  require(!resolve_materials(q.base).has(BlockField::Contact), "materials",
          "design searches the surface, and a contact column or segment would override every candidate's pattern; "
          "leave contact out of the materials");
  q.space.family = parse_family(t.family);
  q.space.max_np = t.max_np.value_or(std::min(kDefaultMaxSize, q.base.geometry.N));
  q.space.max_ng = t.max_ng.value_or(std::min(kDefaultMaxSize, q.base.geometry.N));
  if (!t.target_mu_s.empty()) q.target.mu_s = parse_interval("target_mu_s", t.target_mu_s);
  if (!t.target_mu_d.empty()) q.target.mu_d = parse_interval("target_mu_d", t.target_mu_d);
  if (!t.target_ratio.empty()) q.target.ratio = parse_interval("target_ratio", t.target_ratio);
  if (!t.minimise.empty() && !t.maximise.empty()) throw InputError("maximise", "give --minimise or --maximise, not both");
  if (!t.minimise.empty()) q.target.goal = Goal::Minimise, q.target.objective = parse_quantity_name("minimise", t.minimise);
  if (!t.maximise.empty()) q.target.goal = Goal::Maximise, q.target.objective = parse_quantity_name("maximise", t.maximise);
  validate(q);
}

void refuse_pattern(const std::string& pattern) {
  throw InputError("pattern", "'" + pattern + "': design chooses the surface, so it takes no fixed pattern; to choose "
                              "among surfaces of your own give --family given --candidates PATTERN... (masks too), "
                              "to run one surface use springblock run --pattern");
}

bool shared_scene_field(const std::string& key) {
  return key != "pattern" && key != "reps" && key != "stop_after_mu_s";
}

}  // namespace sb::design
