#include "springblock/scene_state.hpp"

#include <nlohmann/json.hpp>

#include "springblock/errors.hpp"
#include "springblock/exact_json.hpp"

namespace sb {
// Named, not anonymous: in a unity batch an anonymous helper called num() or code() would meet
// another file's.
namespace scene_state_parts {

// Bumped whenever a field is added to Scene (and to both functions below), so an old pickle is
// refused rather than read with the new field silently left at its default.
constexpr int kStateVersion = 1;

using exact_json::num;
using exact_json::nums;

template <class Enum>
int code(Enum e) {
  return static_cast<int>(e);
}
template <class Enum>
Enum enum_of(const nlohmann::json& j) {
  return static_cast<Enum>(j.get<int>());
}

nlohmann::json pattern_state(const PatternSpec& p) {
  auto layout = nlohmann::json::array();
  for (auto l : p.layout) layout.push_back(code(l));
  return {{"kind", code(p.kind)}, {"n_p", p.n_p},   {"n_g", p.n_g},        {"levels", p.levels},
          {"level_pawls", p.level_pawls}, {"groove_fraction", num(p.groove_fraction)},
          {"mask", p.mask}, {"mask_path", p.mask_path}, {"layout", layout}};
}
PatternSpec pattern_from(const nlohmann::json& j) {
  PatternSpec p;
  p.kind = enum_of<SurfaceKind>(j.at("kind"));
  p.n_p = j.at("n_p").get<int>();
  p.n_g = j.at("n_g").get<int>();
  p.levels = j.at("levels").get<std::vector<int>>();
  p.level_pawls = j.at("level_pawls").get<std::vector<int>>();
  p.groove_fraction = num(j.at("groove_fraction"));
  p.mask = j.at("mask").get<std::vector<std::uint8_t>>();
  p.mask_path = j.at("mask_path").get<std::string>();
  p.layout.clear();
  for (const auto& l : j.at("layout")) p.layout.push_back(enum_of<Layout>(l));
  return p;
}

nlohmann::json materials_state(const BlockMaterials& m) {
  auto columns = nlohmann::json::array();
  for (const auto& c : m.columns) columns.push_back(nums(c));
  auto segments = nlohmann::json::array();
  for (const auto& g : m.segments)
    segments.push_back({code(g.field), g.from, g.to, g.ramp, num(g.value), num(g.start), num(g.end)});
  return {{"source", m.source}, {"columns", columns}, {"file", m.file}, {"lines", m.lines}, {"segments", segments}};
}
BlockMaterials materials_from(const nlohmann::json& j) {
  BlockMaterials m;
  m.source = j.at("source").get<std::string>();
  const auto& columns = j.at("columns");
  if (columns.size() != m.columns.size()) throw InputError("state", "the materials hold another number of fields");
  for (std::size_t i = 0; i < m.columns.size(); ++i) m.columns[i] = nums(columns[i]);
  m.file = j.at("file").get<bool>();
  m.lines = j.at("lines").get<std::vector<int>>();
  for (const auto& g : j.at("segments"))
    m.segments.push_back({enum_of<BlockField>(g.at(0)), g.at(1).get<long>(), g.at(2).get<long>(), g.at(3).get<bool>(),
                          num(g.at(4)), num(g.at(5)), num(g.at(6))});
  return m;
}

nlohmann::json run_state(const RunControl& r, const ExtractionRules& x) {
  return {{"method", code(r.method)},         {"dt_s", num(r.dt_s)},
          {"tol", num(r.tol)},                {"modal_max_run", r.modal_max_run},
          {"modal_max_groove", r.modal_max_groove}, {"stepper", code(r.stepper)},
          {"exact_max_run", r.exact_max_run}, {"duration_t0", num(r.duration_t0)},
          {"duration_s", num(r.duration_s)},  {"sample_dt_s", num(r.sample_dt_s)},
          {"stop_after_mu_s", r.stop_after_mu_s}, {"peak_rule", code(x.peak_rule)},
          {"peak_drop", num(x.peak_drop)},    {"peak_drop_fraction", num(x.peak_drop_fraction)},
          {"peak_event_fraction", num(x.peak_event_fraction)}, {"mu_d_skip_t0", num(x.mu_d_skip_t0)}};
}
void run_from(const nlohmann::json& j, RunControl& r, ExtractionRules& x) {
  r.method = enum_of<Method>(j.at("method"));
  r.dt_s = num(j.at("dt_s"));
  r.tol = num(j.at("tol"));
  r.modal_max_run = j.at("modal_max_run").get<int>();
  r.modal_max_groove = j.at("modal_max_groove").get<int>();
  r.stepper = enum_of<Stepper>(j.at("stepper"));
  r.exact_max_run = j.at("exact_max_run").get<int>();
  r.duration_t0 = num(j.at("duration_t0"));
  r.duration_s = num(j.at("duration_s"));
  r.sample_dt_s = num(j.at("sample_dt_s"));
  r.stop_after_mu_s = j.at("stop_after_mu_s").get<bool>();
  x.peak_rule = enum_of<ExtractionRules::PeakRule>(j.at("peak_rule"));
  x.peak_drop = num(j.at("peak_drop"));
  x.peak_drop_fraction = num(j.at("peak_drop_fraction"));
  x.peak_event_fraction = num(j.at("peak_event_fraction"));
  x.mu_d_skip_t0 = num(j.at("mu_d_skip_t0"));
}

}  // namespace scene_state_parts

nlohmann::json scene_state(const Scene& s) {
  using namespace scene_state_parts;
  const auto& m = s.material;
  const auto& f = s.friction;
  return {{"springblock_scene_state", kStateVersion},
          {"material", {num(m.G_Pa), num(m.E_Pa), num(m.rho_kg_per_m3), num(m.P_Pa), num(m.gamma_per_s),
                        num(m.v_m_per_s), num(m.l_y_m), num(m.l_z_m)}},
          {"geometry", {s.geometry.N, num(s.geometry.L_x_m)}},
          {"friction", {num(f.mu_s_mean), num(f.mu_s_sd), num(f.mu_d_mean), num(f.mu_d_sd), code(f.pair_policy)}},
          {"k_int_scale", num(s.k_int_scale)},
          {"pattern", pattern_state(s.pattern)},
          {"materials", materials_state(s.materials)},
          {"run", run_state(s.run, s.rules)},
          {"observe", {s.observe.series, nums(s.observe.stress_times_s), s.observe.timed_work, s.observe.slip_events}},
          {"reps", s.reps},
          {"seed", s.seed},
          {"threads", s.threads}};
}

Scene scene_from_state(const nlohmann::json& j) {
  using namespace scene_state_parts;
  if (!j.is_object() || j.value("springblock_scene_state", 0) != kStateVersion)
    throw InputError("state", "not a scene state of this springblock (state version " + std::to_string(kStateVersion) +
                                  "): pickle the scene again with this version");
  try {
    Scene s;
    const auto& m = j.at("material");
    s.material = {num(m.at(0)), num(m.at(1)), num(m.at(2)), num(m.at(3)),
                  num(m.at(4)), num(m.at(5)), num(m.at(6)), num(m.at(7))};
    s.geometry = {j.at("geometry").at(0).get<int>(), num(j.at("geometry").at(1))};
    const auto& f = j.at("friction");
    s.friction = {num(f.at(0)), num(f.at(1)), num(f.at(2)), num(f.at(3)),
                  enum_of<FrictionDistribution::PairPolicy>(f.at(4))};
    s.k_int_scale = num(j.at("k_int_scale"));
    s.pattern = pattern_from(j.at("pattern"));
    s.materials = materials_from(j.at("materials"));
    run_from(j.at("run"), s.run, s.rules);
    const auto& o = j.at("observe");
    s.observe = {o.at(0).get<bool>(), nums(o.at(1)), o.at(2).get<bool>(), o.at(3).get<bool>()};
    s.reps = j.at("reps").get<int>();
    s.seed = j.at("seed").get<std::uint64_t>();
    s.threads = j.at("threads").get<int>();
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("state", std::string("a scene state with a missing or malformed entry: ") + e.what());
  }
}

}  // namespace sb
