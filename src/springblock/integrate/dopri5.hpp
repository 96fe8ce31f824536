#pragma once
// Dormand-Prince 5(4) embedded Runge-Kutta pair for the chain, y = (u, v), y' = (v, a).
// FSAL (the last stage of an accepted step is the first of the next), a max-norm error estimate
// against atol + rtol |y|, and the pair's 4th-order continuous extension for locating events
// inside a step. The contact phase is frozen during a step: the caller owns the switching.
// No allocation after construction.
#include <vector>

#include "springblock/integrate/chain_accel.hpp"
#include "springblock/model.hpp"

namespace sb::event_detail {

// The Dormand-Prince (1980) tableau, the standard published coefficients.
struct Dp5Tableau {
  static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  static constexpr double a21 = 1.0 / 5;
  static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729;
  static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                          a64 = 49.0 / 176, a65 = -5103.0 / 18656;
  static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                          b6 = 11.0 / 84;
  // b - b_hat (5th minus embedded 4th order weights); stage 7 enters only the estimate.
  static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                          e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
  // Continuous extension of order 4 (Hairer, Norsett, Wanner, Solving ODEs I, sec. II.6).
  static constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                          d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                          d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
};

class Dopri5 {
 public:
  explicit Dopri5(int N);

  // Stage 1 at (u, v, t). Needed at the start and after every switch (the right-hand side jumps).
  template <bool Coupled, bool Damped>
  void first_stage(const Chain& c, const double* u, const double* v, double t, const double* mobile,
                   const double* f_kin);

  // One trial step of size h from (u, v, t) whose stage 1 is current. Leaves the 5th-order
  // solution in u1(), v1() and returns the error in units of the tolerance (accept if <= 1).
  template <bool Coupled, bool Damped>
  double attempt(const Chain& c, const double* u, const double* v, double t, double h,
                 const double* mobile, const double* f_kin, double atol_u, double atol_v, double rtol);

  // After accepting: stage 7 becomes the next step's stage 1 (FSAL).
  void accept_fsal();

  // The continuous extension of the last attempted step at theta in [0, 1].
  double dense_u(int i, double theta) const { return dense(u0_, u1_.data(), 0, i, theta); }
  double dense_v(int i, double theta) const { return dense(v0_, v1_.data(), 7, i, theta); }

  const double* u1() const { return u1_.data(); }
  const double* v1() const { return v1_.data(); }
  // Acceleration at the start of the step (stage 1).
  const double* a0() const { return k_[7]; }

 private:
  double dense(const double* y0, const double* y1, int k_base, int i, double theta) const;
  double error_norm(const double* u, const double* v, const double* mobile, double atol_u, double atol_v,
                    double rtol) const;

  int N_;
  std::vector<double> store_;  // 14 stage arrays: k_[0..6] = u' stages (velocities), k_[7..13] = v' (accelerations)
  double* k_[14];
  std::vector<double> ut_, vt_, u1_, v1_;
  double h_ = 0;
  const double* u0_ = nullptr;
  const double* v0_ = nullptr;
};

template <bool Coupled, bool Damped>
void Dopri5::first_stage(const Chain& c, const double* u, const double* v, double t, const double* mobile,
                         const double* f_kin) {
  for (int i = 0; i < N_; ++i) k_[0][i] = v[i];
  chain_accel<Coupled, Damped>(c, u, v, t, mobile, f_kin, k_[7]);
}

template <bool Coupled, bool Damped>
double Dopri5::attempt(const Chain& c, const double* u, const double* v, double t, double h,
                       const double* mobile, const double* f_kin, double atol_u, double atol_v, double rtol) {
  using T = Dp5Tableau;
  const int N = N_;
  double* __restrict ut = ut_.data();
  double* __restrict vt = vt_.data();
  double** K = k_;  // K[s] velocity stage s, K[7+s] acceleration stage s
  auto stage = [&](int s, double cs) {
    for (int i = 0; i < N; ++i) K[s][i] = vt[i];
    chain_accel<Coupled, Damped>(c, ut, vt, t + cs * h, mobile, f_kin, K[7 + s]);
  };
  for (int i = 0; i < N; ++i) {
    ut[i] = u[i] + h * T::a21 * K[0][i];
    vt[i] = v[i] + h * T::a21 * K[7][i];
  }
  stage(1, T::c2);
  for (int i = 0; i < N; ++i) {
    ut[i] = u[i] + h * (T::a31 * K[0][i] + T::a32 * K[1][i]);
    vt[i] = v[i] + h * (T::a31 * K[7][i] + T::a32 * K[8][i]);
  }
  stage(2, T::c3);
  for (int i = 0; i < N; ++i) {
    ut[i] = u[i] + h * (T::a41 * K[0][i] + T::a42 * K[1][i] + T::a43 * K[2][i]);
    vt[i] = v[i] + h * (T::a41 * K[7][i] + T::a42 * K[8][i] + T::a43 * K[9][i]);
  }
  stage(3, T::c4);
  for (int i = 0; i < N; ++i) {
    ut[i] = u[i] + h * (T::a51 * K[0][i] + T::a52 * K[1][i] + T::a53 * K[2][i] + T::a54 * K[3][i]);
    vt[i] = v[i] + h * (T::a51 * K[7][i] + T::a52 * K[8][i] + T::a53 * K[9][i] + T::a54 * K[10][i]);
  }
  stage(4, T::c5);
  for (int i = 0; i < N; ++i) {
    ut[i] = u[i] + h * (T::a61 * K[0][i] + T::a62 * K[1][i] + T::a63 * K[2][i] + T::a64 * K[3][i] +
                        T::a65 * K[4][i]);
    vt[i] = v[i] + h * (T::a61 * K[7][i] + T::a62 * K[8][i] + T::a63 * K[9][i] + T::a64 * K[10][i] +
                        T::a65 * K[11][i]);
  }
  stage(5, 1.0);
  double* __restrict u1 = u1_.data();
  double* __restrict v1 = v1_.data();
  for (int i = 0; i < N; ++i) {
    u1[i] = u[i] + h * (T::b1 * K[0][i] + T::b3 * K[2][i] + T::b4 * K[3][i] + T::b5 * K[4][i] + T::b6 * K[5][i]);
    v1[i] = v[i] + h * (T::b1 * K[7][i] + T::b3 * K[9][i] + T::b4 * K[10][i] + T::b5 * K[11][i] +
                        T::b6 * K[12][i]);
  }
  // Stage 7 is evaluated at the new point (c7 = 1, a7 = b): FSAL.
  for (int i = 0; i < N; ++i) {
    ut[i] = u1[i];
    vt[i] = v1[i];
  }
  stage(6, 1.0);
  h_ = h;
  u0_ = u;
  v0_ = v;
  return error_norm(u, v, mobile, atol_u, atol_v, rtol);
}

}  // namespace sb::event_detail
