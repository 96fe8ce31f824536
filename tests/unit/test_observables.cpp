// Every observable registered in observables.hpp reaches each output: the repetition's value
// from the observer, the ensemble statistic, the runs' JSON and (when reported) the results JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/ensemble.hpp"
#include "springblock/io.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {

Scene observed_scene() {
  Scene s;
  set_scene_field(s, "N", "20");
  set_scene_field(s, "length", "0.4cm");
  set_scene_field(s, "duration", "3t0");
  s.reps = 2;
  s.threads = 1;
  validate(s);
  return s;
}

TEST(Observables, EachReachesTheRunsTheStatisticsAndTheJson) {
  const Scene s = observed_scene();
  const auto r = run_ensemble(s);
  const auto j = ensemble_json(s, r, "test");
  for (const auto& o : observables()) {
    std::vector<double> values;
    for (std::size_t k = 0; k < r.runs.size(); ++k) {
      const double x = r.runs[k].*o.value;
      values.push_back(x);
      const auto& entry = j.at("runs").at(k).at(o.name);
      if (std::isfinite(x)) EXPECT_EQ(entry.get<double>(), x) << o.name;
      else EXPECT_TRUE(entry.is_null()) << o.name;
    }
    EXPECT_EQ((r.*o.statistic).n, summarize(values).n) << o.name;
    EXPECT_EQ(j.contains(o.name), o.summary != Summary::None) << o.name;
  }
}

}  // namespace
