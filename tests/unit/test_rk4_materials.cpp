// RK4 on a chain whose blocks differ in slider spring, mass and internal springs, against the
// exact motion of the linear system. Blocks 0 and 1 sit in grooves (no friction), joined by a
// spring of half the scene's K_int; the spring from block 1 to block 2 is cut (k_int_scale 0), and
// block 2 is held by friction far above its load. So u = (u0, u1) obeys
//   M u'' + gamma M u' + K u = k_s v t,   u(0) = u'(0) = 0,
// with M = diag(m_i), K = diag(k_s,i) + the coupling spring. The solution is u_p = a t + b with
// K a = k_s v and K b = -gamma M a, plus the modes of K phi = w^2 M phi (M-normalised), each
// q'' + gamma q' + w^2 q = 0 from q(0) = -phi^T M b, q'(0) = -phi^T M a. A kernel that used the
// uniform K_s, m or K_int for any block, or damped by m gamma instead of m_i gamma, misses it by
// far more than RK4's error ((w h)^4 ~ 1e-11 here).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/errors.hpp"
#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/scene.hpp"
#include "gsl_eigen.hpp"

using namespace sb;

namespace {

struct PositionRecorder final : Observer {
  std::vector<double> t, u0, u1;
  std::vector<int> dir2;
  void sample(const Chain&, const State& s) override {
    t.push_back(s.t), u0.push_back(s.u[0]), u1.push_back(s.u[1]), dir2.push_back(s.dir[2]);
  }
};

Scene three_blocks(double gamma) {
  Scene s;
  s.geometry.N = 3;
  s.material.gamma_per_s = gamma;
  s.run.method = Method::RK4;
  s.materials = parse_materials_tsv(
      "contact\tmu_s\tmu_s_sd\tmu_d\tmu_d_sd\tk_s_scale\tmass_scale\tk_int_scale\n"
      "0\t1\t0\t0.5\t0\t1\t1\t0.5\n"
      "0\t1\t0\t0.5\t0\t3\t0.5\t0\n"
      "1\t100\t0\t0.5\t0\t1\t1\t1\n",
      "three.tsv");
  return s;
}

// The exact (u0, u1) at time t.
Eigen::Vector2d exact(const Chain& c, double gamma, double t) {
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero(), K;
  M(0, 0) = c.blocks.m[0], M(1, 1) = c.blocks.m[1];
  const double k = c.blocks.K_int[0];
  K << c.blocks.K_s[0] + k, -k, -k, c.blocks.K_s[1] + k;
  const Eigen::Vector2d ks(c.blocks.K_s[0], c.blocks.K_s[1]);
  const Eigen::Vector2d a = K.ldlt().solve(ks * c.v_slider);
  const Eigen::Vector2d b = K.ldlt().solve(-gamma * (M * a));
  const sbtest::SymmetricEigen modes = sbtest::symmetric_eigen(K, M);
  Eigen::Vector2d u = a * t + b;
  for (int j = 0; j < 2; ++j) {
    const Eigen::Vector2d phi = modes.vectors.col(j);
    const double w2 = modes.values[j], q0 = -phi.dot(M * b), dq0 = -phi.dot(M * a);
    const double wd = std::sqrt(w2 - 0.25 * gamma * gamma);  // underdamped in these scenes
    const double q = std::exp(-0.5 * gamma * t) *
                     (q0 * std::cos(wd * t) + (dq0 + 0.5 * gamma * q0) / wd * std::sin(wd * t));
    u += phi * q;
  }
  return u;
}

}  // namespace

class Rk4Materials : public ::testing::TestWithParam<double> {};

TEST_P(Rk4Materials, MatchesTheExactLinearMotion) {
  const double gamma = GetParam(), h = 1e-7, T = 2e-3;
  Scene s = three_blocks(gamma);
  ASSERT_NO_THROW(validate(s));
  const Chain c = build_chain(s, 0);
  ASSERT_FALSE(c.blocks.uniform());
  EXPECT_EQ(c.blocks.K_s[1], 3.0 * c.K_s);
  EXPECT_EQ(c.blocks.m[1], 0.5 * c.m);
  EXPECT_EQ(c.blocks.K_int[1], 0.0);
  State st = State::at_rest(c);
  PositionRecorder rec;
  Rk4 rk4(h);
  rk4.run(c, st, T, 1e-5, rec);
  ASSERT_GE(rec.t.size(), 200u);
  double scale = 0, worst = 0;
  for (std::size_t k = 0; k < rec.t.size(); ++k) {
    const auto u = exact(c, gamma, rec.t[k]);
    scale = std::max({scale, std::fabs(u(0)), std::fabs(u(1))});
    worst = std::max({worst, std::fabs(rec.u0[k] - u(0)), std::fabs(rec.u1[k] - u(1))});
    EXPECT_EQ(rec.dir2[k], 0) << "block 2 must stay stuck";
  }
  EXPECT_LT(worst, 1e-8 * scale) << "max |u - exact| = " << worst << " of " << scale;
  // The two blocks do not move alike: the test sees each block's own springs and mass.
  EXPECT_GT(std::fabs(rec.u0.back() - rec.u1.back()), 1e-3 * scale);
}

INSTANTIATE_TEST_SUITE_P(UndampedAndDamped, Rk4Materials, ::testing::Values(0.0, 1000.0));

// A stable step for this chain: the per-block Gershgorin bound, not the uniform one, decides.
TEST(Rk4MaterialsStep, StableStepUsesTheStiffestBlock) {
  Scene s;
  s.geometry.N = 4;
  s.run.method = Method::RK4;
  s.material.gamma_per_s = 0;
  const auto d = s.derived();
  const double h_uniform = 2.0 * std::sqrt(2.0) / d.omega_max;
  s.run.dt_s = 0.9 * h_uniform;
  EXPECT_NO_THROW(validate(s));
  // Block 1 four times lighter: its row's bound is four times larger, so the step must halve.
  s.materials = parse_materials_tsv("mass_scale\n1\n0.25\n1\n1\n", "light.tsv");
  try {
    validate(s);
    FAIL() << "a step stable only for the uniform chain was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the RK4 stability limit"), std::string::npos) << e.what();
  }
  s.run.dt_s = 0.45 * h_uniform;
  EXPECT_NO_THROW(validate(s));
}

// mu(t) as the results report it, on a chain whose blocks differ in all three mechanical fields,
// against the friction forces summed here from each block's own springs (friction_force): the
// observers' uniform stuck-force kernels must not be what reads such a chain.
struct MuRecorder final : Observer {
  std::vector<double> t, mu;
  void sample(const Chain& c, const State& s) override {
    double sum = 0;
    for (int i = 0; i < c.N; ++i) sum += std::fabs(friction_force(c, s, i));
    t.push_back(s.t), mu.push_back(sum / c.F_load);
  }
};

TEST(Rk4MaterialsObserved, MuOfTheResultsUsesEachBlocksSprings) {
  Scene s;
  s.geometry.N = 12;
  s.reps = 1;
  s.run.method = Method::RK4;
  s.run.duration_t0 = 2.0;
  s.observe.series = true;
  s.pattern = parse_pattern("periodic:2,1");
  std::string text = "k_s_scale\tmass_scale\tk_int_scale\n";
  for (int i = 0; i < 12; ++i)
    text += std::to_string(1.0 + 0.25 * (i % 3)) + "\t" + std::to_string(i < 6 ? 1.0 : 2.0) + "\t" +
            std::to_string(i % 2 ? 0.3 : 1.7) + "\n";
  s.materials = parse_materials_tsv(text, "mixed.tsv");
  ASSERT_NO_THROW(validate(s));
  const auto result = run_ensemble(s);
  ASSERT_EQ(result.runs.size(), 1u);
  const auto& series = result.runs[0].series;
  const Chain c = build_chain(s, 0);
  State st = State::at_rest(c);
  MuRecorder rec;
  Rk4(s.run.dt_s).run(c, st, s.duration(), s.run.sample_dt_s, rec);
  ASSERT_EQ(series.size(), rec.mu.size());
  ASSERT_GT(series.size(), 10u);
  double worst = 0, top = 0;
  for (std::size_t k = 0; k < series.size(); ++k) {
    ASSERT_EQ(series[k].t, rec.t[k]);
    worst = std::max(worst, std::fabs(series[k].mu - rec.mu[k]));
    top = std::max(top, rec.mu[k]);
  }
  EXPECT_GT(top, 0.1);
  EXPECT_LT(worst, 1e-12 * top) << "largest |mu - sum |f_i| / F_load| = " << worst;
}
