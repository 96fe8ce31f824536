// A scene's and an ensemble's complete states read back exactly (scene_state.hpp,
// ensemble_state.hpp): every field, values that are not finite included. The member counts below
// trip when a field is added to a scene's parts, which the states must then carry too.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "springblock/ensemble_state.hpp"
#include "springblock/errors.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/scene_state.hpp"

namespace {

// How many members an aggregate has: the most initialisers it accepts.
struct Any {
  template <class T>
  operator T() const;
};
template <class T, class... A>
constexpr int members() {
  if constexpr (requires { T{A{}..., Any{}}; }) return members<T, A..., Any>();
  else return static_cast<int>(sizeof...(A));
}

sb::Scene unusual_scene() {
  sb::Scene s;
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"N", "30"}, {"pattern", "hierarchical:6/2,2/1"}, {"layout", "groove_first"}, {"mu_s", "0.9,0.05"},
           {"pair_policy", "keep"}, {"k_int_scale", "0.5"}, {"method", "rk4"}, {"stepper", "dopri5"},
           {"peak_rule", "drop"}, {"stress_times", "1ms,2ms"}, {"slip_events", "true"}, {"seed", "9223372036854775807"}})
    sb::set_scene_field(s, key, value);
  s.materials.columns[sb::index_of(sb::BlockField::MuD)] = std::vector<double>(30, 0.45);
  s.materials.segments.push_back({sb::BlockField::KsScale, 2, -3, true, 0, 1.0, 2.0});
  s.materials.source = "python arrays";
  s.observe.timed_work = true;
  s.threads = 3;
  return s;
}

}  // namespace

TEST(SceneState, EveryPartHasTheMembersTheStateCarries) {
  // A field added to one of these must be added to scene_state.cpp (and kStateVersion bumped);
  // then the count here.
  EXPECT_EQ(members<sb::Scene>(), 12);
  EXPECT_EQ(members<sb::MaterialParameters>(), 8);
  EXPECT_EQ(members<sb::ChainGeometry>(), 2);
  EXPECT_EQ(members<sb::FrictionDistribution>(), 5);
  EXPECT_EQ(members<sb::PatternSpec>(), 9);
  EXPECT_EQ(members<sb::BlockMaterials>(), 5);
  EXPECT_EQ(members<sb::MaterialSegment>(), 7);
  EXPECT_EQ(members<sb::RunControl>(), 11);
  EXPECT_EQ(members<sb::ExtractionRules>(), 5);
  EXPECT_EQ(members<sb::Observables>(), 4);
}

TEST(SceneState, ReadsBackFieldForField) {
  const sb::Scene s = unusual_scene();
  const auto state = sb::scene_state(s);
  const sb::Scene back = sb::scene_from_state(nlohmann::json::parse(state.dump()));
  EXPECT_EQ(sb::scene_state(back), state);
  EXPECT_EQ(nlohmann::json(back), nlohmann::json(s));  // the results' record of it too
  EXPECT_EQ(back.seed, s.seed);
  EXPECT_EQ(back.pattern.level_pawls, s.pattern.level_pawls);
  EXPECT_EQ(back.materials.segments.size(), 1u);
  EXPECT_EQ(back.threads, 3);
  // A state that differs in one field is another state.
  sb::Scene other = s;
  other.rules.peak_drop = std::nextafter(s.rules.peak_drop, 1.0);
  EXPECT_NE(sb::scene_state(other), state);
}

TEST(SceneState, ValuesThatAreNotFiniteReadBack) {
  sb::Scene s;
  s.materials.columns[0] = {std::nan(""), HUGE_VAL, -HUGE_VAL, -0.0, 5e-324};
  const auto back = sb::scene_from_state(nlohmann::json::parse(sb::scene_state(s).dump()));
  const auto& c = back.materials.columns[0];
  ASSERT_EQ(c.size(), 5u);
  EXPECT_TRUE(std::isnan(c[0]));
  EXPECT_EQ(c[1], HUGE_VAL);
  EXPECT_EQ(c[2], -HUGE_VAL);
  EXPECT_TRUE(std::signbit(c[3]));
  EXPECT_EQ(c[4], 5e-324);
}

TEST(SceneState, AForeignStateIsRefusedNamingState) {
  for (const char* text : {R"({"N": 3})", R"({"springblock_scene_state": 1})", "[]"}) {
    try {
      sb::scene_from_state(nlohmann::json::parse(text));
      ADD_FAILURE() << text << " was accepted";
    } catch (const sb::InputError& e) {
      EXPECT_EQ(e.field, "state") << text;
    }
  }
}

TEST(EnsembleState, ReadsBackNumberForNumber) {
  sb::Scene s = unusual_scene();
  s.reps = 3;
  s.run.method = sb::Method::Event;
  s.observe.series = true;
  sb::set_scene_field(s, "duration", "2t0");
  sb::set_scene_field(s, "sample_dt", "0.1ms");  // a series of a few thousand samples is enough to read back
  const auto e = sb::run_ensemble(s);
  const auto state = sb::ensemble_state(e);
  const auto back = sb::ensemble_from_state(nlohmann::json::parse(state.dump()));
  EXPECT_EQ(sb::ensemble_state(back), state);
  ASSERT_EQ(back.runs.size(), 3u);
  EXPECT_EQ(back.runs[0].series.size(), e.runs[0].series.size());
  EXPECT_FALSE(e.runs[0].series.empty());
  EXPECT_EQ(back.runs[0].stress.size(), e.runs[0].stress.size());
  EXPECT_EQ(back.runs[1].contact_fraction, e.runs[1].contact_fraction);
  EXPECT_EQ(back.mu_s.mean, e.mu_s.mean);
  EXPECT_EQ(back.wall_s, e.wall_s);
  EXPECT_EQ(nlohmann::json(back.runs), nlohmann::json(e.runs));
}
