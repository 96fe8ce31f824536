// EdgeMarch's refinement of a bracket to round-off in t (edge_march.hpp): the gap and its slope
// from a direct evaluation or from the local Taylor polynomial, and the safeguarded Newton
// iteration on them.
#include <cmath>

#include "springblock/integrate/numerics/estrin.hpp"
#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/numerics/infinity.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {

void EdgeMarch::expand(const double* q0, const double* p0, double tau_base) {
  local_ = taylor_ok_;
  if (!local_) return;
  base_ = tau_base;
  direct(q0, p0, tau_base, qs_.data(), qds_.data());
  const double* q = qs_.data();
  const double* qd = qds_.data();
  // coef_j = F^(j)(base) / j!: F and F' at the base summed as force_at and gap sum them, so
  // the polynomial there is their value to the last bit.
  for (int j = 0; j <= kTaylor; ++j) coef_[j] = 0.0;
  for (std::size_t k = 0; k < modes_.size(); ++k)
    add_taylor(w_[k], q[k], qd[k], 2.0 * modes_[k].mode.alpha, modes_[k].mode.omega2, kTaylor, coef_);
  taylor_scale(kTaylor, coef_);
  coef_[0] = force_at(tau_base, q);
  coef_[1] = b_ + weighted(qd);
  for (int j = 0; j < kTaylor; ++j) dcoef_[j] = (j + 1) * coef_[j + 1];
}

void EdgeMarch::local_eval(double tau, double& F, double& dF) {
  ++local_evals;
  const double x = tau - base_;
  F = estrin<kTaylor>(coef_, x);
  dF = estrin<kTaylor - 1>(dcoef_, x);
}

void EdgeMarch::gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg) {
  double F, dF;
  if (local_) {
    local_eval(tau, F, dF);
  } else {
    direct(q0, p0, tau);
    F = force_at(tau, q_.data());
    dF = b_ + weighted(qd_.data());
  }
  g = fs - measure(F);
  dg = (sense_ == Sense::Abs && F < 0) ? dF : -dF;
}

// Shrink a bracket with gap g = fs - measure(F) > 0 at lo and <= 0 at hi to round-off in t: the
// safeguarded Newton iteration of first_root_newton, whose slopes gap() gives for free. Its
// evaluations are the local polynomial's when it holds, and then one direct evaluation confirms
// the result (see the header).
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
  return first_root_newton([&](double at, double& g, double& dg) { gap(q0, p0, fs, at, g, dg); }, lo, glo, hi, ghi,
                           [&](double end) { return time_round_off(t0 + end); }, x, gx, dgx);
}

}  // namespace sb::event_detail
