#include "springblock/integrate/step/dopri5.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sb::event_detail {

Dopri5::Dopri5(int N) : store_(14 * static_cast<std::size_t>(N)), ut_(N), u1_(N) {
  for (int s = 0; s < 14; ++s) k_[s] = store_.data() + static_cast<std::size_t>(s) * N;
}

void Dopri5::set_frozen(const double* u, const std::vector<BlockRange>& spans) {
  // Only the borders: copying the whole chain twice at every switch was O(N) per switch.
  for (const BlockRange& sp : spans)
    for (int i : {sp.lo - 1, sp.hi})
      if (i >= 0 && i < std::ssize(ut_)) ut_[i] = u1_[i] = u[i];  // stage 7 reads the neighbours from u1
}

void Dopri5::accept_fsal() {
  std::swap(k_[0], k_[6]);
  std::swap(k_[7], k_[13]);
}

namespace {

// The continuous extension of component i at theta, from the step's start y0, end y1 and the
// seven slopes K[0..6] of that component: the one place it is written.
SB_INLINE double dense_at(const double* __restrict y0, const double* __restrict y1, const double* const* K, double h,
                          int i, double th) {
  using T = Dp5Tableau;
  const double dy = y1[i] - y0[i];
  const double r3 = h * K[0][i] - dy;
  const double r4 = dy - h * K[6][i] - r3;
  const double r5 = h * (T::d1 * K[0][i] + T::d3 * K[2][i] + T::d4 * K[3][i] + T::d5 * K[4][i] +
                         T::d6 * K[5][i] + T::d7 * K[6][i]);
  const double s = 1.0 - th;
  return y0[i] + th * (dy + s * (r3 + th * (r4 + s * r5)));
}

SB_KERNEL_CLONES void dense_span(int lo, int hi, const double* __restrict y0, const double* __restrict y1,
                                 const double* const* K, double h, double th, double* __restrict out) {
  for (int i = lo; i < hi; ++i) out[i] = dense_at(y0, y1, K, h, i, th);
}

}  // namespace

double Dopri5::dense(const double* y0, const double* y1, int b, int i, double th) const {
  return dense_at(y0, y1, k_ + b, h_, i, th);
}

void Dopri5::dense_v_spans(const std::vector<BlockRange>& spans, double th, double* out) const {
  for (const BlockRange& sp : spans) dense_span(sp.lo, sp.hi, v0_, k_[6], k_ + 7, h_, th, out);
}

namespace {
// Largest weighted error of the u and v components over [lo, hi); restrict-qualified and
// branch-free (stuck blocks weighted by mobile = 0). GCC keeps a floating-point max reduction
// scalar unless told its order does not matter (omp simd); a max is exact, so it does not.
SB_KERNEL_CLONES double span_error(int lo, int hi, double h, const double* __restrict k0,
                                   const double* __restrict k2, const double* __restrict k3,
                                   const double* __restrict k4, const double* __restrict k5,
                                   const double* __restrict k6, const double* __restrict y0,
                                   const double* __restrict y1, const double* __restrict mobile, double atol,
                                   double rtol) {
  using T = Dp5Tableau;
  // `seen` sums the ratios only to carry a NaN (a vector max may drop one): a NaN error must
  // reject the step.
  double worst = 0, seen = 0;
#pragma omp simd reduction(max : worst) reduction(+ : seen)
  for (int i = lo; i < hi; ++i) {
    const double e = h * (T::e1 * k0[i] + T::e3 * k2[i] + T::e4 * k3[i] + T::e5 * k4[i] + T::e6 * k5[i] +
                          T::e7 * k6[i]);
    const double a0 = std::fabs(y0[i]), a1 = std::fabs(y1[i]);
    const double sc = atol + rtol * (a0 < a1 ? a1 : a0);
    const double r = mobile[i] * std::fabs(e) / sc;
    worst = worst > r ? worst : r;
    seen += r;
  }
  return std::isnan(seen) ? seen : worst;
}
}  // namespace

double Dopri5::error_norm(const std::vector<BlockRange>& spans, const double* u, const double* v,
                          const double* mobile, double atol_u, double atol_v, double rtol) const {
  // Max norm over the moving components: stuck blocks carry no error, and an RMS over the
  // whole chain would dilute the error of the one block that slides.
  // A NaN from any span is kept (std::max(worst, NaN) would return worst): it rejects the step.
  double worst = 0;
  auto keep = [&worst](double e) { worst = std::isnan(e) || e > worst ? e : worst; };
  for (const BlockRange& sp : spans) {
    keep(span_error(sp.lo, sp.hi, h_, k_[0], k_[2], k_[3], k_[4], k_[5], k_[6], u, u1_.data(), mobile, atol_u, rtol));
    keep(span_error(sp.lo, sp.hi, h_, k_[7], k_[9], k_[10], k_[11], k_[12], k_[13], v, k_[6], mobile, atol_v, rtol));
  }
  return worst;
}

}  // namespace sb::event_detail
