#pragma once
// Shared helpers of the stability suite: scenes scaled for short runs, an observer that checks
// the stick/slip invariants at every sample, and integrator creation that skips (rather than
// fails) methods not built yet, so every test covers a new integrator as soon as it lands.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "springblock/energy.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/scene.hpp"
#include "springblock/errors.hpp"

namespace sbtest {

// All methods the suite runs over.
inline const auto kMethods = ::testing::Values(sb::Method::RK4, sb::Method::Event);
inline std::string method_label(const ::testing::TestParamInfo<sb::Method>& info) {
  return sb::method_name(info.param);
}

// Integrator for `rc`, or nullptr with the reason in `why` if this build lacks it.
inline std::unique_ptr<sb::Integrator> try_make(const sb::RunControl& rc, std::string& why) {
  try {
    return sb::make_integrator(rc);
  } catch (const std::exception& e) {
    why = e.what();
    return nullptr;
  }
}

// Declares `var` or skips the test with the reason (GTEST_SKIP must run in the test body).
#define SB_INTEGRATOR_OR_SKIP(var, rc)                                                         \
  std::string var##_why;                                                                      \
  auto var = ::sbtest::try_make((rc), var##_why);                                             \
  if (!var) GTEST_SKIP() << "method '" << sb::method_name((rc).method)                        \
                         << "' is not available in this build: " << var##_why

// The paper's parameters with a 100x faster slider: a stick phase then lasts ~1e-2 s instead of
// ~1 s, so a run covers several stick-slip cycles in a fraction of a second while the slider is
// still slow against the slip velocity (v / (A omega_s) ~ 1e-2).
inline sb::Scene base_scene(sb::Method method, int N = 50) {
  sb::Scene s;
  s.geometry.N = N;
  s.material.v_m_per_s = 5e-2;
  s.run.method = method;
  s.run.dt_s = std::min(1e-7, 0.25 * sb::rk4_stable_dt(s.derived()));
  s.run.sample_dt_s = s.run.dt_s;
  s.run.tol = 1e-10;
  s.reps = 1;
  return s;
}

// Checks, at every sample: finite state; stuck blocks have v == 0 exactly and a static
// friction within mu_s,i F_n up to roundoff; groove blocks never carry a sliding direction.
// And at every switch: the shortest time between two instants at which one block switched
// (a block that stutters, stopped and restarted by round-off, switches again a few ulp later).
class InvariantObserver final : public sb::Observer {
 public:
  long samples = 0, nonfinite = 0, stuck_moving = 0, groove_sliding = 0, over_threshold = 0;
  double max_excess = 0;  // max (|f| - mu_s F_n) / (mu_s F_n) over stuck blocks
  double max_abs_u = 0, max_abs_v = 0;
  double min_switch_interval = std::numeric_limits<double>::infinity();

  void switched(const sb::Chain& c, const sb::State& s, sb::SwitchedBlocks blocks) override {
    if (last_switch_.empty()) last_switch_.assign(static_cast<std::size_t>(c.N), -1.0);
    for (int i : blocks) {
      double& last = last_switch_[static_cast<std::size_t>(i)];
      if (last >= 0 && s.t > last) min_switch_interval = std::min(min_switch_interval, s.t - last);
      last = s.t;
    }
  }

  void sample(const sb::Chain& c, const sb::State& s) override {
    ++samples;
    for (int i = 0; i < c.N; ++i) {
      if (!std::isfinite(s.u[i]) || !std::isfinite(s.v[i])) ++nonfinite;
      max_abs_u = std::max(max_abs_u, std::fabs(s.u[i]));
      max_abs_v = std::max(max_abs_v, std::fabs(s.v[i]));
      if (!c.contact[i]) {
        groove_sliding += s.dir[i] != 0;
        continue;
      }
      if (s.dir[i] != 0) continue;
      if (s.v[i] != 0.0) ++stuck_moving;
      const double f = std::fabs(sb::friction_force(c, s, i));
      const double excess = (f - c.f_static[i]) / c.f_static[i];
      max_excess = std::max(max_excess, excess);
      // Roundoff allowance: a few ulps of the largest force term that enters the sum.
      if (excess > kRoundoff) ++over_threshold;
    }
  }
  static constexpr double kRoundoff = 1e-12;

 private:
  std::vector<double> last_switch_;  // per block, the last instant it switched (-1: none)
};

// Shows every sample to several observers.
class FanOut final : public sb::Observer {
 public:
  explicit FanOut(std::vector<sb::Observer*> obs) : obs_(std::move(obs)) {}
  void sample(const sb::Chain& c, const sb::State& s) override {
    for (auto* o : obs_) o->sample(c, s);
  }
  void switched(const sb::Chain& c, const sb::State& s, sb::SwitchedBlocks blocks) override {
    for (auto* o : obs_) o->switched(c, s, blocks);
  }

 private:
  std::vector<sb::Observer*> obs_;
};

struct CaseResult {
  sb::EnergyBudget energy;
  InvariantObserver inv;
  sb::State state;
};

// Runs `chain` from `state` to t_end under both observers.
inline CaseResult run_case(sb::Integrator& integ, const sb::Chain& chain, sb::State state,
                           double t_end, double sample_dt) {
  CaseResult r;
  sb::EnergyObserver energy;
  FanOut fan({&energy, &r.inv});
  integ.run(chain, state, t_end, sample_dt, fan);
  r.energy = energy.budget();
  r.state = std::move(state);
  return r;
}

// The invariants every case must keep, whatever the physics.
inline void expect_invariants(const CaseResult& r, const sb::Chain& c) {
  EXPECT_GT(r.inv.samples, 1);
  EXPECT_EQ(r.inv.nonfinite, 0) << "NaN or Inf in the state";
  EXPECT_EQ(r.inv.stuck_moving, 0) << "a stuck block has a nonzero velocity";
  EXPECT_EQ(r.inv.groove_sliding, 0) << "a groove block carries a sliding direction";
  EXPECT_EQ(r.inv.over_threshold, 0) << "static friction above mu_s F_n by " << r.inv.max_excess;
  for (int i = 0; i < c.N; ++i) {
    ASSERT_TRUE(std::isfinite(r.state.u[i]) && std::isfinite(r.state.v[i])) << "block " << i;
  }
}

}  // namespace sbtest

namespace sb {
// Readable parameter names in CTest ("... /rk4  # GetParam() = rk4").
inline void PrintTo(Method m, std::ostream* os) { *os << method_name(m); }
}  // namespace sb
