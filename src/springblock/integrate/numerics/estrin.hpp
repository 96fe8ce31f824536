#pragma once
// A polynomial of fixed degree d, p(x) = sum_j c[j] x^j, evaluated by Estrin's scheme:
// neighbouring coefficients paired as c_2i + c_2i+1 x, those pairs paired with x^2, and so on.
// Horner's rule is one chain of d dependent multiply-adds, 8 cycles each in this library (no
// contraction into fused multiply-adds, kernel_clones.hpp); this is ceil(log2(d + 1)) levels of
// independent ones. The event refinements evaluate their polynomials several times per located
// event, so the latency is their cost. The doubles differ from Horner's by round-off
// (paper/choices.md).
namespace sb {
namespace estrin_detail {

// One level of the scheme on n values, then the next on the (n + 1) / 2 it leaves, with every
// size known at compile time: each level's loop unrolls and its values stay in registers. (One
// loop over the levels, with n halving at run time, kept them in memory and each level waited
// for the last one's stores.) The operations and their order are the same either way.
template <int n>
inline double level(const double* a, double xp) {
  if constexpr (n == 1) {
    return a[0];
  } else {
    double b[(n + 1) / 2];
    for (int i = 0; i < n / 2; ++i) b[i] = a[2 * i] + a[2 * i + 1] * xp;
    if constexpr (n % 2 != 0) b[n / 2] = a[n - 1];
    return level<(n + 1) / 2>(b, xp * xp);
  }
}

}  // namespace estrin_detail

template <int d>
inline double estrin(const double* c, double x) {
  return estrin_detail::level<d + 1>(c, x);
}

}  // namespace sb
