// The trajectory spec holds exactly the scene inputs the motion depends on: every scene field is
// classified here as changing the trajectory (so the spec) or only what is read off it, and a
// field added to the scene table without a verdict fails the coverage test.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "springblock/scene_fields.hpp"
#include "springblock/trajectory_spec.hpp"

using namespace sb;

namespace {

struct Verdict {
  const char* key;
  const char* value;  // differs from the default
  bool changes_trajectory;
};

const Verdict kVerdicts[] = {
    // The chain: stiffnesses, mass, load, damping, slider.
    {"N", "360", true},
    {"length", "7.2cm", true},
    {"k_int_scale", "0.5", true},
    // Per-block fields, by the hash of their values.
    {"materials", SPRINGBLOCK_SOURCE_DIR "/examples/graded_materials.tsv", true},
    {"damping", "5/ms", true},
    {"velocity", "0.1cm/s", true},
    {"pressure", "2MPa", true},
    {"shear_modulus", "6MPa", true},
    {"young_modulus", "16MPa", true},
    {"density", "1.3g/cm3", true},
    {"l_y", "2cm", true},
    {"l_z", "0.2cm", true},
    // The micro coefficients and the contact mask.
    {"mu_s", "1.2,0.1", true},
    {"mu_d", "0.4,0.01", true},
    {"pair_policy", "keep", true},
    {"pattern", "periodic:3,1", true},
    {"layout", "groove_first", true},
    // The draws and the ensemble of repetitions.
    {"seed", "7", true},
    {"reps", "5", true},
    // The integrator and its sample grid.
    {"method", "rk4", true},
    {"dt", "2e-4ms", true},
    {"tol", "1e-9", true},
    {"modal_max_run", "3", true},
    {"modal_max_groove", "8", true},
    {"stepper", "dopri5", true},
    {"exact_max_run", "16", true},
    {"sample_dt", "2e-2ms", true},
    // What is read off the trajectory or recorded, and who runs it.
    {"duration", "2t0", false},
    {"peak_rule", "drop", false},
    {"peak_drop", "0.2", false},
    {"peak_drop_fraction", "0.2", false},
    {"peak_event_fraction", "0.25", false},
    {"mu_d_skip", "0.5", false},
    {"stress_times", "0.2s", false},
    {"slip_events", "true", false},
    {"threads", "2", false},
};

// On a grooved surface, so that the layout places its grooves.
Scene grooved() {
  Scene s;
  set_scene_field(s, "pattern", "periodic:2,1");
  return s;
}

TEST(TrajectorySpec, EveryFieldEitherChangesItOrNot) {
  const Scene base = grooved();
  const auto spec = trajectory_spec(base);
  ASSERT_TRUE(spec.has_value());
  for (const auto& v : kVerdicts) {
    Scene s = base;
    set_scene_field(s, v.key, v.value);
    const auto other = trajectory_spec(s);
    ASSERT_TRUE(other.has_value()) << v.key;
    EXPECT_EQ(*other != *spec, v.changes_trajectory) << v.key << " = " << v.value;
    // operator< agrees with equality: two specs are equal iff neither orders before the other.
    EXPECT_EQ(*other < *spec || *spec < *other, v.changes_trajectory) << v.key;
  }
}

TEST(TrajectorySpec, KeepingTheSeriesDoesNotChangeIt) {
  Scene s;
  s.observe.series = true;
  EXPECT_EQ(*trajectory_spec(s), *trajectory_spec(Scene{}));
}

TEST(TrajectorySpec, StoppingAtTheFirstSlipHasNoSpec) {
  Scene s;
  set_scene_field(s, "stop_after_mu_s", "true");
  EXPECT_FALSE(trajectory_spec(s).has_value());
}

TEST(TrajectorySpec, EverySceneFieldHasAVerdict) {
  std::set<std::string> judged = {"stop_after_mu_s"};  // tested above
  for (const auto& v : kVerdicts) judged.insert(v.key);
  for (const auto& f : scene_fields())
    EXPECT_TRUE(judged.count(f.key)) << "scene field '" << f.key
                                     << "' has no verdict: does it change the trajectory?";
}

}  // namespace
