// Tests of the event-driven integrator (the exact stepper or Dormand-Prince 5(4) with located
// switching events, and an exact quiet-phase propagator). References: the closed-form
// single-block cycle, the Dormand-Prince stepper at a much tighter tolerance, and the paper's RK4
// at two step sizes. The exact stepper's own tests are in test_exact_stepper.cpp.
#include "springblock/integrate/methods/event_driven.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <future>
#include <stdexcept>
#include <thread>
#include <string>
#include <vector>

#include "forwarding_observer.hpp"
#include "hand_chain.hpp"
#include "null_observer.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene.hpp"
#include "springblock/theory.hpp"

namespace {

// The paper's default block (N = 200, L_x = 4 cm): m = 2.4 mg, K_s = 1e4 N/m, F_n = 2 N.
sb::Chain single_block(double mu_s, double mu_d) {
  sb::Chain c;
  c.N = 1;
  c.K_s = 1e4;
  c.m = 2.4e-6;
  c.v_slider = 5e-4;
  c.F_n = c.F_load = 2.0;
  c.contact = {1};
  c.mu_s = {mu_s};
  c.mu_d = {mu_d};
  c.f_static = {mu_s * c.F_n};
  c.f_kinetic = {mu_d * c.F_n};
  c.n_contact = 1;
  return c;
}

// Switching instants of a single block over three cycles at tolerance tol, and their
// largest error against the closed form, in units of the cycle period T_d + T_s. (A position
// error du made while sliding shifts the next slip onset by du / v, so onset errors are measured
// against the cycle, not against the short sliding time.)
// fast_forward = false runs the Dormand-Prince stepper; true the exact per-block solution that
// the event method uses for chains without internal springs.
double single_block_error(double tol, bool fast_forward = false) {
  const double mu_s = 1.0, mu_d = 0.3;
  const sb::Chain c = single_block(mu_s, mu_d);
  const auto cyc = sb::theory::cycle({c.m, c.K_s, c.v_slider, c.F_n}, mu_s, mu_d);
  const double t1 = mu_s * c.F_n / (c.K_s * c.v_slider);
  std::vector<double> expect;
  for (int k = 0; k < 3; ++k) {
    const double start = t1 + k * (cyc.T_d_s + cyc.T_s_s);
    expect.push_back(start);
    expect.push_back(start + cyc.T_d_s);
  }
  sb::State s = sb::State::at_rest(c);
  sb::EventDriven ev(tol, fast_forward);
  std::vector<double> log;
  ev.set_switch_log(&log);
  sbtest::NullObserver obs;
  const double t_end = expect.back() + 0.5 * cyc.T_s_s;
  ev.run(c, s, t_end, 1e-3, obs);
  EXPECT_EQ(log.size(), expect.size());
  if (log.size() != expect.size()) return 1.0;
  double worst = 0;
  const double period = cyc.T_d_s + cyc.T_s_s;
  for (std::size_t k = 0; k < log.size(); ++k) worst = std::max(worst, std::fabs(log[k] - expect[k]) / period);
  // Durations of each sliding phase against T_d.
  for (std::size_t k = 0; k < log.size(); k += 2)
    EXPECT_NEAR(log[k + 1] - log[k], cyc.T_d_s, 50 * tol * period) << "tol " << tol;
  // Rest offset: stuck after the third stop at slider position + delta_r.
  const double u_rest = c.v_slider * expect.back() + cyc.delta_r_m;
  EXPECT_NEAR(s.u[0], u_rest, 20 * tol * cyc.r0_m) << "tol " << tol;
  EXPECT_EQ(s.dir[0], 0);
  return worst;
}

TEST(EventIntegrator, SingleBlockMatchesClosedFormAndConvergesWithTol) {
  const double e6 = single_block_error(1e-6);
  const double e8 = single_block_error(1e-8);
  const double e10 = single_block_error(1e-10);
  // Observed order in the step size: h ~ tol^(1/5), so error ~ tol^(p/5).
  const double p = 5.0 * std::log10(e6 / e10) / 4.0;
  std::printf("single block: max switching-time error / period at tol 1e-6, 1e-8, 1e-10: %.3e %.3e %.3e, "
              "observed order %.2f\n", e6, e8, e10, p);
  EXPECT_LT(e6, 10 * 1e-6);
  EXPECT_LT(e10, 10 * 1e-10);
  EXPECT_GT(p, 4.0);
  // Error proportional to tol (local error h^5 with h ~ tol^(1/5)): two decades in tol should give
  // well over one decade in error, unless already at round-off.
  EXPECT_TRUE(e8 < e6 / 10 || e8 < 1e-10);
  EXPECT_TRUE(e10 < e8 / 10 || e10 < 1e-10);
}

TEST(EventIntegrator, UncoupledExactSolutionIsTheClosedFormToRoundOff) {
  // The per-block solution (K_int = 0) has no tolerance: its switching instants are the closed
  // form's to round-off of the times (~1e-16 s on cycles of ~0.1 s), whatever tol says.
  for (double tol : {1e-4, 1e-9}) {
    const double e = single_block_error(tol, true);
    std::printf("single block, exact per-block solution (tol %g unused): max error / period %.3e\n", tol, e);
    EXPECT_LT(e, 1e-12);
  }
}

// Groove chain N = 10 with pattern 3 pawls, 2 grooves; stuck blocks held by huge thresholds.
sb::Chain grooved_chain(double gamma) {
  const std::vector<std::uint8_t> contact = {1, 1, 1, 0, 0, 1, 1, 1, 0, 0};
  return sbtest::hand_chain(contact, 7.3e5, gamma, std::vector<double>(10, 1e9 / 2.0), std::vector<double>(10, 0.0));
}

TEST(EventIntegrator, QuietPhaseMatchesFineStepping) {
  for (double gamma : {1e4, 0.0, 3e7}) {  // damped, undamped, overdamped low modes
    const sb::Chain c = grooved_chain(gamma);
    sb::State s0 = sb::State::at_rest(c);
    for (int i = 0; i < c.N; ++i) s0.u[i] = 1e-5 * std::sin(1.0 + i);
    for (int i = 0; i < c.N; ++i) s0.v[i] = c.contact[i] ? 0.0 : 0.02 * std::cos(2.0 + i);
    s0.t = 0.01;
    const double T = 0.01 + 3e-5;

    sb::event_detail::RunStore q_store(c);

    sb::event_detail::QuietPhase q(c, q_store);
    EXPECT_EQ(q_store.shapes().size(), 2);  // interior groove and the groove at the chain end
    q.begin(c, s0.t, s0.u.data(), s0.v.data());
    std::vector<double> u = s0.u, v = s0.v;
    q.evaluate(T, u.data(), v.data());

    sb::State s = s0;
    sb::EventDriven fine(1e-13, false);
    sbtest::NullObserver obs;
    fine.run(c, s, T, 1.0, obs);
    ASSERT_DOUBLE_EQ(s.t, T);
    double umax = 0, vmax = 0;
    for (int i = 0; i < c.N; ++i) umax = std::max(umax, std::fabs(s.u[i])), vmax = std::max(vmax, std::fabs(s.v[i]));
    for (int i = 0; i < c.N; ++i) {
      EXPECT_NEAR(u[i], s.u[i], 1e-9 * umax) << "gamma " << gamma << " block " << i;
      EXPECT_NEAR(v[i], s.v[i], 1e-8 * vmax) << "gamma " << gamma << " block " << i;
    }
  }
}

TEST(EventIntegrator, EdgeSearchFindsFirstSlipWithRingingModes) {
  // After a slip event the grooves ring while a stuck block next to them sits just below its
  // threshold: the case where the grid march and its grazing bound matter. Reference: the same
  // chain stepped by Dormand-Prince at tol 1e-12 (no fast-forward), first switch instant.
  const sb::Chain base = grooved_chain(1e4);
  const std::vector<double> fractions = {0.02, 0.1, 0.3, 0.6, 0.9, 1.5};
  for (std::size_t n = 0; n < fractions.size(); ++n) {
    sb::Chain c = base;
    sb::State s0 = sb::State::at_rest(c);
    for (int i = 0; i < c.N; ++i) s0.u[i] = 1e-6 * std::sin(1.0 + i);
    for (int i = 0; i < c.N; ++i) s0.v[i] = c.contact[i] ? 0.0 : 0.05 * std::cos(2.0 + 3.0 * i + n);
    s0.t = 0.01;
    // Thresholds: far for blocks 0, 1, 6; blocks 2, 5, 7 (next to a groove) a fraction of the
    // groove's force swing above their present force, so the ringing decides who slips first.
    const double swing = c.K_int * 0.05 / std::sqrt((c.K_s + 4 * c.K_int) / c.m);
    for (int i = 0; i < c.N; ++i) {
      if (!c.contact[i]) continue;
      const double F = c.driving_force(i, s0.u.data(), s0.v.data(), s0.t);
      const bool edge = i == 2 || i == 5 || i == 7;
      c.f_static[i] = std::fabs(F) + (edge ? fractions[n] * swing * (1.0 + 0.1 * i) : 1.0);
      c.mu_s[i] = c.f_static[i] / c.F_n;
    }
    const double T = s0.t + 2e-3;
    sb::event_detail::RunStore q_store(c);
    sb::event_detail::QuietPhase q(c, q_store);
    q.begin(c, s0.t, s0.u.data(), s0.v.data());
    const auto next = q.next_threshold(c, T);

    sb::State s = s0;
    sb::EventDriven fine(1e-12, false);
    std::vector<double> log;
    fine.set_switch_log(&log);
    sbtest::NullObserver obs;
    fine.run(c, s, T, 1.0, obs);
    ASSERT_FALSE(log.empty()) << "fraction " << fractions[n];
    std::printf("ringing edge, margin %.2f swing: quiet search t = %.15g (block %d), DP5 1e-12 t = %.15g\n",
                fractions[n], next.t, next.block, log.front());
    EXPECT_NEAR(next.t, log.front(), 1e-10) << "fraction " << fractions[n];
  }
}

sb::Scene small_scene(int N, const char* pattern) {
  sb::Scene sc;
  sc.geometry.N = N;
  sc.geometry.L_x_m = 0.04 * N / 200.0;  // the paper's block size
  sc.pattern = sb::parse_pattern(pattern);
  sc.run.stop_after_mu_s = true;
  sc.run.duration_t0 = 2.0;
  sc.reps = 1;
  sc.seed = 3;
  return sc;
}

struct Peak {
  double mu_s, t_peak;
  std::int64_t rhs;
};

Peak first_peak(const sb::Scene& sc, sb::Integrator& integ) {
  const sb::Chain c = sb::build_chain(sc, 0);
  sb::State s = sb::State::at_rest(c);
  sb::FrictionObserverConfig cfg;
  cfg.F_load = c.F_load;
  cfg.peak_rule = sb::ExtractionRules::PeakRule::AllSlipped;  // up to the whole surface's slip: many switches
  cfg.stop_after_mu_s = true;
  sb::FrictionObserver obs(cfg);
  integ.run(c, s, sc.duration(), sc.run.sample_dt_s, obs);
  EXPECT_TRUE(obs.slipped());
  return {obs.mu_s(), obs.t_peak(), s.rhs_evals};
}

TEST(EventIntegrator, FastForwardAgreesWithStepping) {
  // The sampled mu_s jumps when a switch moves across a sample time, so the comparison is on
  // the switching instants (the stepped run at a tight tolerance, since its error accumulates
  // over the long stuck phases that the fast-forward crosses exactly) and loosely on mu_s.
  const sb::Scene sc = small_scene(40, "periodic:4,4");
  sb::EventDriven on(1e-9, true), off(1e-11, false);
  std::vector<double> log_on, log_off;
  on.set_switch_log(&log_on);
  off.set_switch_log(&log_off);
  const Peak a = first_peak(sc, on), b = first_peak(sc, off);
  std::printf("periodic:4,4 N=40: fast-forward mu_s %.12f t %.9g rhs %lld | stepping mu_s %.12f t %.9g rhs %lld\n",
              a.mu_s, a.t_peak, (long long)a.rhs, b.mu_s, b.t_peak, (long long)b.rhs);
  ASSERT_EQ(log_on.size(), log_off.size());
  ASSERT_GE(log_on.size(), 4u);
  // Measured: the stepped instants differ by 3.9e-8 s at tol 1e-9 and 4.5e-10 s at 1e-11,
  // converging linearly in tol onto the fast-forward ones (which do not move between 1e-9 and
  // 1e-11): the stepped run's error is its drift over the 0.07 s stuck phase.
  for (std::size_t k = 0; k < log_on.size(); ++k)
    EXPECT_NEAR(log_on[k], log_off[k], 1e-8 * log_on[k]) << "switch " << k;
  EXPECT_NEAR(a.mu_s, b.mu_s, 1e-4);
  EXPECT_DOUBLE_EQ(a.t_peak, b.t_peak);  // both on the same sample grid
  EXPECT_LT(a.rhs * 100, b.rhs);
}

TEST(EventIntegrator, ModalRunsAgreeWithStepping) {
  // Short runs propagated by their modes (modal_runs.hpp) against the same integrator stepping
  // every run, on one-block grooves (each groove beside a slipping pawl is a short run) with
  // damping and without. The switching instants must agree to the stepper's own accuracy: the
  // same bound as FastForwardAgreesWithStepping, whose reference is also the stepped run.
  for (const char* damping : {"damped", "undamped"}) {
    sb::Scene sc = small_scene(40, "periodic:1,1");
    if (std::string(damping) == "undamped") sc.material.gamma_per_s = 0;
    sb::EventDriven modal(1e-9, true), stepped(1e-11, true);
    modal.set_exact_stepper(false);  // the modal runs against Dormand-Prince steps
    stepped.set_exact_stepper(false);
    modal.set_modal_max_run(4);
    stepped.set_modal_max_run(0);
    stepped.set_modal_max_groove(0);
    std::vector<double> log_m, log_s;
    modal.set_switch_log(&log_m);
    stepped.set_switch_log(&log_s);
    const Peak a = first_peak(sc, modal), b = first_peak(sc, stepped);
    std::printf("periodic:1,1 N=40 %s: modal mu_s %.12f t %.9g rhs %lld | stepped mu_s %.12f t %.9g rhs %lld\n",
                damping, a.mu_s, a.t_peak, (long long)a.rhs, b.mu_s, b.t_peak, (long long)b.rhs);
    ASSERT_EQ(log_m.size(), log_s.size()) << damping;
    ASSERT_GE(log_m.size(), 4u);
    for (std::size_t k = 0; k < log_m.size(); ++k)
      EXPECT_NEAR(log_m[k], log_s[k], 1e-8 * log_m[k]) << damping << " switch " << k;
    EXPECT_NEAR(a.mu_s, b.mu_s, 1e-4) << damping;
    EXPECT_LT(a.rhs, b.rhs) << damping;  // the modal runs take no steps
  }
}

TEST(EventIntegrator, ModalGrooveRunsAgreeWithStepping) {
  // Ringing grooves of 9 and 12 blocks propagated by their modes while pawls elsewhere slide
  // (modal_max_groove), against stepping them. Undamped, so the grooves keep ringing and every
  // crossing of a pawl edge beside one is searched on 9 or 12 live modes. Runs holding a contact
  // block are stepped in both, to isolate the groove runs. Same bound as
  // ModalRunsAgreeWithStepping: the reference's own accuracy. (Larger undamped chains are
  // chaotic before the first peak: their peaks move by 1e-3 between tolerances of either
  // method, so they cannot serve here.)
  for (const char* pattern : {"periodic:3,9", "periodic:4,12"}) {
    sb::Scene sc = small_scene(48, pattern);
    sc.material.gamma_per_s = 0;
    sb::EventDriven modal(1e-9, true), stepped(1e-9, true), reference(1e-11, true);
    modal.set_modal_max_run(0);
    modal.set_modal_max_groove(32);
    for (sb::EventDriven* e : {&modal, &stepped, &reference}) e->set_exact_stepper(false);  // Dormand-Prince steps
    for (sb::EventDriven* e : {&stepped, &reference}) {
      e->set_modal_max_run(0);
      e->set_modal_max_groove(0);
    }
    std::vector<double> log_m, log_r;
    modal.set_switch_log(&log_m);
    reference.set_switch_log(&log_r);
    const Peak a = first_peak(sc, modal), b = first_peak(sc, stepped), r = first_peak(sc, reference);
    std::printf("%s N=48 undamped: modal grooves mu_s %.12f rhs %lld | stepped mu_s %.12f rhs %lld | reference %.12f\n",
                pattern, a.mu_s, (long long)a.rhs, b.mu_s, (long long)b.rhs, r.mu_s);
    ASSERT_EQ(log_m.size(), log_r.size()) << pattern;
    ASSERT_GE(log_m.size(), 20u);
    for (std::size_t k = 0; k < log_m.size(); ++k)
      EXPECT_NEAR(log_m[k], log_r[k], 1e-8 * log_m[k]) << pattern << " switch " << k;
    EXPECT_NEAR(a.mu_s, r.mu_s, 1e-4) << pattern;
    EXPECT_LT(a.rhs, b.rhs) << pattern;  // same tolerance: the groove runs took no steps
  }
}

// One scene (periodic:4,16, N = 120, 3 t0, after loading too) run twice by the event method,
// each run with its own observer: the switching logs and end states of both.
struct PairedRuns {
  sb::Scene sc;
  sb::Chain c;
  sb::FrictionObserverConfig cfg;
  std::vector<double> log[2];
  sb::State state[2];
  PairedRuns() : sc(small_scene(120, "periodic:4,16")) {
    sc.run.stop_after_mu_s = false;
    sc.run.duration_t0 = 3.0;
    c = sb::build_chain(sc, 0);
    cfg.F_load = c.F_load;
    cfg.peak_rule = sb::ExtractionRules::PeakRule::AllSlipped;  // up to the whole surface's slip: many switches
    cfg.mu_d_skip_s = 0.25 * sc.t0_s();
  }
  void run(sb::Observer& a, sb::Observer& b) {
    sb::Observer* obs[2] = {&a, &b};
    for (int k = 0; k < 2; ++k) {
      sb::EventDriven e(1e-9);
      e.set_switch_log(&log[k]);
      state[k] = sb::State::at_rest(c);
      e.run(c, state[k], sc.duration(), sc.run.sample_dt_s, *obs[k]);
    }
  }
};

// The same friction observer, but asking for every groove row: quiet-phase samples then keep
// the groove modes to round-off instead of dropping them below the settle scales.
class EveryRow final : public sb::Observer {
 public:
  explicit EveryRow(sb::FrictionObserver& inner) : inner_(inner) {}
  void sample(const sb::Chain& c, const sb::State& s) override { inner_.sample(c, s); }
  bool wants_stop() const override { return inner_.wants_stop(); }
  bool reads_groove_interiors() const override { return true; }

 private:
  sb::FrictionObserver& inner_;
};

TEST(EventIntegrator, SampleScalesChangeNoResult) {
  // Samples for a contact-force observer drop a quiet phase's groove modes once they are below
  // the settle scales (QuietPhase::set_sample_scales); the dynamics keeps them, so the switching
  // history must be identical. A dropped transient is at most eps_u per groove end when dropped
  // and decays after, so the sampled mu_s and mu_d must stay within 1e-3 of the stepper's
  // tolerance (1e-12) of the samples that keep it (measured: equal to all 15 digits; scales
  // 1e6 times larger move mu_d by 5e-11 and fail).
  PairedRuns p;
  sb::FrictionObserver dropped(p.cfg), kept(p.cfg);
  EveryRow every(kept);
  p.run(dropped, every);
  const std::vector<double>& log1 = p.log[0];
  const std::vector<double>& log2 = p.log[1];
  std::printf("periodic:4,16 N=120 3 t0: mu_s %.15f / %.15f  mu_d %.15f / %.15f  window %zu / %zu\n",
              dropped.mu_s(), kept.mu_s(), dropped.mu_d(), kept.mu_d(), dropped.window_samples(),
              kept.window_samples());
  ASSERT_TRUE(dropped.slipped());
  EXPECT_EQ(log1, log2);
  EXPECT_NEAR(dropped.mu_s(), kept.mu_s(), 1e-12);
  EXPECT_NEAR(dropped.mu_d(), kept.mu_d(), 1e-12);
  EXPECT_EQ(dropped.window_samples(), kept.window_samples());
  EXPECT_EQ(dropped.t_peak(), kept.t_peak());
}

// The same friction observer declining every block of quiet-phase samples offered as sums, so
// that each of them is served one by one.
using OneByOne = sbtest::Forwarding;

TEST(EventIntegrator, SummedSampleBlocksEqualTheSamplesOneByOne) {
  // During loading, stretches of quiet-phase samples are taken from bounds on the friction sums
  // (QuietPhase::envelope), looking only at the samples that may hold the peak. After loading, blocks of quiet-phase samples reach the mu_d window as closed-form sums over
  // the modes (QuietPhase::window_sums). Against the same run serving them one by one: the same
  // switching history (samples never act on the dynamics), mu_s and the window count exactly,
  // mu_d to round-off: the sums of up to 64 samples are rounded differently. Measured on ten
  // seeds of this scene, before and after short runs were first stepped (paper/choices.md):
  // up to 1.5e-14 relative (1.1e-14 for the signed sum), so the bound is 1e-13; a sample
  // dropped or counted twice moves mu_d by (mu - mu_d) / window_samples, far above that.
  PairedRuns p;
  sb::FrictionObserver summed(p.cfg), single(p.cfg);
  OneByOne one(single);
  p.run(summed, one);
  const sb::State& s1 = p.state[0];
  const sb::State& s2 = p.state[1];
  const std::vector<double>& log1 = p.log[0];
  const std::vector<double>& log2 = p.log[1];
  ASSERT_TRUE(summed.slipped());
  EXPECT_GT(s1.work.summed_samples, 1000);  // the blocks were taken
  EXPECT_GT(s1.work.peak_samples, 1000);    // and the loading stretches
  EXPECT_EQ(s2.work.summed_samples + s2.work.peak_samples, 0);
  EXPECT_EQ(s1.work.samples + s1.work.stretch_samples + s1.work.summed_samples + s1.work.peak_samples,
            s2.work.samples + s2.work.stretch_samples);
  EXPECT_EQ(log1, log2);
  // Loading stretches look only at the samples their bounds leave: the peak, its time and the
  // signed peak are still those of every sample, bit for bit.
  EXPECT_EQ(summed.mu_s(), single.mu_s());
  EXPECT_EQ(summed.t_peak(), single.t_peak());
  EXPECT_EQ(summed.mu_s_signed(), single.mu_s_signed());
  EXPECT_EQ(summed.window_samples(), single.window_samples());
  EXPECT_NEAR(summed.mu_d(), single.mu_d(), 1e-13 * single.mu_d());
  EXPECT_NEAR(summed.mu_d_signed(), single.mu_d_signed(), 1e-13 * std::fabs(single.mu_d_signed()));
}

TEST(EventIntegrator, CreepingBlocksInModalRunsDoNotStutter) {
  // With (mu_d)_m = 0.9 and the clip policy about one block in six has mu_d = mu_s: once it
  // slides it creeps, and without damping its velocity touches zero once per period. The modal
  // runs do not stop it at such touches (dir v must fall below -1e-12 v_s), which is what keeps
  // the undamped case cheap; the first peak must not move by more than the stepper's accuracy.
  sb::Scene sc = small_scene(40, "smooth");
  sc.material.gamma_per_s = 0;
  sc.friction.mu_d_mean = 0.9;
  sb::EventDriven modal(1e-9, true), stepped(1e-11, true);
  modal.set_exact_stepper(false);  // the modal runs against Dormand-Prince steps
  stepped.set_exact_stepper(false);
  modal.set_modal_max_run(2);
  stepped.set_modal_max_run(0);
  stepped.set_modal_max_groove(0);
  const Peak a = first_peak(sc, modal), b = first_peak(sc, stepped);
  std::printf("smooth N=40 r=0.9 undamped: modal mu_s %.12f t %.9g | stepped mu_s %.12f t %.9g\n", a.mu_s,
              a.t_peak, b.mu_s, b.t_peak);
  EXPECT_NEAR(a.mu_s, b.mu_s, 1e-4);
}

TEST(EventIntegrator, FirstPeakWithinRk4ConvergenceTrend) {
  const sb::Scene sc = small_scene(40, "smooth");
  sb::EventDriven ev(1e-10);
  sb::Rk4 coarse(1e-7), fine(2.5e-8);
  const Peak e = first_peak(sc, ev), r1 = first_peak(sc, coarse), r2 = first_peak(sc, fine);
  std::printf("smooth N=40 first peak: event %.12f @ %.9g | rk4 1e-7 %.12f @ %.9g | rk4 2.5e-8 %.12f @ %.9g\n",
              e.mu_s, e.t_peak, r1.mu_s, r1.t_peak, r2.mu_s, r2.t_peak);
  // RK4 resolves switching to one step (first order): its error shrinks ~4x from 1e-7 to 2.5e-8,
  // so the event result must be closer to the fine RK4 than the coarse one is, within the
  // remaining first-order distance.
  const double d_coarse = std::fabs(r1.mu_s - e.mu_s), d_fine = std::fabs(r2.mu_s - e.mu_s);
  EXPECT_LE(d_fine, std::max(d_coarse, 1e-9) * 1.0 + 1e-9);
  EXPECT_LT(d_fine, 2.0 * std::fabs(r1.mu_s - r2.mu_s) + 1e-6);
  EXPECT_NEAR(e.t_peak, r2.t_peak, 2e-5);  // one sample of 1e-5 either way
}

TEST(EventIntegrator, CascadeIsReportedNotHung) {
  // Kinetic friction above the static threshold: a block that reaches its threshold cannot
  // move and cannot stay stuck.
  sb::Chain c = single_block(0.5, 1.0);
  auto task = std::async(std::launch::async, [c] {
    sb::State s = sb::State::at_rest(c);
    sb::EventDriven ev(1e-9);
    sbtest::NullObserver obs;
    try {
      ev.run(c, s, 0.3, 1e-3, obs);
      return std::string("ran, switches ") + std::to_string(s.switches);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
  });
  ASSERT_EQ(task.wait_for(std::chrono::seconds(5)), std::future_status::ready) << "integrator hung";
  const std::string what = task.get();
  std::printf("cascade case: %s\n", what.c_str());
  EXPECT_NE(what.find("switching cascade"), std::string::npos);
}

}  // namespace
