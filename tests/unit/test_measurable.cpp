// A scene either measures something or is refused: the default method, the scenes validate()
// refuses because they could only average over no samples (mu_d above mu_s, a sampling step or
// a mu_d window longer than the run), the reasons ensemble_json gives beside its nulls, and
// output paths refused before anything runs.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/ensemble.hpp"
#include "springblock/io.hpp"
#include "springblock/scene.hpp"
#include "springblock/errors.hpp"

using namespace sb;
namespace fs = std::filesystem;

namespace {

// The InputError's field, or "" if `s` validates.
std::string refused_field(const Scene& s) {
  try {
    validate(s);
  } catch (const InputError& e) {
    return e.field;
  }
  return "";
}

// True if any number in `j` is NaN or infinite (dump() would print those as null, hiding them).
bool has_non_finite(const nlohmann::json& j) {
  if (j.is_number_float()) return !std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& v : j)
      if (has_non_finite(v)) return true;
  return false;
}

Scene small() {
  Scene s;
  s.geometry = {40, 0.008};
  s.reps = 2;
  s.seed = 3;
  return s;
}

}  // namespace

TEST(Defaults, EventMethodAndAllCores) {
  EXPECT_EQ(RunControl{}.method, Method::Event);
  EXPECT_EQ(Scene{}.threads, 0);  // 0 = all cores
  EXPECT_EQ(refused_field(Scene{}), "");
}

TEST(Validate, MuDMeanAboveMuSMeanIsRefusedUnderBothPolicies) {
  for (auto policy : {FrictionDistribution::PairPolicy::Clip, FrictionDistribution::PairPolicy::Keep})
    for (auto method : {Method::RK4, Method::Event}) {
      Scene s;
      s.run.method = method;
      s.friction = {1.0, 0.1, 1.5, 0.01, policy};
      EXPECT_EQ(refused_field(s), "mu_d");
      s.friction.mu_d_mean = 1.0;  // equal means: blocks creep at their threshold, allowed
      EXPECT_EQ(refused_field(s), "");
    }
}

TEST(Validate, SampleStepMustLeaveASlipSampleAndOneAfterIt) {
  Scene s = small();
  s.run.duration_s = 1.0;
  s.run.sample_dt_s = 0.5;
  EXPECT_EQ(refused_field(s), "");
  s.run.sample_dt_s = 0.6;
  EXPECT_EQ(refused_field(s), "sample_dt");
  s.run.stop_after_mu_s = true;  // no mu_d window: one interval suffices
  EXPECT_EQ(refused_field(s), "");
  s.run.sample_dt_s = 1.1;
  EXPECT_EQ(refused_field(s), "sample_dt");
}

TEST(Validate, MuDWindowMustOpenBeforeTheEnd) {
  Scene s = small();
  s.run.duration_t0 = 4;
  s.rules.mu_d_skip_t0 = 3.9;
  EXPECT_EQ(refused_field(s), "");
  s.rules.mu_d_skip_t0 = 4;
  EXPECT_EQ(refused_field(s), "mu_d_skip");
  s.rules.mu_d_skip_t0 = 0.25;
  s.run.duration_t0 = 0.2;
  EXPECT_EQ(refused_field(s), "mu_d_skip");
  s.run.stop_after_mu_s = true;  // no window, so no constraint on it
  EXPECT_EQ(refused_field(s), "");
}

TEST(NotMeasured, StopAfterMuSGivesNullMuDWithItsReason) {
  Scene s = small();
  s.run.stop_after_mu_s = true;
  validate(s);
  const auto r = run_ensemble(s);
  EXPECT_EQ(r.mu_s.n, 2);
  EXPECT_EQ(r.mu_d.n, 0);
  EXPECT_EQ(not_measured(s, r, "mu_s"), "");
  EXPECT_EQ(not_measured(s, r, "mu_d"), "stop_after_mu_s");
  const auto j = ensemble_json(s, r, "test");
  EXPECT_TRUE(j["mu_d"]["mean"].is_null());
  EXPECT_EQ(j["mu_d"]["not_measured"], "stop_after_mu_s");
  EXPECT_EQ(j["mu_d_signed"]["not_measured"], "stop_after_mu_s");
  EXPECT_FALSE(j["mu_s"].contains("not_measured"));
  EXPECT_FALSE(has_non_finite(j));
}

TEST(NotMeasured, RunEndingBeforeTheFirstSlipNamesDuration) {
  Scene s = small();
  s.run.duration_t0 = 0.05;  // far before any block reaches its threshold
  s.rules.mu_d_skip_t0 = 0;
  validate(s);
  const auto r = run_ensemble(s);
  EXPECT_EQ(r.mu_s.n, 0);
  EXPECT_NE(not_measured(s, r, "mu_s").find("(duration)"), std::string::npos);
  EXPECT_NE(not_measured(s, r, "mu_d").find("(duration)"), std::string::npos);
  const auto j = ensemble_json(s, r, "test");
  EXPECT_TRUE(j["mu_s"]["mean"].is_null());
  EXPECT_FALSE(has_non_finite(j));
}

TEST(NotMeasured, EmptyMuDWindowNamesMuDSkip) {
  Scene s = small();
  s.run.duration_t0 = 4;
  s.rules.mu_d_skip_t0 = 3.99;  // opens after the end: the first slip comes well after 0.01 t0
  validate(s);
  const auto r = run_ensemble(s);
  EXPECT_EQ(r.mu_s.n, 2);
  EXPECT_EQ(r.mu_d.n, 0);
  EXPECT_NE(not_measured(s, r, "mu_d").find("mu_d_skip"), std::string::npos);
}

class CheckWritable : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/sb_writable_XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl), nullptr);
    dir = tmpl;
  }
  void TearDown() override { fs::remove_all(dir); }
  // The field of the InputError check_writable throws, or "" if it accepts the path.
  static std::string refused(const std::string& path) {
    try {
      check_writable(path, "out");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.empty() ? "empty" : path), std::string::npos) << e.what();
      return e.field;
    }
    return "";
  }
  bool empty_dir() const { return fs::is_empty(dir); }
  std::string dir;
};

TEST_F(CheckWritable, RefusesMissingDirectoryDirectoryAndFileAsDirectory) {
  EXPECT_EQ(refused(dir + "/missing/out.json"), "out");
  EXPECT_EQ(refused(dir), "out");
  std::ofstream(dir + "/file") << "x";
  EXPECT_EQ(refused(dir + "/file/out.json"), "out");
  EXPECT_EQ(refused(""), "out");
  fs::remove(dir + "/file");
  EXPECT_TRUE(empty_dir());
}

TEST_F(CheckWritable, AcceptsAWritableDirectoryAndLeavesNothing) {
  EXPECT_EQ(refused(dir + "/out.json"), "");
  EXPECT_TRUE(empty_dir()) << "the probe file was left behind";
}
