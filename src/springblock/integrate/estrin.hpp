#pragma once
// A polynomial of fixed degree d, p(x) = sum_j c[j] x^j, evaluated by Estrin's scheme:
// neighbouring coefficients paired as c_2i + c_2i+1 x, those pairs paired with x^2, and so on.
// Horner's rule is one chain of d dependent multiply-adds, 8 cycles each in this library (no
// contraction into fused multiply-adds, kernel_clones.hpp); this is ceil(log2(d + 1)) levels of
// independent ones. The event refinements evaluate their polynomials several times per located
// event, so the latency is their cost. The doubles differ from Horner's by round-off
// (paper/choices.md).
namespace sb {

template <int d>
inline double estrin(const double* c, double x) {
  double a[d + 1];
  for (int i = 0; i <= d; ++i) a[i] = c[i];
  int n = d + 1;
  for (double xp = x; n > 1; xp *= xp) {
    for (int i = 0; i < n / 2; ++i) a[i] = a[2 * i] + a[2 * i + 1] * xp;
    if (n % 2 != 0) a[n / 2] = a[n - 1];
    n = (n + 1) / 2;
  }
  return a[0];
}

}  // namespace sb
