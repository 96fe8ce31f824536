// EdgeMarch's refinement of a bracket to round-off in t (edge_march.hpp): the gap and its slope
// from a direct evaluation or from the local Taylor polynomial, and the safeguarded Newton
// iteration on them.
#include <cmath>

#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/infinity.hpp"
#include "springblock/integrate/round_off.hpp"

namespace sb::event_detail {

void EdgeMarch::expand(const double* q0, const double* p0, double tau_base) {
  local_ = taylor_ok_;
  if (!local_) return;
  base_ = tau_base;
  direct(q0, p0, tau_base, qs_.data(), qds_.data());
  const double* q = qs_.data();
  const double* qd = qds_.data();
  // coef_j = F^(j)(base) / j!: the constant term sums like force_at, so F at the base is its
  // value to the last bit.
  coef_[0] = a_ + b_ * tau_base;
  coef_[1] = b_;
  for (int j = 2; j <= kTaylor; ++j) coef_[j] = 0.0;
  for (std::size_t k = 0; k < modes_.size(); ++k)
    add_taylor(w_[k], q[k], qd[k], 2.0 * modes_[k].mode.alpha, modes_[k].mode.omega2, kTaylor, coef_);
  taylor_scale(kTaylor, coef_);
}

void EdgeMarch::local_eval(double tau, double& F, double& dF) {
  ++local_evals;
  const double x = tau - base_;
  F = coef_[kTaylor], dF = 0.0;
  for (int j = kTaylor - 1; j >= 0; --j) dF = dF * x + F, F = F * x + coef_[j];
}

void EdgeMarch::gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg) {
  double F, dF;
  if (local_) {
    local_eval(tau, F, dF);
  } else {
    direct(q0, p0, tau);
    F = a_ + b_ * tau, dF = b_;
    for (std::size_t k = 0; k < modes_.size(); ++k) F += w_[k] * q_[k], dF += w_[k] * qd_[k];
  }
  g = fs - measure(F);
  dg = (sense_ == Sense::Abs && F < 0) ? dF : -dF;
}

// Shrink a bracket with gap g = fs - measure(F) > 0 at lo and <= 0 at hi to round-off in t;
// returns the crossed end. Every evaluation gives the gap's slope for free (gap()), so the next
// point is Newton's, aimed a quarter of the tolerance past its root estimate: once the estimate
// is that good the point lands on the far side and closes the bracket. A Newton point outside
// the bracket, or a Newton step that did not halve it, hands one iteration to regula falsi with
// the Illinois modification (bisection when the secant point is not well inside), which keeps
// the bracket at every iteration. A smooth gap takes ~5 evaluations instead of the ~10 of
// regula falsi alone; they are the local polynomial's when it holds, and then one direct
// evaluation confirms the result (see the header).
double EdgeMarch::refine(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                         double ghi) {
  const double x = shrink(q0, p0, fs, t0, lo, glo, hi, ghi, kInf, 0, 0);
  if (!local_) return x;
  // The polynomial's root, confirmed by the closed form (see the header).
  local_ = false;
  double gx, dgx;
  gap(q0, p0, fs, x, gx, dgx);
  if (gx <= 0) return x;
  return shrink(q0, p0, fs, t0, x, gx, hi, ghi, x, gx, dgx);
}

double EdgeMarch::shrink(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                         double ghi, double x, double gx, double dgx) {
  int kept = 0;  // +1: lo kept last time, -1: hi kept last time
  bool was_newton = false;
  const bool have = x != kInf;  // x, gx, dgx: the last evaluation (from it > 0 on, or given)
  double w_before = kInf;
  for (int it = 0; it < 200; ++it) {
    const double w = hi - lo, tol = time_round_off(t0 + hi);
    if (!(w > tol)) break;
    double mid = kInf;
    if ((it > 0 || have) && dgx != 0 && !(was_newton && w > 0.5 * w_before)) {
      const double step = -gx / dgx;
      mid = x + step + std::copysign(0.25 * tol, step);
      if (!(mid > lo && mid < hi)) mid = kInf;
    }
    was_newton = mid != kInf;
    if (!was_newton) {
      mid = hi - ghi * (hi - lo) / (ghi - glo);
      if (!(mid > lo + 1e-3 * w && mid < hi - 1e-3 * w)) mid = 0.5 * (lo + hi);
    }
    w_before = w;
    gap(q0, p0, fs, mid, gx, dgx);
    x = mid;
    if (gx > 0) {
      lo = mid, glo = gx;
      if (kept == -1) ghi *= 0.5;
      kept = -1;
    } else {
      hi = mid, ghi = gx;
      if (kept == 1) glo *= 0.5;
      kept = 1;
    }
  }
  return hi;
}

}  // namespace sb::event_detail
