#pragma once
// The first root of a polynomial on an interval, isolated in the Bernstein basis: the exact
// stepper's event screen (span_screen.hpp) has each event function over a step as a polynomial.
//
// On [s0, s1] a polynomial of degree d is sum_i b_i B_i,d(s) with the Bernstein basis functions
// B_i,d >= 0 summing to 1, b_0 its value at s0 and b_d at s1. So it is positive on (s0, s1] if
// b_0 >= 0 and every other b_i > 0, and it has at most as many roots there as the b_i have sign
// changes (Descartes' rule for the Bernstein basis). De Casteljau's algorithm gives the
// coefficients of the two halves. The search takes the left half first, so the root it brackets
// is the first one; a bracket narrower than 2^-kMaxDepth of the interval whose end is still
// positive is a touch below resolution, not a root (the same limit as EdgeMarch's grazing test).
#include <cmath>

namespace sb::event_detail {

template <int D>
class BernsteinRoots {
 public:
  BernsteinRoots() {
    // ratio_[i][j] = C(i, j) / C(D, j), the monomial-to-Bernstein weights.
    double C[D + 1][D + 1] = {};
    for (int n = 0; n <= D; ++n) {
      C[n][0] = 1.0;
      for (int k = 1; k <= n; ++k) C[n][k] = C[n - 1][k - 1] + C[n - 1][k];
    }
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= i; ++j) ratio_[i][j] = C[i][j] / C[D][j];
  }

  // p(tau) = sum_j c[j] tau^j, j = 0 .. D. The first bracket [lo, hi] in [0, h] with p(lo) >= 0
  // (> 0 unless lo = 0) and p(hi) <= 0 holding one sign change, or false if p stays positive.
  // A coefficient that is not finite gives the whole step as the bracket (the refinement then
  // stops at its start, as the Dormand-Prince search does on a NaN), never a search of every
  // half: the positivity test fails on NaN at every depth.
  bool first_bracket(const double* c, double h, double& lo, double& hi) const {
    double a[D + 1], b[D + 1] = {};
    double hj = 1.0;
    for (int j = 0; j <= D; ++j) a[j] = c[j] * hj, hj *= h;
    for (int j = 0; j <= D; ++j)
      if (!std::isfinite(a[j])) {
        lo = 0.0, hi = h;
        return true;
      }
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= i; ++j) b[i] += ratio_[i][j] * a[j];
    double s0, s1;
    if (!isolate(b, 0.0, 1.0, 0, s0, s1)) return false;
    lo = s0 * h, hi = s1 * h;
    return true;
  }

 private:
  static constexpr int kMaxDepth = 30;

  static int sign_changes(const double* b) {
    int n = 0, last = 0;
    for (int i = 0; i <= D; ++i) {
      const int sg = b[i] > 0 ? 1 : b[i] < 0 ? -1 : 0;
      if (sg != 0 && last != 0 && sg != last) ++n;
      if (sg != 0) last = sg;
    }
    return n;
  }

  bool isolate(const double* b, double s0, double s1, int depth, double& lo, double& hi) const {
    bool positive = b[0] >= 0;
    for (int i = 1; i <= D && positive; ++i) positive = b[i] > 0;
    if (positive) return false;
    if ((b[0] > 0 && b[D] <= 0 && sign_changes(b) == 1) || depth == kMaxDepth) {
      if (!(b[D] <= 0)) return false;  // a touch below resolution (or NaN-free positive end)
      lo = s0, hi = s1;
      return true;
    }
    double left[D + 1], right[D + 1], w[D + 1];
    for (int i = 0; i <= D; ++i) w[i] = b[i];
    left[0] = w[0], right[D] = w[D];
    for (int r = 1; r <= D; ++r) {
      for (int i = 0; i + r <= D; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
      left[r] = w[0], right[D - r] = w[D - r];
    }
    const double mid = 0.5 * (s0 + s1);
    return isolate(left, s0, mid, depth + 1, lo, hi) || isolate(right, mid, s1, depth + 1, lo, hi);
  }

  double ratio_[D + 1][D + 1] = {};
};

}  // namespace sb::event_detail
