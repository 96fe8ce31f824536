// RK4's explicit stability limit h * omega_max <= 2 sqrt 2 is where divergence really starts.
// A free chain (no block in contact, no damping, slider at rest) is a linear system whose
// highest normal mode is excited; the amplitude stays bounded at 0.95 of the limit and grows
// at 1.05. The chain is built by hand, bypassing validate(), which would refuse the larger
// step. omega_max of the finite chain is computed exactly (Eigen) rather than taken from the
// Gershgorin bound sqrt((K_s + 4 K_int)/m), which it approaches as N grows.
#include <Eigen/Dense>
#include <cmath>

#include "springblock/integrate/methods/rk4.hpp"
#include "stability_support.hpp"

namespace {

struct MaxAmplitude final : sb::Observer {
  double max_u = 0;
  void sample(const sb::Chain& c, const sb::State& s) override {
    for (int i = 0; i < c.N; ++i) max_u = std::max(max_u, std::fabs(s.u[i]));
  }
};

sb::Chain free_chain(int N) {
  sb::Scene s;
  s.geometry.N = N;
  const auto d = s.derived();
  sb::Chain c;
  c.N = N;
  c.K_s = d.K_s_N_per_m;
  c.K_int = d.K_int_N_per_m;
  c.m = d.m_kg;
  c.gamma = 0;
  c.v_slider = 0;  // slider at rest: the system is exactly linear and homogeneous
  c.contact.assign(N, 0);  // every block in a groove: nothing ever sticks
  c.f_static.assign(N, 0);
  c.f_kinetic.assign(N, 0);
  c.mu_s.assign(N, 0);
  c.mu_d.assign(N, 0);
  c.n_contact = 0;
  c.F_load = 1;
  c.F_n = 1;
  return c;
}

TEST(Rk4StabilityLimit, DivergenceStartsAtTheLimit) {
  const int N = 200;
  const sb::Chain c = free_chain(N);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  for (int i = 0; i < N; ++i) {
    K(i, i) = c.K_s;
    if (i > 0) K(i, i) += c.K_int, K(i, i - 1) = -c.K_int;
    if (i + 1 < N) K(i, i) += c.K_int, K(i, i + 1) = -c.K_int;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K / c.m);
  const double omega_top = std::sqrt(eig.eigenvalues()(N - 1));
  const double omega_bound = std::sqrt((c.K_s + 4 * c.K_int) / c.m);
  EXPECT_LE(omega_top, omega_bound);
  EXPECT_GT(omega_top, 0.999 * omega_bound) << "N large enough for the Gershgorin bound to be tight";
  const double h_limit = 2 * std::sqrt(2.0) / omega_top;

  for (double factor : {0.95, 1.05}) {
    sb::State st = sb::State::at_rest(c);
    const double a0 = 1e-6;
    for (int i = 0; i < N; ++i) st.u[i] = a0 * eig.eigenvectors()(i, N - 1) / eig.eigenvectors().col(N - 1).cwiseAbs().maxCoeff();
    const double h = factor * h_limit;
    sb::Rk4 rk4(h);
    MaxAmplitude amp;
    // 300 steps: at 1.05 the top mode grows by |R(i 2.97)| per step (~1e44 overall here);
    // at 0.95 RK4 is slightly dissipative and the amplitude must not exceed its start.
    rk4.run(c, st, 300 * h, h, amp);
    const double growth = amp.max_u / a0;
    std::printf("h = %.2f x limit: max amplitude / initial = %.3g\n", factor, growth);
    if (factor < 1) EXPECT_LE(growth, 1.0 + 1e-9);
    else EXPECT_GT(growth, 1e10);
  }
  // The limit validate() enforces is the Gershgorin one, on the safe side of the exact one.
  sb::Scene s;
  s.geometry.N = N;
  EXPECT_LE(sb::rk4_stable_dt(s.derived()), h_limit);
  EXPECT_GT(sb::rk4_stable_dt(s.derived()), 0.999 * h_limit);
}

}  // namespace

namespace {

// Damping has its own explicit limit: an overdamped mode has a real eigenvalue near -gamma and
// RK4's stability region ends at -2.785 on the real axis, so h gamma > 2.785 diverges even when
// h omega_max <= 2 sqrt 2. validate() must refuse such a step.
TEST(Rk4StabilityLimit, DampingLimitIsEnforced) {
  sb::Scene s;
  s.geometry.N = 10;
  s.reps = 1;
  s.run.method = sb::Method::RK4;  // validate() checks the step only for RK4
  s.run.dt_s = 1e-7;
  s.material.gamma_per_s = 1e8;  // h gamma = 10
  ASSERT_LE(s.run.dt_s, sb::rk4_stable_dt(s.derived())) << "the undamped limit alone allows it";
  // It really diverges: a free damped chain displaced from rest.
  sb::Chain c = free_chain(10);
  c.gamma = s.material.gamma_per_s;
  sb::State st = sb::State::at_rest(c);
  st.u[3] = 1e-6;
  sb::Rk4 rk4(s.run.dt_s);
  MaxAmplitude amp;
  rk4.run(c, st, 200 * s.run.dt_s, s.run.dt_s, amp);
  EXPECT_FALSE(amp.max_u < 1.0) << "h gamma = 10 should blow up, max |u| = " << amp.max_u;
  try {
    sb::validate(s);
    ADD_FAILURE() << "validate accepted h gamma = 10";
  } catch (const sb::InputError& e) {
    EXPECT_EQ(e.field, "dt");
    EXPECT_NE(std::string(e.what()).find("damping"), std::string::npos) << e.what();
  }
  // At the step validate() proposes, the same chain decays.
  s.run.dt_s = 2.785 / s.material.gamma_per_s * 0.99;
  EXPECT_NO_THROW(sb::validate(s));
  st = sb::State::at_rest(c);
  st.u[3] = 1e-6;
  sb::Rk4 ok(s.run.dt_s);
  MaxAmplitude amp_ok;
  ok.run(c, st, 2000 * s.run.dt_s, s.run.dt_s, amp_ok);
  EXPECT_LE(amp_ok.max_u, 1e-6);
  // The paper's defaults are unaffected.
  sb::Scene paper;
  paper.run.method = sb::Method::RK4;
  EXPECT_NO_THROW(sb::validate(paper));
}

}  // namespace
