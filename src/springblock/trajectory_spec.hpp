#pragma once
// What a scene's repetitions simulate, apart from what is read off them.
//
// Two scenes with equal specs run the same chains through the same integrator with the same
// sample grid, so repetition r of one is, up to its run length, repetition r of the other: the
// ensemble simulates such scenes once and observes the run once per scene (observe/fan_out.hpp).
// The spec holds exactly the scene inputs the trajectories depend on; each member says why.
// Left out, because they change only what is recorded or read off mu(t), not the motion:
//   duration        no integrator's path up to a time t depends on where the run will end, so a
//                   shorter run is a prefix of the longest (the group runs the longest);
//   rules           peak_rule, peak_drop, mu_d_skip: how mu_s and mu_d are read off mu(t);
//   observe         the mu(t) series and stress snapshots kept for repetition 0, slip events;
//   threads         repetition r draws from rep_seed(seed, r) on whichever thread runs it.
// stop_after_mu_s is not a member: such a run ends when its own observer sees the first slip, so
// its length is not the scene's to state, and it has no spec (it is never shared).
#include <cstdint>
#include <optional>
#include <string>

#include "springblock/parameters.hpp"
#include "springblock/run_control.hpp"
#include "springblock/surface.hpp"

namespace sb {

struct Scene;

struct TrajectorySpec {
  // The chain's K_s, K_int, m, F_load (derive()), damping gamma and slider velocity v.
  MaterialParameters material;
  ChainGeometry geometry;
  double k_int_scale = 1.0;
  // The micro coefficients mu_s,i and mu_d,i drawn per block, and the pair policy applied to them.
  FrictionDistribution friction;
  // The per-block fields (contact, friction, springs, masses) by the hash of their values.
  std::string materials_hash;
  // Which blocks touch: the pattern and its layout rule give the mask (random ones draw it from
  // the repetition's seed; a mask pattern holds it).
  PatternSpec pattern;
  // Repetition r draws from rep_seed(seed, r). The number of repetitions is part of the spec
  // because scenes share repetition by repetition: a group runs its leader's repetitions.
  std::uint64_t seed = 1;
  int reps = 0;
  // The integrator, as make_integrator builds it from RunControl. Every setting is kept, even one
  // the chosen method does not read (tol for RK4, dt for the event method): which settings a
  // method reads is the integrator's business, and a needless difference only costs a second run.
  Method method = Method::Event;
  double dt_s = 0, tol = 0;
  int modal_max_run = 0, modal_max_groove = 0;
  Stepper stepper = Stepper::Exact;
  int exact_max_run = 0;
  // The sample times are points the event method steps to and where RK4's stride lands, and the
  // FanOut hands the same grid to every view.
  double sample_dt_s = 0;
};

// The spec of a scene's trajectories, or none when its run length depends on what it observes
// (stop_after_mu_s).
std::optional<TrajectorySpec> trajectory_spec(const Scene& s);

// Member by member, doubles compared exactly (validated scenes hold no NaN). operator< is a
// strict weak order over the same members, so specs can key a map.
bool operator==(const TrajectorySpec& a, const TrajectorySpec& b);
bool operator!=(const TrajectorySpec& a, const TrajectorySpec& b);
bool operator<(const TrajectorySpec& a, const TrajectorySpec& b);

}  // namespace sb
