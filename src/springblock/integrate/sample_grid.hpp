#pragma once
// Samples sit at t_k = k dt for integer k (no accumulated rounding over long runs). Shared by the
// integrators that hand the observer a stretch of samples at once (Observer::sample_affine).
#include <cmath>

namespace sb::event_detail {

// The first index k >= k_min with k dt >= t: the samples k_min .. k - 1 are those before t,
// counted with the same floating-point products the sample clock uses.
inline long long first_sample_at_or_after(double t, double dt, long long k_min) {
  long long k = static_cast<long long>(std::ceil(t / dt));
  while (k > k_min && static_cast<double>(k - 1) * dt >= t) --k;
  while (static_cast<double>(k) * dt < t) ++k;
  return k;
}

}  // namespace sb::event_detail
