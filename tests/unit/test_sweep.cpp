// The sweep library without the command: sweep files (TOML and JSON) read to the same spec with
// the line of every entry, ranges, the order of expanded scenes, errors naming field and line,
// the checkpoint's resume (a truncated last line, lost units, a foreign checkpoint), and a unit's
// record equal to its repetition run directly.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "springblock/ensemble.hpp"
#include "springblock/errors.hpp"
#include "springblock/sweep/checkpoint.hpp"
#include "springblock/sweep/expand.hpp"
#include "springblock/sweep/units.hpp"
#include "temp_dir.hpp"

namespace {

using sb::sweep::parse_json;
using sb::sweep::parse_toml;

const char* kToml = R"([base]
N = 20
duration = "3t0"
reps = 2

[axes]
pattern = ["smooth", "periodic:3,1"]
velocity = { from = 0.01, to = 0.04, steps = 3, scale = "log" }
)";

const char* kJson = R"({"base": {"N": 20, "duration": "3t0", "reps": 2},
 "axes": {"pattern": ["smooth", "periodic:3,1"],
          "velocity": {"from": 0.01, "to": 0.04, "steps": 3, "scale": "log"}}})";

TEST(SweepSpec, TomlAndJsonGiveTheSameSpecWithLines) {
  const auto t = parse_toml(kToml, "s.toml");
  const auto j = parse_json(kJson, "s.json");
  ASSERT_EQ(t.base.size(), 3u);
  ASSERT_EQ(t.axes.size(), 2u);
  EXPECT_EQ(t.axes[0].key, "pattern");  // file order, not toml++'s sorted order
  EXPECT_EQ(t.axes[1].key, "velocity");
  EXPECT_EQ(t.base[1].key, "duration");
  EXPECT_EQ(t.base[1].line, 3);
  EXPECT_EQ(t.axes[1].line, 8);
  EXPECT_EQ(j.axes[0].line, 2);
  EXPECT_EQ(j.axes[1].line, 3);
  for (std::size_t a = 0; a < 2; ++a) EXPECT_EQ(t.axes[a].values, j.axes[a].values);
}

TEST(SweepSpec, RangesIncludeBothEndsAndKeepIntegers) {
  const auto lin = sb::sweep::range_values("N", {{"from", 20}, {"to", 60}, {"steps", 3}}, "f", 1);
  ASSERT_EQ(lin.size(), 3u);
  EXPECT_TRUE(lin[1].is_number_integer());
  EXPECT_EQ(lin[1].get<long long>(), 40);
  const auto log = sb::sweep::range_values("v", {{"from", 0.01}, {"to", 0.04}, {"steps", 3}, {"scale", "log"}}, "f", 1);
  EXPECT_DOUBLE_EQ(log[1].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(log[2].get<double>(), 0.04);
  EXPECT_THROW(sb::sweep::range_values("N", {{"from", 1}, {"to", 2}, {"steps", 0}}, "f", 1), sb::InputError);
  EXPECT_THROW(sb::sweep::range_values("N", {{"from", 1}, {"steps", 2}}, "f", 1), sb::InputError);
}

TEST(SweepExpand, LastAxisVariesFastest) {
  const auto scenes = sb::sweep::expand(parse_toml(kToml, "s.toml"));
  ASSERT_EQ(scenes.size(), 6u);
  EXPECT_EQ(scenes[0].varied.at("pattern"), "smooth");
  EXPECT_EQ(scenes[2].varied.at("pattern"), "smooth");
  EXPECT_EQ(scenes[3].varied.at("pattern"), "periodic:3,1");
  EXPECT_DOUBLE_EQ(scenes[1].scene.material.v_m_per_s, 0.02);
  EXPECT_EQ(scenes[4].scene.geometry.N, 20);
  EXPECT_EQ(sb::sweep::make_units(scenes).size(), 12u);
}

TEST(SweepExpand, ListedScenesTimesAxes) {
  const char* toml = R"([base]
N = 20
duration = "3t0"
reps = 1

[[scenes]]
pattern = "smooth"

[[scenes]]
pattern = "periodic:3,1"
N = 40

[axes]
seed = [1, 2, 3]
)";
  const auto spec = parse_toml(toml, "s.toml");
  ASSERT_EQ(spec.scenes.size(), 2u);
  EXPECT_EQ(spec.scenes[1][1].key, "N");
  EXPECT_EQ(spec.scenes[1][1].line, 11);
  const auto scenes = sb::sweep::expand(spec);
  ASSERT_EQ(scenes.size(), 6u);  // listed scene slowest
  EXPECT_EQ(scenes[2].scene.seed, 3u);
  EXPECT_EQ(scenes[3].scene.geometry.N, 40);
  EXPECT_EQ(scenes[3].varied.at("pattern"), "periodic:3,1");
  EXPECT_EQ(scenes[0].scene.geometry.N, 20);
  const auto json = parse_json(R"({"base": {"N": 20, "duration": "3t0", "reps": 1},
    "scenes": [{"pattern": "smooth"}, {"pattern": "periodic:3,1",
                                       "N": 40}],
    "axes": {"seed": [1, 2, 3]}})", "s.json");
  EXPECT_EQ(json.scenes[1][1].line, 3);
  EXPECT_EQ(sb::sweep::fingerprint(sb::sweep::expand(json)), sb::sweep::fingerprint(scenes));
}

// The message of `spec`'s InputError, or "" when it expands.
std::string error_of(const std::string& toml) {
  try {
    sb::sweep::expand(parse_toml(toml, "s.toml"));
  } catch (const sb::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepExpand, ErrorsNameTheFieldAndTheLine) {
  EXPECT_NE(error_of("[base]\nN = 20\ncolour = 1\n").find("colour: unknown scene field (s.toml line 3)"),
            std::string::npos);
  EXPECT_NE(error_of("[base]\nN = 20\n[axes]\nN = [20, 0]\n").find("N: N = 0 is outside [1, 1000000] (s.toml line 4)"),
            std::string::npos);
  // A range error found by validate() points at the line that set the field.
  EXPECT_NE(error_of("[base]\nmu_d = \"0.9,0.01\"\n[axes]\nmu_s = [\"1.0,0.1\", \"0.8,0.1\"]\n").find("(s.toml line 2;"),
            std::string::npos);
  EXPECT_NE(error_of("[base]\nN = [1, 2]\n").find("belong in [axes]"), std::string::npos);
  EXPECT_NE(error_of("[bases]\nN = 2\n").find("bases: unknown section (s.toml line 1)"), std::string::npos);
  EXPECT_NE(error_of("[base]\nN = = 2\n").find("not valid TOML"), std::string::npos);
}

TEST(SweepCheckpoint, ResumeKeepsFinishedUnitsDropsACutLineAndReportsLostOnes) {
  sbtest::TempDir dir("sb_sweep_");
  const std::string path = (dir.path / "c.checkpoint").string();
  {
    sb::sweep::Checkpoint cp(path, "abc", 4, false);
    cp.assigned({0}, 0);
    cp.assigned({1, 3}, 1);
    cp.finished({{"unit", 0}, {"x", 0.1}});
  }
  std::ofstream(path, std::ios::app) << R"({"unit": 1, "x")";  // a kill mid-write
  EXPECT_THROW(sb::sweep::Checkpoint(path, "abc", 4, false), sb::InputError);  // no --resume
  EXPECT_THROW(sb::sweep::Checkpoint(path, "abd", 4, true), sb::InputError);   // another sweep
  std::vector<int> resumed;
  sb::sweep::Checkpoint cp(path, "abc", 4, true, [&](const nlohmann::json& r) { resumed.push_back(r.at("unit")); });
  ASSERT_EQ(cp.done_count(), 1);
  EXPECT_TRUE(cp.done(0));
  EXPECT_FALSE(cp.done(1));
  EXPECT_EQ(resumed, std::vector<int>{0});
  EXPECT_EQ(nlohmann::json::parse(cp.record_text(0)).at("x").get<double>(), 0.1);
  ASSERT_EQ(cp.lost().size(), 2u);  // 1 and 3, handed out together
  EXPECT_EQ(cp.lost()[0].unit, 1);
  EXPECT_EQ(cp.lost()[0].rank, 1);
  EXPECT_EQ(cp.lost()[1].unit, 3);
  cp.finished({{"unit", 2}, {"x", 0.2}});
  cp.sync();
  sb::sweep::Checkpoint again(path, "abc", 4, true);  // the cut line is gone, appends parse
  EXPECT_EQ(again.done_count(), 2);
  EXPECT_EQ(again.record_text(2), R"({"unit":2,"x":0.2})");
}

TEST(SweepUnits, ARecordHoldsTheRepetitionsNumbersExactly) {
  const auto scenes = sb::sweep::expand(parse_toml(kToml, "s.toml"));
  const auto units = sb::sweep::make_units(scenes);
  const auto record = sb::sweep::run_unit(scenes, units, 3, nullptr);  // scene 1, repetition 1
  const auto direct = sb::run_repetition(scenes[1].scene, 1);
  EXPECT_EQ(record.at("scene").get<int>(), 1);
  EXPECT_EQ(record.at("rep").get<int>(), 1);
  EXPECT_EQ(record.at("seed").get<std::uint64_t>(), sb::rep_seed(scenes[1].scene.seed, 1));
  // Through text and back, as between ranks and through the checkpoint: the same doubles.
  const auto back = nlohmann::json::parse(record.dump()).get<sb::RunResult>();
  EXPECT_EQ(back.mu_s, direct.mu_s);
  EXPECT_EQ(back.mu_d, direct.mu_d);
  EXPECT_EQ(back.steps, direct.steps);
}

}  // namespace
