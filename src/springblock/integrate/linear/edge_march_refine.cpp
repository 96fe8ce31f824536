// EdgeMarch's refinement of a bracket to round-off in t (edge_march.hpp): the gap and its slope
// from a direct evaluation or from the local Taylor polynomial, and the safeguarded Newton
// iteration on them.
#include <cmath>

#include "springblock/integrate/numerics/estrin.hpp"
#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/infinity.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {

void EdgeMarch::expand(const double* q0, const double* p0, double tau_base) {
  poly_.on = poly_.ok;
  if (!poly_.on) return;
  poly_.base = tau_base;
  direct(q0, p0, tau_base, scratch_.q.data(), scratch_.p.data());
  const double* q = scratch_.q.data();
  const double* qd = scratch_.p.data();
  // coef_j = F^(j)(base) / j!, with F and F' summed as force_at and gap sum them (lane_sum).
  for (int j = 0; j <= kTaylor; ++j) poly_.coef[j] = 0.0;
  for (std::size_t k = 0; k < sum_.modes.size(); ++k)
    add_taylor(sum_.w[k], q[k], qd[k], 2.0 * sum_.modes[k].mode.alpha, sum_.modes[k].mode.omega2, kTaylor, poly_.coef);
  taylor_scale(kTaylor, poly_.coef);
  poly_.coef[0] = force_at(tau_base, q);
  poly_.coef[1] = gap_.b + weighted(qd);
  for (int j = 0; j < kTaylor; ++j) poly_.dcoef[j] = (j + 1) * poly_.coef[j + 1];
}

void EdgeMarch::local_eval(double tau, double& F, double& dF) {
  const double x = tau - poly_.base;
  F = estrin<kTaylor>(poly_.coef, x);
  dF = estrin<kTaylor - 1>(poly_.dcoef, x);
}

void EdgeMarch::gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg) {
  double F, dF;
  if (poly_.on) {
    local_eval(tau, F, dF);
  } else {
    direct(q0, p0, tau);
    F = force_at(tau, now_.q.data());
    dF = gap_.b + weighted(now_.p.data());
  }
  g = fs - measure(F);
  dg = (gap_.sense == Sense::Abs && F < 0) ? dF : -dF;
}

// The bracket's gap g = fs - measure(F) is > 0 at lo and <= 0 at hi.
double EdgeMarch::refine(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                         double ghi) {
  // [from, hi] shrunk; x, gx, dgx: an evaluation inside it to start Newton from (x = +inf: none).
  auto shrink = [&](double from, double gfrom, double x, double gx, double dgx) {
    return first_root_newton([&](double at, double& g, double& dg) { gap(q0, p0, fs, at, g, dg); }, from, gfrom, hi,
                             ghi, [&](double end) { return time_round_off(t0 + end); }, x, gx, dgx);
  };
  const double x = shrink(lo, glo, kInf, 0, 0);
  if (!poly_.on) return x;
  // The polynomial's root, confirmed by the closed form (see the header).
  poly_.on = false;
  double gx, dgx;
  gap(q0, p0, fs, x, gx, dgx);
  if (gx <= 0) return x;
  return shrink(x, gx, x, gx, dgx);
}

}  // namespace sb::event_detail
