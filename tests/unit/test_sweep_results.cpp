// A sweep's results streamed scene by scene: the partial file (a header marked partial, a whole
// line per scene as it completes, in completion order) and the complete file assembled from the
// checkpoint, byte for byte the file the records held in memory would give (each scene's
// statistics over its repetitions in repetition order, whatever order the units came in).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "springblock/ensemble.hpp"
#include "springblock/sweep/checkpoint.hpp"
#include "springblock/sweep/expand.hpp"
#include "springblock/sweep/streamed_results.hpp"
#include "springblock/sweep/units.hpp"
#include "temp_dir.hpp"

namespace {

const char* kResultsToml = R"([base]
N = 20
duration = "3t0"
reps = 5
[axes]
pattern = ["smooth", "periodic:3,1", "hierarchical:2,2"]
)";

// A made-up record with every field a scene line reads: doubles of all sizes, a null value.
nlohmann::json fake_record(int unit, int scene, int rep) {
  std::mt19937_64 rng(unit);
  std::uniform_real_distribution<double> u(0, 1);
  nlohmann::json r = {{"unit", unit}, {"scene", scene}, {"rep", rep}, {"rank", unit % 3}};
  for (const auto& o : sb::observables()) r[o.name] = u(rng) * std::pow(10.0, unit % 7 - 3);
  r["mu_d"] = unit % 4 == 1 ? nlohmann::json(nullptr) : nlohmann::json(u(rng));
  r["wall_s"] = u(rng) * 1e-3;
  r["contact_fraction"] = u(rng);
  r["work"] = {{"steps", unit * 17}};
  return r;
}

// The results as they were made with every record in memory: the reference the streamed file
// must equal byte for byte.
std::string in_memory_results(const std::vector<sb::sweep::SweepScene>& scenes,
                              const std::map<int, nlohmann::json>& records, const nlohmann::json& header) {
  std::string out = header.dump() + "\n";
  int first = 0;
  for (int k = 0; k < static_cast<int>(scenes.size()); ++k) {
    nlohmann::json runs = nlohmann::json::array();
    double wall_s = 0;
    for (int r = 0; r < scenes[k].scene.reps; ++r) {
      const auto& rec = records.at(first + r);
      wall_s += rec.at("wall_s").get<double>();
      runs.push_back(rec);
    }
    const nlohmann::json scene_json = scenes[k].scene;
    nlohmann::json line = {{"scene", k}, {"varied", scenes[k].varied}};
    for (const auto& o : sb::observables()) {
      std::vector<double> values;
      for (const auto& rec : runs)
        values.push_back(rec.at(o.name).is_null() ? std::nan("") : rec.at(o.name).get<double>());
      line[o.name] = sb::summarize(values);
    }
    line.update(sb::schema_entries(scene_json));
    line["contact_fraction"] = runs[0].at("contact_fraction");
    line["wall_s"] = wall_s;
    line["scene_json"] = scene_json;
    line["runs"] = runs;
    out += line.dump() + "\n";
    first += scenes[k].scene.reps;
  }
  return out;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SweepResults, StreamedFileEqualsTheInMemoryOneWhateverTheFinishingOrder) {
  sbtest::TempDir dir("sb_sweep_results_");
  const auto scenes = sb::sweep::expand(sb::sweep::parse_toml(kResultsToml, "s.toml"));
  const auto units = sb::sweep::make_units(scenes);
  std::vector<int> order(units.size());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  const std::string out = (dir.path / "r.jsonl").string();
  sb::sweep::Checkpoint cp(out + ".checkpoint", "f", static_cast<int>(units.size()), false);
  sb::sweep::StreamedResults results(scenes, out);
  results.start({{"kind", "sweep"}});
  std::map<int, nlohmann::json> records;
  int complete = 0;
  for (int id : order) {
    records[id] = fake_record(id, units[id].scene, units[id].rep);
    cp.finished(records[id]);
    results.add(units[id].scene, units[id].rep, sb::sweep::record_numbers(records[id]));
    // Every line of the partial file is whole JSON; one per complete scene, after the header.
    const auto lines = lines_of(results.partial());
    ASSERT_EQ(static_cast<int>(lines.size()), 1 + results.scenes_complete());
    EXPECT_TRUE(nlohmann::json::parse(lines[0]).at("partial").get<bool>());
    for (const auto& l : lines) EXPECT_TRUE(nlohmann::json::accept(l));
    if (results.scenes_complete() > complete) {
      complete = results.scenes_complete();
      EXPECT_FALSE(nlohmann::json::parse(lines.back()).contains("runs"));
    }
  }
  EXPECT_FALSE(std::filesystem::exists(out));  // only the partial file until the end
  const nlohmann::json header = {{"kind", "sweep"}, {"units", units.size()}};
  results.complete(header, cp);
  EXPECT_EQ(text_of(out), in_memory_results(scenes, records, header));
  EXPECT_FALSE(std::filesystem::exists(results.partial()));
}

TEST(SweepResults, ResumedRecordsCompleteTheirScenesBeforeThePartialFileStarts) {
  sbtest::TempDir dir("sb_sweep_results_");
  const auto scenes = sb::sweep::expand(sb::sweep::parse_toml(kResultsToml, "s.toml"));
  const auto units = sb::sweep::make_units(scenes);
  const std::string out = (dir.path / "r.jsonl").string();
  std::map<int, nlohmann::json> records;
  {
    sb::sweep::Checkpoint cp(out + ".checkpoint", "f", static_cast<int>(units.size()), false);
    for (int id = 0; id < 7; ++id) cp.finished(records[id] = fake_record(id, units[id].scene, units[id].rep));
  }
  sb::sweep::StreamedResults results(scenes, out);
  sb::sweep::Checkpoint cp(out + ".checkpoint", "f", static_cast<int>(units.size()), true,
                           [&](const nlohmann::json& r) {
                             const auto& u = units.at(r.at("unit").get<int>());
                             results.add(u.scene, u.rep, sb::sweep::record_numbers(r));
                           });
  results.start({{"kind", "sweep"}});
  EXPECT_EQ(lines_of(results.partial()).size(), 2u);  // the header and scene 0 (units 0-4)
  for (int id = 7; id < static_cast<int>(units.size()); ++id) {
    cp.finished(records[id] = fake_record(id, units[id].scene, units[id].rep));
    results.add(units[id].scene, units[id].rep, sb::sweep::record_numbers(records[id]));
  }
  results.complete({{"kind", "sweep"}}, cp);
  EXPECT_EQ(text_of(out), in_memory_results(scenes, records, {{"kind", "sweep"}}));
}

}  // namespace
