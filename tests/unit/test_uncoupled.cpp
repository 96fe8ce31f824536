// Tests of the exact per-block solution for chains without internal springs (K_int = 0),
// against the Dormand-Prince stepper at a tight tolerance (the event method with fast-forward
// off), and its handling of creeping blocks (mu_d clipped to mu_s), which have no second event.
#include "springblock/integrate/methods/uncoupled.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hand_chain.hpp"
#include "null_observer.hpp"
#include "springblock/integrate/methods/event_driven.hpp"

namespace {

// Records every sample's friction sum, reading only friction forces (so the exact solver may
// leave moving blocks unevaluated) or everything (so it must evaluate them).
class SumObserver final : public sb::Observer {
 public:
  explicit SumObserver(bool friction_only) : friction_only_(friction_only) {}
  void sample(const sb::Chain& c, const sb::State& s) override {
    double sum = 0, usum = 0;
    for (int i = 0; i < c.N; ++i) {
      sum += std::fabs(sb::friction_force(c, s, i));
      usum += s.u[i];
    }
    mu.push_back(sum);
    u_sum.push_back(usum);
  }
  bool reads_only_friction() const override { return friction_only_; }
  std::vector<double> mu, u_sum;

 private:
  bool friction_only_;
};

// Eight blocks of the paper's size: one groove (3), one creeping pair (5: mu_d = mu_s), one
// deep drop (6: mu_d = 0.1), the others spread around mu_s = 1, mu_d = 0.5.
sb::Chain uncoupled(double gamma) {
  return sbtest::hand_chain({1, 1, 1, 0, 1, 1, 1, 1}, 0.0, gamma, {1.0, 0.93, 1.12, 0, 0.87, 0.95, 1.05, 0.99},
                            {0.5, 0.47, 0.55, 0, 0.52, 0.95, 0.1, 0.3});
}

sb::State start(const sb::Chain& c) {
  sb::State s = sb::State::at_rest(c);
  s.u[3] = 2e-6;  // the groove block starts off its path: a transient to carry
  s.v[3] = -1e-3;
  return s;
}

TEST(Uncoupled, MatchesTheStepperAtTightTolerance) {
  for (double gamma : {1e4, 0.0}) {
    const sb::Chain c = uncoupled(gamma);
    const double T = 1.3;  // about three stick-slip cycles of the typical block
    sb::State a = start(c), b = start(c);
    std::vector<double> log_a, log_b;
    sb::EventDriven exact(1e-9, true), stepped(1e-12, false);
    exact.set_switch_log(&log_a);
    stepped.set_switch_log(&log_b);
    SumObserver oa(false), ob(false);
    // A sample spacing incommensurate with the round thresholds above, so that no slip lands on
    // a sample time (where the order of sample and switch would be decided by one ulp).
    const double dt = 1.2345678e-3;
    exact.run(c, a, T, dt, oa);
    stepped.run(c, b, T, dt, ob);
    std::printf("gamma %g: exact %zu switch instants, %lld evals | stepped %zu, %lld rhs evals\n", gamma,
                log_a.size(), (long long)a.rhs_evals, log_b.size(), (long long)b.rhs_evals);
    ASSERT_EQ(log_a.size(), log_b.size()) << "gamma " << gamma;
    // The stepper's error in a switching time grows over the run (position errors shift the
    // next slip by du / v); at tol 1e-12 it stays below 1e-9 s.
    for (std::size_t k = 0; k < log_a.size(); ++k) EXPECT_NEAR(log_a[k], log_b[k], 1e-9) << "instant " << k;
    // Error budget of the stepper: its local errors (<= atol per accepted step, atol_u = tol F_n /
    // K_s, atol_v = omega_s atol_u) add up at most linearly over its steps (~rhs evals / 6).
    // Without damping nothing decays, so the groove and the creeping block carry all of it.
    const double steps = b.rhs_evals / 6.0, atol_u = 1e-12 * c.F_n / c.K_s;
    const double budget_u = steps * atol_u, budget_v = steps * atol_u * std::sqrt(c.K_s / c.m);
    double du = 0, dv = 0;
    for (int i = 0; i < c.N; ++i) {
      EXPECT_EQ(a.dir[i], b.dir[i]) << "block " << i;
      du = std::max(du, std::fabs(a.u[i] - b.u[i]));
      dv = std::max(dv, std::fabs(a.v[i] - b.v[i]));
    }
    std::printf("  final state: max |du| %.2e m (budget %.2e), max |dv| %.2e m/s (budget %.2e)\n", du, budget_u,
                dv, budget_v);
    EXPECT_LT(du, budget_u);
    EXPECT_LT(dv, budget_v);
    ASSERT_EQ(oa.mu.size(), ob.mu.size());
    for (std::size_t k = 0; k < oa.mu.size(); ++k) {
      EXPECT_NEAR(oa.mu[k], ob.mu[k], c.N * c.K_s * budget_u) << "sample " << k;
      EXPECT_NEAR(oa.u_sum[k], ob.u_sum[k], c.N * budget_u) << "sample " << k;
    }
  }
}

TEST(Uncoupled, FrictionOnlyObserverSeesTheSameFriction) {
  const sb::Chain c = uncoupled(1e4);
  sb::State a = start(c), b = start(c);
  SumObserver full(false), lean(true);
  sb::EventDriven ev(1e-9, true);
  ev.run(c, a, 1.0, 1e-4, full);
  ev.run(c, b, 1.0, 1e-4, lean);
  ASSERT_EQ(full.mu.size(), lean.mu.size());
  for (std::size_t k = 0; k < full.mu.size(); ++k) EXPECT_EQ(full.mu[k], lean.mu[k]) << "sample " << k;
  // The final state is evaluated either way.
  for (int i = 0; i < c.N; ++i) EXPECT_EQ(a.u[i], b.u[i]);
}

TEST(Uncoupled, CreepingBlockHasNoSecondEvent) {
  // mu_d = mu_s with damping: released at its threshold, the block settles into steady sliding
  // at the slider's speed (the damped transient never brings v back to 0), so after its slip
  // nothing happens however long the run. The stepper, by contrast, must step it throughout.
  sb::Chain c = uncoupled(1e4);
  c.N = 1;
  c.contact = {1};
  c.n_contact = 1;
  c.mu_s = {0.9};
  c.mu_d = {0.9};
  c.f_static = {1.8};
  c.f_kinetic = {1.8};
  c.F_load = 2.0;
  sb::State s = sb::State::at_rest(c);
  sbtest::NullObserver obs;
  std::vector<double> log;
  sb::EventDriven ev(1e-9, true);
  ev.set_switch_log(&log);
  ev.run(c, s, 50.0, 1e-3, obs);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NEAR(log[0], 1.8 / (c.K_s * c.v_slider), 1e-15);
  EXPECT_EQ(s.dir[0], 1);
  EXPECT_NEAR(s.v[0], c.v_slider, 1e-12);  // the transient has long died
  // Steady sliding: the spring pulls exactly kinetic friction plus the damping force.
  EXPECT_NEAR(c.K_s * (c.v_slider * s.t - s.u[0]), c.f_kinetic[0] + c.m * c.gamma * c.v_slider, 1e-9);
}

TEST(Uncoupled, CascadeIsReported) {
  // f_kin > f_static, built by hand (build_chain raises the threshold): the released block can
  // neither move nor stay stuck; the guard reports it instead of spinning.
  sb::Chain c = uncoupled(1e4);
  c.f_kinetic[1] = 3.0;  // f_static[1] = 1.86
  sb::State s = sb::State::at_rest(c);
  sbtest::NullObserver obs;
  sb::EventDriven ev(1e-9, true);
  EXPECT_THROW(ev.run(c, s, 1.0, 1e-3, obs), std::runtime_error);
}

}  // namespace
