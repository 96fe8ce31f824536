// Hard cases for every integrator: extreme coefficients, stiffness ratios, chain sizes,
// damping and slider speeds, hand-made initial states. Each case checks the invariants
// (finite state, stuck blocks motionless and within their static threshold, groove blocks never
// sliding, bounded switching) and the energy balance
//   work of the slider springs = change of kinetic + elastic energy + friction + damping losses.
//
// Tolerances of the energy balance. The trapezoid bookkeeping at sample_dt = h contributes
// ~ (omega_max h)^2 / 12 relative at worst (<= 5e-3 here, far less in practice since the
// highest modes carry little energy). The dominant error is RK4's switching rule: contact phases
// are frozen over a step and a block that stops within a step is set to v = 0 at its end, so
// each stop misplaces O(h) of friction work; relative to a slip's dissipation that is
// O(h / T_slip) ~ 1e-3 with ~1000 steps per slip. The measured errors are printed per case.
#include <cstdio>

#include "stability_support.hpp"

namespace {

using sbtest::CaseResult;

class HardCases : public ::testing::TestWithParam<sb::Method> {};

double t0_first(const sb::Chain& c) {
  // Time at which the slider, moving a motionless chain, loads the weakest pawl to its threshold.
  double t = 1e300;
  for (int i = 0; i < c.N; ++i)
    if (c.contact[i]) t = std::min(t, c.f_static[i] / (c.K_s * c.v_slider));
  return t;
}

// Displacements that put the net force on every block exactly at +mu_s,i F_n at t = 0: solve
// (K_s I - K_int Laplacian) u = -f_static (free chain ends) by the Thomas algorithm, which is
// stable here because the matrix is diagonally dominant.
std::vector<double> at_threshold(const sb::Chain& c) {
  const int N = c.N;
  std::vector<double> diag(N), rhs(N), u(N);
  for (int i = 0; i < N; ++i) {
    diag[i] = c.K_s + (i > 0 ? c.K_int : 0.0) + (i + 1 < N ? c.K_int : 0.0);
    rhs[i] = -c.f_static[i];
  }
  for (int i = 1; i < N; ++i) {  // off-diagonals are all -K_int
    const double w = -c.K_int / diag[i - 1];
    diag[i] -= w * -c.K_int;
    rhs[i] -= w * rhs[i - 1];
  }
  u[N - 1] = rhs[N - 1] / diag[N - 1];
  for (int i = N - 2; i >= 0; --i) u[i] = (rhs[i] + c.K_int * u[i + 1]) / diag[i];
  return u;
}

// A start time `lead` before the first threshold crossing, on the step grid.
double start_before_first_slip(const sb::Chain& c, double lead, double dt) {
  return std::floor((t0_first(c) - lead) / dt) * dt;
}

// Runs one case from `st` to t_end with samples every `sample_dt`, checks the invariants and
// the energy balance to `tol`, prints what was measured.
CaseResult check(const std::string& name, sb::Integrator& integ, const sb::Chain& c, sb::State st,
                 double t_end, double sample_dt, double tol) {
  SCOPED_TRACE(name);
  const auto r = sbtest::run_case(integ, c, std::move(st), t_end, sample_dt);
  sbtest::expect_invariants(r, c);
  const double err = r.energy.relative_error();
  std::printf("[case] %-28s %-5s energy rel.err %.2e (tol %.0e)  work %.3e  friction %.3e  "
              "damping %.3e  switches/pawl %.1f  steps %lld  max|v| %.3g  shortest re-switch %.2e periods\n",
              name.c_str(), integ.name().c_str(), err, tol, r.energy.work_in, r.energy.friction,
              r.energy.damping, double(r.state.switches) / std::max(1, c.n_contact),
              (long long)r.state.steps, r.inv.max_abs_v, r.inv.min_switch_interval * c.omega_max() / (2 * M_PI));
  EXPECT_LE(err, tol) << "energy balance: imbalance " << r.energy.imbalance() << " of scale "
                      << r.energy.scale();
  // Switching is bounded: at most a stop and a restart per pawl per step (chattering), and
  // the state never blows up.
  EXPECT_LE(r.state.switches, 2 * (r.state.steps + 1) * c.n_contact);
  return r;
}

// A scene's chain from rest for `t0s` loading times. No block stutters: two instants at which
// one block switches are never closer than 1e-6 of the fastest mode's period. A block stopped
// and restarted by round-off switches again a few ulp of t later, some 1e-12 of a period; every
// case here, with either integrator, keeps at least 4e-3 of a period. A bound on the number of
// switches cannot tell stutter from the dynamics: on the stiffest chain (K_int/K_s = 1e4, run
// from the command line, 3 repetitions) the count is chaotic, 130 to 3,200 a pawl between
// repetitions and steppers (exact; Dormand-Prince at tol 1e-8 and 1e-10), a bound of 2,000
// failed by the Dormand-Prince reference itself.
void run_scene(const std::string& name, const sb::Scene& s, double t0s, double tol, sb::Integrator& integ) {
  const sb::Chain c = sb::build_chain(s, 0);
  const auto r = check(name, integ, c, sb::State::at_rest(c), t0s * s.t0_s(), s.run.sample_dt_s, tol);
  const double period = 2 * M_PI / c.omega_max();
  EXPECT_GE(r.inv.min_switch_interval, 1e-6 * period) << name << ": a block switched twice within "
                                                       << r.inv.min_switch_interval << " s";
}

TEST_P(HardCases, BaselineAndPatterns) {
  for (std::string pat : {"smooth", "periodic:2,1", "hierarchical:10,2", "random:0.5"}) {
    auto s = sbtest::base_scene(GetParam());
    s.pattern = sb::parse_pattern(pat);
    sb::validate(s);
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    run_scene("pattern " + pat, s, 3.0, 5e-3, *integ);
  }
}

TEST_P(HardCases, MuDEqualsMuS) {
  auto s = sbtest::base_scene(GetParam());
  s.friction = {1.0, 0.1, 1.0, 0.1};  // independent draws, clipped: mu_d = min(draws)
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  run_scene("mu_d = mu_s (clipped pairs)", s, 3.0, 5e-3, *integ);
  s.friction = {1.0, 0.0, 1.0, 0.0};  // exactly equal: slips are creeps at the threshold
  run_scene("mu_d = mu_s exactly", s, 3.0, 5e-3, *integ);
}

TEST_P(HardCases, MuDToZero) {
  for (double md : {1e-9, 0.0}) {
    auto s = sbtest::base_scene(GetParam());
    s.friction.mu_d_mean = md;
    s.friction.mu_d_sd = 0;
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    char name[32];
    std::snprintf(name, sizeof name, "mu_d = %g", md);
    run_scene(name, s, 3.0, 5e-3, *integ);
  }
}

TEST_P(HardCases, MuDAboveMuSKept) {
  auto s = sbtest::base_scene(GetParam());
  s.friction = {1.0, 0.1, 1.0, 0.1, sb::FrictionDistribution::PairPolicy::Keep};
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  const sb::Chain c = sb::build_chain(s, 0);
  int above = 0;
  for (int i = 0; i < c.N; ++i) above += c.mu_d[i] > c.mu_s[i];
  ASSERT_GT(above, 5) << "the draw should contain pairs with mu_d > mu_s";
  // A block with mu_d > mu_s restarts and stops every step near its threshold (chattering): the
  // switch count is bounded only by 2 per step, and each stop drops O(h) of kinetic energy.
  run_scene("mu_d > mu_s kept", s, 3.0, 2e-2, *integ);
}

TEST_P(HardCases, ZeroDispersion) {
  auto s = sbtest::base_scene(GetParam());
  s.friction = {1.0, 0.0, 0.5, 0.0};
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  run_scene("zero dispersion", s, 3.0, 5e-3, *integ);
}

TEST_P(HardCases, StiffnessRatioSweep) {
  for (double ratio : {1e-3, 1e-2, 1e-1, 1.0, 10.0, 1e2, 1e3, 1e4}) {
    auto s = sbtest::base_scene(GetParam());
    const auto d1 = sb::derive(s.material, s.geometry, 1.0);
    s.k_int_scale = ratio * d1.K_s_N_per_m / d1.K_int_N_per_m;  // K_int / K_s = ratio
    s.run.dt_s = std::min(1e-7, 0.25 * sb::rk4_stable_dt(s.derived()));
    s.run.sample_dt_s = s.run.dt_s;
    sb::validate(s);
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    char name[64];
    std::snprintf(name, sizeof name, "K_int/K_s = %g", ratio);
    run_scene(name, s, 2.5, 5e-3, *integ);
  }
}

TEST_P(HardCases, ChainSizes) {
  for (int N : {1, 2}) {
    auto s = sbtest::base_scene(GetParam(), N);
    sb::validate(s);
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    run_scene("N = " + std::to_string(N), s, 4.0, 5e-3, *integ);
  }
}

TEST_P(HardCases, TenThousandBlocksShortRun) {
  auto s = sbtest::base_scene(GetParam(), 10000);
  s.run.sample_dt_s = 10 * s.run.dt_s;  // trapezoid error (omega_max * 10 h)^2 / 12 <= 5e-2 on the
                                        // highest modes, which carry almost no energy here
  sb::validate(s);
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  const sb::Chain c = sb::build_chain(s, 0);
  sb::State st = sb::State::at_rest(c);
  // A run from rest would only see single blocks creep for a long time (K_int / K_s ~ 2e5 here
  // holds each one back); start instead with every block at its threshold and follow the
  // avalanche for 1/32 of a slip period (kept short: the event method spends ~10 s on the first
  // 1e-7 s here, where all 10^4 blocks switch at once).
  st.u = at_threshold(c);
  const double omega_s = std::sqrt(c.K_s / c.m);
  check("N = 10000 (short)", *integ, c, st, 6.283 / 32 / omega_s, s.run.sample_dt_s, 5e-3);
}

TEST_P(HardCases, DampingExtremes) {
  {
    auto s = sbtest::base_scene(GetParam());
    s.material.gamma_per_s = 0;
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    run_scene("gamma = 0", s, 3.0, 5e-3, *integ);
  }
  for (double factor : {10.0, 1e3}) {
    auto s = sbtest::base_scene(GetParam());
    // Strongly overdamped for every mode: gamma = factor * 2 omega_max. RK4's real-axis limit
    // h gamma <= 2.78 then binds, not h omega_max <= 2 sqrt 2.
    s.material.gamma_per_s = factor * 2 * s.derived().omega_max;
    s.run.dt_s = std::min(s.run.dt_s, 1.0 / s.material.gamma_per_s);
    // Motion is slow here (relaxation time gamma / omega^2 >> h), so coarser samples suffice.
    s.run.sample_dt_s = 10 * s.run.dt_s;
    sb::validate(s);
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    run_scene("overdamped x" + std::to_string(int(factor)), s, 1.5, 5e-3, *integ);
  }
}

TEST_P(HardCases, SliderSpeeds) {
  for (double v : {5e-6, 5e-4, 5.0, 500.0}) {
    auto s = sbtest::base_scene(GetParam());
    s.material.v_m_per_s = v;
    sb::validate(s);
    SB_INTEGRATOR_OR_SKIP(integ, s.run);
    const sb::Chain c = sb::build_chain(s, 0);
    sb::State st = sb::State::at_rest(c);
    // Slow sliders: skip the long quiet loading (it is exact for a motionless chain) and follow
    // the slips. Fast sliders: the whole run from rest.
    const double omega_s = std::sqrt(c.K_s / c.m);
    const double periods = 20 * 6.283 / omega_s;
    double t_end = 3 * s.t0_s();
    if (t0_first(c) > periods) {
      st.t = start_before_first_slip(c, 0.05 * 6.283 / omega_s, s.run.dt_s);
      t_end = st.t + periods;
    }
    char name[64];
    std::snprintf(name, sizeof name, "slider v = %g m/s", v);
    check(name, *integ, c, st, t_end, s.run.sample_dt_s, 5e-3);
  }
}

TEST_P(HardCases, EveryBlockAtItsThresholdAtStart) {
  auto s = sbtest::base_scene(GetParam());
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  const sb::Chain c = sb::build_chain(s, 0);
  sb::State st = sb::State::at_rest(c);
  st.u = at_threshold(c);
  for (int i = 0; i < c.N; ++i)
    ASSERT_NEAR(c.driving_force(i, st.u.data(), st.v.data(), 0.0), c.f_static[i], 1e-9 * c.f_static[i]);
  check("all at threshold at t = 0", *integ, c, st, 2 * s.t0_s(), s.run.sample_dt_s, 5e-3);
}

TEST_P(HardCases, SingleBlockInContact) {
  // N = 20 keeps the cost down: with one pawl the chain is never fully stuck, so RK4 cannot
  // jump over the loading phase.
  auto s = sbtest::base_scene(GetParam(), 20);
  s.pattern = sb::parse_pattern("periodic:1,19");  // block 0 is the only pawl
  sb::validate(s);
  SB_INTEGRATOR_OR_SKIP(integ, s.run);
  const sb::Chain c = sb::build_chain(s, 0);
  ASSERT_EQ(c.n_contact, 1);
  EXPECT_DOUBLE_EQ(c.F_n, c.F_load);  // the whole load on one pawl
  run_scene("one block in contact", s, 2.0, 5e-3, *integ);
}

TEST(HardCasesInput, NoBlockInContactIsAnInputError) {
  auto s = sbtest::base_scene(sb::Method::RK4);
  s.pattern = sb::parse_pattern("random:0.999");
  EXPECT_THROW(sb::validate(s), sb::InputError);
  sb::PatternSpec all_grooves;
  all_grooves.kind = sb::SurfaceKind::Random;
  all_grooves.groove_fraction = 0.99;
  EXPECT_THROW(sb::build_contact_mask(all_grooves, 50, 1), sb::InputError);
  try {
    sb::validate(s);
  } catch (const sb::InputError& e) {
    EXPECT_EQ(e.field, "pattern");
    EXPECT_NE(std::string(e.what()).find("no block in contact"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, HardCases, sbtest::kMethods, sbtest::method_label);

}  // namespace
