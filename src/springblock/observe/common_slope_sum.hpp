#pragma once
// Sums of |a_k + s tau| and of a_k + s tau over many affine forces that share one slope s.
//
// In a quiet phase every contact block with no groove neighbour feels the force a_k + K_s v tau
// (its neighbours are stuck; only the slider moves), so mu(t) at a sample needs these two sums
// over most of the chain. Each is O(1) once prepared: a force whose sign is opposite to the
// slope's changes sign exactly once, at tau_k = -a_k / s, and afterwards counts with the slope's
// sign. Sorting those forces by that time and keeping prefix sums gives the sums at any tau from
// one binary search.
#include <vector>

namespace sb {

class CommonSlopeSum {
 public:
  // The forces a[0..n) at tau = 0, all with slope s.
  void reset(const double* a, int n, double s);
  // Sum over k of |a_k + s tau| and of a_k + s tau, for any tau >= 0.
  void at(double tau, double& sum_abs, double& sum_signed) const;
  // How many forces have changed sign by tau (at()'s count).
  int crossed(double tau) const;
  // The sums of at() over m times whose own sum is sum_tau, all with crossed(tau) == p: both
  // sums are then affine in tau, so they add up in closed form.
  void sums(int p, long m, double sum_tau, double& sum_abs, double& sum_signed) const;

 private:
  double s_ = 0, sgn_ = 1;
  int n_ = 0, n_same_ = 0;
  double same_a_ = 0;            // forces that keep their sign: sum of a (sign of s, or s = 0)
  double abs_const_ = 0;         // s = 0: sum of |a|
  double all_a_ = 0;             // every a
  std::vector<double> opp_mag_;  // |a| of the others, increasing: the order in which they cross
  std::vector<double> opp_prefix_;  // opp_prefix_[p] = sum of a over the first p of them
};

}  // namespace sb
