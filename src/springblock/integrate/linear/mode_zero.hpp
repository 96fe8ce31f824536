#pragma once
// The next zero of a damped mode's trajectory, in closed form: when a block moving alone (no
// internal springs, uncoupled.cpp) reverses its velocity.
#include <cmath>
#include <numbers>

#include "springblock/integrate/numerics/infinity.hpp"
#include "springblock/integrate/linear/damped_mode.hpp"

namespace sb::event_detail {

// First zero strictly after `from` of the damped-mode trajectory with q(0) = q0, q'(0) = p0
// (infinity if none). Underdamped: q = e^{-alpha tau} R cos(w tau - phi), zeros every pi / w.
// Critical and overdamped: at most one zero, from q0 + P tau = 0 or tanh(k tau) = -q0 k / P.
inline double next_zero(const DampedMode& m, double q0, double p0, double from) {
  constexpr double kPi = std::numbers::pi;
  const double a = m.alpha, s = m.s, P = p0 + a * q0;
  if (q0 == 0.0 && P == 0.0) return kInf;
  if (s > 0) {
    const double w = m.w;
    const double phi = std::atan2(P / w, q0);
    const double k = std::ceil((w * from - phi - 0.5 * kPi) / kPi);
    double tau = (phi + 0.5 * kPi + k * kPi) / w;
    while (tau <= from) tau += kPi / w;
    return tau;
  }
  if (P == 0.0) return kInf;
  double tau;
  if (s == 0) {
    tau = -q0 / P;
  } else {
    const double k = m.w, r = -q0 * k / P;
    if (!(r > -1.0 && r < 1.0)) return kInf;
    tau = std::atanh(r) / k;
  }
  return tau > from ? tau : kInf;
}

}  // namespace sb::event_detail
