// Derived stiffnesses, mass and loads against hand calculations from the paper's formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "springblock/parameters.hpp"
#include "springblock/scene.hpp"

using namespace sb;

TEST(Parameters, DefaultsMatchThePapersTable) {
  MaterialParameters m;
  EXPECT_DOUBLE_EQ(m.G_Pa, 5e6);
  EXPECT_DOUBLE_EQ(m.E_Pa, 15e6);
  EXPECT_DOUBLE_EQ(m.rho_kg_per_m3, 1200);
  EXPECT_DOUBLE_EQ(m.P_Pa, 1e6);
  EXPECT_DOUBLE_EQ(m.gamma_per_s, 1e4);     // 10 /ms
  EXPECT_DOUBLE_EQ(m.v_m_per_s, 5e-4);      // 0.05 cm/s
  EXPECT_DOUBLE_EQ(m.l_y_m, 0.01);
  EXPECT_DOUBLE_EQ(m.l_z_m, 0.001);
  FrictionDistribution f;
  EXPECT_DOUBLE_EQ(f.mu_s_mean, 1.0);
  EXPECT_DOUBLE_EQ(f.mu_s_sd, 0.1);
  EXPECT_DOUBLE_EQ(f.mu_d_mean, 0.5);
  EXPECT_DOUBLE_EQ(f.mu_d_sd, 0.01);
}

// N = 200, L_x = 4 cm by hand: l_x = 0.02 cm; K_int = 15e6 * 199 * 1e-3 * 1e-2 / 0.04 = 746250;
// K_s = 5e6 * 0.01 * 0.04 / (1e-3 * 200) = 1e4; m = 1200 * 2e-4 * 1e-2 * 1e-3 = 2.4e-6;
// F_load = 1e6 * 0.04 * 0.01 = 400 N, so 2 N per block on a smooth surface.
TEST(Parameters, DerivedValuesForFig1Scene) {
  auto d = derive(MaterialParameters{}, ChainGeometry{200, 0.04}, 1.0);
  EXPECT_NEAR(d.l_x_m, 2e-4, 1e-18);
  EXPECT_NEAR(d.K_int_N_per_m, 746250.0, 1e-6);
  EXPECT_NEAR(d.K_s_N_per_m, 1e4, 1e-9);
  EXPECT_NEAR(d.m_kg, 2.4e-6, 1e-20);
  EXPECT_NEAR(d.F_load_N, 400.0, 1e-9);
  EXPECT_NEAR(d.omega_s, std::sqrt(1e4 / 2.4e-6), 1e-6);
}

// The paper quotes (N_g/N)_cr = 2 sqrt(K_s/K_int) ~ 0.23 for N = 360, L_x = 7.2 cm.
TEST(Parameters, CriticalGrooveRatioOfFigP1) {
  auto d = derive(MaterialParameters{}, ChainGeometry{360, 0.072}, 1.0);
  const double ratio = 2 * std::sqrt(d.K_s_N_per_m / d.K_int_N_per_m);
  EXPECT_NEAR(ratio, 0.23, 0.005);
}

TEST(Parameters, KIntScaleMultipliesOnlyKInt) {
  auto a = derive(MaterialParameters{}, ChainGeometry{50, 0.01}, 1.0);
  auto b = derive(MaterialParameters{}, ChainGeometry{50, 0.01}, 0.0);
  EXPECT_EQ(b.K_int_N_per_m, 0.0);
  EXPECT_EQ(a.K_s_N_per_m, b.K_s_N_per_m);
  EXPECT_EQ(a.m_kg, b.m_kg);
}

TEST(Parameters, Rk4StableStepAtPaperDefaultsIsAboveThePapersStep) {
  auto d = derive(MaterialParameters{}, ChainGeometry{360, 0.072}, 1.0);
  EXPECT_GT(rk4_stable_dt(d), 1e-7);  // h = 1e-4 ms is stable: h omega_max ~ 0.11
  EXPECT_LT(1e-7 * d.omega_max, 0.2);
}

TEST(Scene, NormalForceIsSharedByContactBlocks) {
  Scene s;
  s.geometry = {360, 0.072};
  s.pattern = parse_pattern("periodic:1,2");
  auto c = build_chain(s, 0);
  EXPECT_EQ(c.n_contact, 120);
  EXPECT_NEAR(c.F_n * c.n_contact, 1e6 * 0.072 * 0.01, 1e-9);
  for (int i = 0; i < c.N; ++i) {
    if (!c.contact[i]) {
      EXPECT_EQ(c.f_static[i], 0.0);
      EXPECT_EQ(c.f_kinetic[i], 0.0);
    }
  }
}

TEST(Scene, DrawsArePairedAcrossSurfacesAndTruncatedAndClipped) {
  Scene smooth, grooved;
  grooved.pattern = parse_pattern("periodic:2,2");
  auto a = build_chain(smooth, 3), b = build_chain(grooved, 3);
  for (int i = 0; i < a.N; ++i)
    if (b.contact[i]) {
      EXPECT_EQ(a.mu_s[i], b.mu_s[i]);
    }
  Scene wide;
  wide.friction = {0.2, 0.5, 0.6, 0.5};  // many negative draws and many mu_d > mu_s
  auto c = build_chain(wide, 0);
  for (int i = 0; i < c.N; ++i) {
    EXPECT_GE(c.mu_s[i], 0.0);
    EXPECT_GE(c.mu_d[i], 0.0);
    EXPECT_LE(c.mu_d[i], c.mu_s[i]);
  }
}

TEST(Scene, RepetitionSeedsDifferAndAreStable) {
  EXPECT_NE(rep_seed(1, 0), rep_seed(1, 1));
  EXPECT_NE(rep_seed(1, 0), rep_seed(2, 0));
  EXPECT_EQ(rep_seed(1, 5), rep_seed(1, 5));
}
