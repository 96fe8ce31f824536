#include "springblock/observe/common_slope_sum.hpp"

#include <algorithm>
#include <cmath>

namespace sb {

void CommonSlopeSum::reset(const double* a, int n, double s) {
  s_ = s;
  sgn_ = s < 0 ? -1.0 : 1.0;
  n_ = n;
  n_same_ = 0;
  same_a_ = abs_const_ = all_a_ = 0;
  opp_mag_.clear();
  for (int k = 0; k < n; ++k) {
    all_a_ += a[k];
    abs_const_ += std::fabs(a[k]);
    if (s == 0 || a[k] * sgn_ >= 0) {
      same_a_ += a[k];
      ++n_same_;
    } else {
      opp_mag_.push_back(std::fabs(a[k]));
    }
  }
  // Crossing time |a| / |s|: the smallest magnitudes cross first.
  std::sort(opp_mag_.begin(), opp_mag_.end());
  opp_prefix_.assign(opp_mag_.size() + 1, 0.0);
  for (std::size_t p = 0; p < opp_mag_.size(); ++p) opp_prefix_[p + 1] = opp_prefix_[p] - sgn_ * opp_mag_[p];
}

int CommonSlopeSum::crossed(double tau) const {
  if (s_ == 0) return 0;
  return static_cast<int>(std::upper_bound(opp_mag_.begin(), opp_mag_.end(), std::fabs(s_ * tau)) - opp_mag_.begin());
}

void CommonSlopeSum::sums(int p, long m, double sum_tau, double& sum_abs, double& sum_signed) const {
  const double mm = static_cast<double>(m), st = s_ * sum_tau;
  sum_signed = all_a_ * mm + n_ * st;
  if (s_ == 0) {
    sum_abs = abs_const_ * mm;
    return;
  }
  const int n_opp = static_cast<int>(opp_mag_.size());
  const double crossed = opp_prefix_[p], waiting = opp_prefix_[n_opp] - crossed;
  sum_abs = sgn_ * (((same_a_ + crossed) * mm + (n_same_ + p) * st) - (waiting * mm + (n_opp - p) * st));
}

void CommonSlopeSum::at(double tau, double& sum_abs, double& sum_signed) const {
  const double st = s_ * tau;
  sum_signed = all_a_ + n_ * st;
  if (s_ == 0) {
    sum_abs = abs_const_;
    return;
  }
  // Forces crossed by tau: |a| <= |s| tau.
  const int n_opp = static_cast<int>(opp_mag_.size());
  const int p = static_cast<int>(std::upper_bound(opp_mag_.begin(), opp_mag_.end(), std::fabs(st)) - opp_mag_.begin());
  const double crossed = opp_prefix_[p], waiting = opp_prefix_[n_opp] - crossed;
  // Those with the slope's sign count as sgn (a + s tau); those still opposite as -sgn (a + s tau).
  sum_abs = sgn_ * ((same_a_ + crossed + (n_same_ + p) * st) - (waiting + (n_opp - p) * st));
}

}  // namespace sb
