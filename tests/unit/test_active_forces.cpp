// Samples of an active phase taken from the forces the event method knows (Observer::sample_active:
// affine and sliding forces summed in a tree kept from sample to sample, only the live blocks read
// from the state) against the same trajectory sampled from the positions (sample()): the same
// times and sliding counts, mu to round-off, on every kind of run the active set makes (settled,
// modal and stepped grooves, modal and stepped slips, per-block chains, both steppers). And the
// bookkeeping of KnownForces itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/integrate/events/known_forces.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene_fields.hpp"
#include "forwarding_observer.hpp"

using namespace sb;

namespace {

// Everything to a FrictionObserver, counting what the known forces offered, and refusing the
// stretches as the plain PerSample does, so that the two see the same samples one by one.
// Positions only where the observer needs them, so an active-phase sample gets only what its live
// blocks read (ActiveSet::materialise_live), and a quiet phase's samples the forces it knows.
class Counting final : public sbtest::Forwarding {
 public:
  using Forwarding::Forwarding;
  long sample_affine(const Chain&, const State&, long, double, long, const AffineForces&) override { return 0; }
  bool takes_active_forces() const override { return true; }
  void sample_active(const Chain& c, const State& s, const ActiveForces& f) override {
    ++active;
    times.push_back(s.t);
    with_live += !f.live.empty();
    with_changes += !f.changed.empty() && !f.all_changed;
    inner_.sample_active(c, s, f);
  }
  long active = 0, with_live = 0, with_changes = 0;
  std::vector<double> times;  // of the samples from the known forces, in order
};

Scene scene(const std::string& pattern, int N, const std::string& stepper = "exact") {
  Scene s;
  set_scene_field(s, "N", std::to_string(N));
  set_scene_field(s, "length", std::to_string(0.02 * N) + "cm");
  set_scene_field(s, "pattern", pattern);
  set_scene_field(s, "method", "event");
  set_scene_field(s, "stepper", stepper);
  set_scene_field(s, "duration", "2t0");
  s.seed = 11;
  return s;
}

void expect_known_forces_give_the_positions_mu(const Scene& sc) {
  const Chain c = build_chain(sc, 0);
  FrictionObserver known(sbtest::series_config(c)), plain(sbtest::series_config(c));
  Counting counting(known);
  sbtest::PerSample from_positions(plain);
  const State s1 = sbtest::run_from_rest(sc, c, counting), s2 = sbtest::run_from_rest(sc, c, from_positions);
  EXPECT_EQ(s1.switches, s2.switches);  // the observer does not change the trajectory
  const auto &a = known.series(), &b = plain.series();
  ASSERT_EQ(a.size(), b.size());
  // The samples from the known forces, to round-off of sums of up to N forces of order F_n each
  // in a different order. (The quiet phases' samples come from their own closed forms in the one
  // and from the positions in the other; their agreement is test_quiet_sums' and
  // test_observation_invariance's to check.)
  std::size_t next = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].t, b[k].t) << k;
    ASSERT_EQ(a[k].n_sliding, b[k].n_sliding) << "sample " << k << " t " << a[k].t;
    if (next == counting.times.size() || counting.times[next] != a[k].t) continue;
    ++next;
    const double tol = 1e-12 * std::max(1.0, std::fabs(b[k].mu));
    ASSERT_NEAR(a[k].mu, b[k].mu, tol) << "sample " << k << " t " << a[k].t;
    ASSERT_NEAR(a[k].mu_signed, b[k].mu_signed, tol) << "sample " << k << " t " << a[k].t;
  }
  EXPECT_EQ(next, counting.times.size());  // every sample from the known forces is in the series
  // Not vacuous: many samples came from the known forces, some with live blocks read from the
  // state and some after changes since the previous one.
  EXPECT_GT(counting.active, 1000);
  EXPECT_GT(counting.with_live, 0);
  EXPECT_GT(counting.with_changes, 0);
}

}  // namespace

TEST(ActiveForces, PeriodicGroovesSettledAndModal) { expect_known_forces_give_the_positions_mu(scene("periodic:10,10", 400)); }

TEST(ActiveForces, PeriodicDormandPrince) {
  expect_known_forces_give_the_positions_mu(scene("periodic:10,10", 400, "dopri5"));
}

TEST(ActiveForces, Hierarchical) { expect_known_forces_give_the_positions_mu(scene("hierarchical:8,2", 400)); }

TEST(ActiveForces, Smooth) { expect_known_forces_give_the_positions_mu(scene("smooth", 200)); }

TEST(ActiveForces, RandomSurface) { expect_known_forces_give_the_positions_mu(scene("random:0.6", 300)); }

// A chain whose blocks differ: graded micro mu_s and composite springs and masses.
TEST(ActiveForces, PerBlockChain) {
  Scene s = scene("periodic:5,5", 200);
  std::vector<double> scale(200), k_s(200);
  for (int i = 0; i < 200; ++i) {
    const bool hard = (i / 7) % 2 == 1;
    scale[i] = hard ? 2.0 : 0.5;
    k_s[i] = hard ? 1.2 : 0.8;
  }
  s.materials.columns[index_of(BlockField::KIntScale)] = scale;
  s.materials.columns[index_of(BlockField::MassScale)] = scale;
  s.materials.columns[index_of(BlockField::KsScale)] = k_s;
  s.materials.segments.push_back({BlockField::MuS, 0, -1, true, 0, 0.8, 1.2});
  s.materials.source = "test: graded composite";
  validate(s);
  expect_known_forces_give_the_positions_mu(s);
}

// A stress snapshot needs every position at its sample: the integrator writes them all there and
// still serves the sample from the known forces, so the statistics do not depend on it.
TEST(ActiveForces, SnapshotsChangeNoStatistic) {
  Scene plain = scene("periodic:10,10", 400);
  plain.reps = 2;
  plain.threads = 1;
  Scene stressed = plain;
  stressed.observe.stress_times_s = {0.3 * plain.duration(), 0.7 * plain.duration()};
  const auto a = run_ensemble(plain), b = run_ensemble(stressed);
  for (std::size_t r = 0; r < a.runs.size(); ++r) {
    EXPECT_EQ(a.runs[r].mu_s, b.runs[r].mu_s) << r;
    EXPECT_EQ(a.runs[r].mu_d, b.runs[r].mu_d) << r;
    EXPECT_EQ(a.runs[r].t_peak_s, b.runs[r].t_peak_s) << r;
  }
  ASSERT_EQ(b.runs[0].stress.size(), 2u);
}

TEST(KnownForces, ListsLiveBlocksAndChanges) {
  event_detail::KnownForces k(6);
  // Before the first delivery every block counts as changed, and none is listed.
  k.affine(1, 2.0, 3.0);
  k.live(2);
  k.live(4);
  k.sliding(5, -0.5);
  ActiveForces v = k.view();
  EXPECT_TRUE(v.all_changed);
  EXPECT_TRUE(v.changed.empty());
  EXPECT_EQ(v.kind[1], ActiveForces::kAffine);
  EXPECT_EQ(v.a[1], 2.0);
  EXPECT_EQ(v.b[1], 3.0);
  EXPECT_EQ(v.kind[5], ActiveForces::kSliding);
  EXPECT_EQ(v.a[5], -0.5);
  EXPECT_EQ(v.kind[0], ActiveForces::kNone);
  std::vector<int> live(v.live.begin(), v.live.end());
  std::sort(live.begin(), live.end());
  EXPECT_EQ(live, (std::vector<int>{2, 4}));
  k.delivered();
  // A live block that becomes affine leaves the live list; each change is listed once.
  k.affine(2, 1.0, 0.0);
  k.affine(2, 1.5, 0.0);
  k.live(3);
  ActiveForces w = k.view();
  EXPECT_FALSE(w.all_changed);
  EXPECT_EQ(w.changed, (std::vector<int>{2, 3}));
  live.assign(w.live.begin(), w.live.end());
  std::sort(live.begin(), live.end());
  EXPECT_EQ(live, (std::vector<int>{3, 4}));
  k.delivered();
  EXPECT_TRUE(k.view().changed.empty());
}
