#pragma once
// Dormand-Prince 5(4) embedded Runge-Kutta pair for the chain, y = (u, v), y' = (v, a).
// FSAL (the last stage of an accepted step is the first of the next), a max-norm error estimate
// against atol + rtol |y|, and the pair's 4th-order continuous extension for locating events
// inside a step. The contact phase is frozen during a step: the caller owns the switching.
// Only the blocks in the given spans are stepped (the others are stuck or solved exactly
// elsewhere, see active_set.hpp). No allocation after construction.
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/step/chain_accel.hpp"
#include "springblock/kernel_clones.hpp"
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

  // Copy the current positions of the blocks bordering the spans into the trial arrays, so that
  // they read as constant to the stages (the stages read no other block outside the spans).
  // Call after every switch, with the new spans.
  void set_frozen(const double* u, const std::vector<BlockRange>& spans);

  // Stage 1 at (u, v, t). Needed at the start and after every switch (the right-hand side jumps).
  template <bool Coupled, bool Damped>
  void first_stage(const Chain& c, const std::vector<BlockRange>& spans, const double* u, const double* v, double t,
                   const double* mobile, const double* f_kin);

  // One trial step of size h from (u, v, t) whose stage 1 is current. Leaves the 5th-order
  // solution in u1(), v1() and returns the error in units of the tolerance (accept if <= 1).
  template <bool Coupled, bool Damped>
  double attempt(const Chain& c, const std::vector<BlockRange>& spans, const double* u, const double* v, double t,
                 double h, const double* mobile, const double* f_kin, double atol_u, double atol_v, double rtol);

  // After accepting: stage 7 becomes the next step's stage 1 (FSAL).
  void accept_fsal();

  // The continuous extension of the last attempted step at theta in [0, 1].
  double dense_u(int i, double theta) const { return dense(u0_, u1_.data(), 0, i, theta); }
  double dense_v(int i, double theta) const { return dense(v0_, k_[6], 7, i, theta); }
  // dense_v of every block of the spans at one theta, into out (by block): one pass over the
  // stage arrays instead of a block at a time.
  void dense_v_spans(const std::vector<BlockRange>& spans, double theta, double* out) const;

  const double* u1() const { return u1_.data(); }
  // The new velocities are stage 7's velocity slope (c7 = 1, a7 = b): stored once, as k_[6].
  const double* v1() const { return k_[6]; }

 private:
  double dense(const double* y0, const double* y1, int k_base, int i, double theta) const;
  double error_norm(const std::vector<BlockRange>& spans, const double* u, const double* v, const double* mobile,
                    double atol_u, double atol_v, double rtol) const;

  std::vector<double> store_;  // 14 stage arrays: k_[0..6] = u' stages (velocities), k_[7..13] = v' (accelerations)
  double* k_[14];
  std::vector<double> ut_, u1_;  // trial positions and the step's end positions
  double h_ = 0;
  const double* u0_ = nullptr;
  const double* v0_ = nullptr;
};

template <bool Coupled, bool Damped>
SB_KERNEL_CLONES void Dopri5::first_stage(const Chain& c, const std::vector<BlockRange>& spans, const double* u,
                                          const double* v, double t, const double* mobile, const double* f_kin) {
  for (const BlockRange& sp : spans) {
    for (int i = sp.lo; i < sp.hi; ++i) k_[0][i] = v[i];
    chain_accel_of<Coupled, Damped>(c, sp.lo, sp.hi, u, v, t, mobile, f_kin, k_[7]);
  }
}

// Stage combinations out = y + h (w1 k1 + ...), one function per number of terms with
// restrict-qualified parameters so GCC vectorises them (through lambdas over an array of stage
// pointers it did not: the loops compiled to scalar code).
SB_INLINE void comb(int lo, int hi, double* __restrict out, const double* __restrict y, double h, double w1,
                    const double* __restrict k1) {
  for (int i = lo; i < hi; ++i) out[i] = y[i] + h * (w1 * k1[i]);
}
SB_INLINE void comb(int lo, int hi, double* __restrict out, const double* __restrict y, double h, double w1,
                    const double* __restrict k1, double w2, const double* __restrict k2) {
  for (int i = lo; i < hi; ++i) out[i] = y[i] + h * (w1 * k1[i] + w2 * k2[i]);
}
SB_INLINE void comb(int lo, int hi, double* __restrict out, const double* __restrict y, double h, double w1,
                    const double* __restrict k1, double w2, const double* __restrict k2, double w3,
                    const double* __restrict k3) {
  for (int i = lo; i < hi; ++i) out[i] = y[i] + h * (w1 * k1[i] + w2 * k2[i] + w3 * k3[i]);
}
SB_INLINE void comb(int lo, int hi, double* __restrict out, const double* __restrict y, double h, double w1,
                    const double* __restrict k1, double w2, const double* __restrict k2, double w3,
                    const double* __restrict k3, double w4, const double* __restrict k4) {
  for (int i = lo; i < hi; ++i) out[i] = y[i] + h * (w1 * k1[i] + w2 * k2[i] + w3 * k3[i] + w4 * k4[i]);
}
SB_INLINE void comb(int lo, int hi, double* __restrict out, const double* __restrict y, double h, double w1,
                    const double* __restrict k1, double w2, const double* __restrict k2, double w3,
                    const double* __restrict k3, double w4, const double* __restrict k4, double w5,
                    const double* __restrict k5) {
  for (int i = lo; i < hi; ++i)
    out[i] = y[i] + h * (w1 * k1[i] + w2 * k2[i] + w3 * k3[i] + w4 * k4[i] + w5 * k5[i]);
}

template <bool Coupled, bool Damped>
SB_KERNEL_CLONES double Dopri5::attempt(const Chain& c, const std::vector<BlockRange>& spans, const double* u,
                                        const double* v, double t, double h, const double* mobile, const double* f_kin,
                                        double atol_u, double atol_v, double rtol) {
  using T = Dp5Tableau;
  double* ut = ut_.data();
  double* u1 = u1_.data();
  double* const* K = k_;  // K[s] velocity stage s (= the trial v), K[7+s] acceleration stage s
  // Stage s from the trial positions ut and the trial velocities already in K[s].
  auto stage = [&](int s, double cs, const double* pos) __attribute__((always_inline)) {
    for (const BlockRange& sp : spans)
      chain_accel_of<Coupled, Damped>(c, sp.lo, sp.hi, pos, K[s], t + cs * h, mobile, f_kin, K[7 + s]);
  };
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, ut, u, h, T::a21, K[0]);
    comb(sp.lo, sp.hi, K[1], v, h, T::a21, K[7]);
  }
  stage(1, T::c2, ut);
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, ut, u, h, T::a31, K[0], T::a32, K[1]);
    comb(sp.lo, sp.hi, K[2], v, h, T::a31, K[7], T::a32, K[8]);
  }
  stage(2, T::c3, ut);
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, ut, u, h, T::a41, K[0], T::a42, K[1], T::a43, K[2]);
    comb(sp.lo, sp.hi, K[3], v, h, T::a41, K[7], T::a42, K[8], T::a43, K[9]);
  }
  stage(3, T::c4, ut);
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, ut, u, h, T::a51, K[0], T::a52, K[1], T::a53, K[2], T::a54, K[3]);
    comb(sp.lo, sp.hi, K[4], v, h, T::a51, K[7], T::a52, K[8], T::a53, K[9], T::a54, K[10]);
  }
  stage(4, T::c5, ut);
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, ut, u, h, T::a61, K[0], T::a62, K[1], T::a63, K[2], T::a64, K[3], T::a65, K[4]);
    comb(sp.lo, sp.hi, K[5], v, h, T::a61, K[7], T::a62, K[8], T::a63, K[9], T::a64, K[10], T::a65, K[11]);
  }
  stage(5, 1.0, ut);
  // The 5th-order solution; stage 7 is evaluated at it (c7 = 1, a7 = b): FSAL.
  for (const BlockRange& sp : spans) {
    comb(sp.lo, sp.hi, u1, u, h, T::b1, K[0], T::b3, K[2], T::b4, K[3], T::b5, K[4], T::b6, K[5]);
    comb(sp.lo, sp.hi, K[6], v, h, T::b1, K[7], T::b3, K[9], T::b4, K[10], T::b5, K[11], T::b6, K[12]);
  }
  stage(6, 1.0, u1);
  h_ = h;
  u0_ = u;
  v0_ = v;
  return error_norm(spans, u, v, mobile, atol_u, atol_v, rtol);
}

}  // namespace sb::event_detail
