#include "springblock/integrate/dopri5.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sb::event_detail {

Dopri5::Dopri5(int N) : N_(N), store_(14 * static_cast<std::size_t>(N)), ut_(N), vt_(N), u1_(N), v1_(N) {
  for (int s = 0; s < 14; ++s) k_[s] = store_.data() + static_cast<std::size_t>(s) * N;
}

void Dopri5::accept_fsal() {
  std::swap(k_[0], k_[6]);
  std::swap(k_[7], k_[13]);
}

double Dopri5::dense(const double* y0, const double* y1, int b, int i, double th) const {
  using T = Dp5Tableau;
  const double* const* K = k_ + b;
  const double dy = y1[i] - y0[i];
  const double r3 = h_ * K[0][i] - dy;
  const double r4 = dy - h_ * K[6][i] - r3;
  const double r5 = h_ * (T::d1 * K[0][i] + T::d3 * K[2][i] + T::d4 * K[3][i] + T::d5 * K[4][i] +
                          T::d6 * K[5][i] + T::d7 * K[6][i]);
  const double s = 1.0 - th;
  return y0[i] + th * (dy + s * (r3 + th * (r4 + s * r5)));
}

double Dopri5::error_norm(const double* u, const double* v, const double* mobile, double atol_u,
                          double atol_v, double rtol) const {
  using T = Dp5Tableau;
  double const* const* K = k_;
  // Max norm over the moving components: stuck blocks carry no error, and an RMS over the
  // whole chain would dilute the error of the one block that slides.
  // Branch-free (stuck blocks weighted by mobile = 0) so the loop vectorises.
  double worst = 0;
  for (int i = 0; i < N_; ++i) {
    const double eu = h_ * (T::e1 * K[0][i] + T::e3 * K[2][i] + T::e4 * K[3][i] + T::e5 * K[4][i] +
                            T::e6 * K[5][i] + T::e7 * K[6][i]);
    const double ev = h_ * (T::e1 * K[7][i] + T::e3 * K[9][i] + T::e4 * K[10][i] + T::e5 * K[11][i] +
                            T::e6 * K[12][i] + T::e7 * K[13][i]);
    const double su = atol_u + rtol * std::max(std::fabs(u[i]), std::fabs(u1_[i]));
    const double sv = atol_v + rtol * std::max(std::fabs(v[i]), std::fabs(v1_[i]));
    const double e = mobile[i] * std::max(std::fabs(eu) / su, std::fabs(ev) / sv);
    worst = worst > e ? worst : e;
  }
  return worst;
}

}  // namespace sb::event_detail
