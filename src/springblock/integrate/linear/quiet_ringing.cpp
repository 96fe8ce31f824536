#include "springblock/integrate/linear/quiet_ringing.hpp"

#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/envelope.hpp"

namespace sb::event_detail {

QuietRinging::QuietRinging(const QuietPhase& phase)
    : phase_(phase),
      w0_(static_cast<int>(phase.cursor_.x.q.size())),
      w1_(static_cast<int>(phase.cursor_.x.q.size())) {}

void QuietRinging::terms_now(double tau, double* x) const {
  for (int k : phase_.live_) {
    const QuietPhase::GrooveRun& s = phase_.segs_[k];
    double first = 0, last = 0;
    if (tau <= s.sample_dead_tau) s.shape->end_rows(phase_.cursor_.x.q.data() + s.first, first, last);
    x[2 * k] = first, x[2 * k + 1] = last;
  }
}

bool QuietRinging::bounds(double tau0, bool sums_wanted, double* bound) {
  for (std::size_t g = 0; g < phase_.segs_.size(); ++g) {
    const QuietPhase::GrooveRun& s = phase_.segs_[g];
    bound[2 * g] = bound[2 * g + 1] = 0.0;
    if (!(tau0 <= s.sample_dead_tau)) continue;
    const RunShape& d = *s.shape;
    for (int k = 0; sums_wanted && k < s.n; ++k)
      if (std::isnan(d.steps.sample_sum[k][0])) return false;  // no closed-form sum for this mode
    double* q = w0_.q.data() + s.first;
    double* p = w0_.p.data() + s.first;
    d.evolve(phase_.store_.q0() + s.first, phase_.store_.p0() + s.first, tau0, q, p);
    bound[2 * g] = row_deviation_bound(d, 0, q, p);
    bound[2 * g + 1] = row_deviation_bound(d, s.n - 1, q, p);
  }
  return true;
}

// Over samples tau_j = tau_0 + j dt a mode's sum is the geometric series of its sample transition
// P: (I - P)^-1 (x_0 - x_m), x_j = (q, q')(tau_j) (first row only), from the modes at the first
// sample and past the last live one.
void QuietRinging::sums(long k0, double dt, long n, double* sum) {
  summed_ = true;
  const double tau0 = tau_of(k0, dt);
  for (std::size_t g = 0; g < phase_.segs_.size(); ++g) {
    const QuietPhase::GrooveRun& s = phase_.segs_[g];
    sum[2 * g] = sum[2 * g + 1] = 0.0;
    if (!(tau0 <= s.sample_dead_tau)) continue;
    long live = n;
    while (live > 0 && !(tau_of(k0 + live - 1, dt) <= s.sample_dead_tau)) --live;  // rare: dies in the stretch
    const RunShape& d = *s.shape;
    const double tau1 = tau_of(k0 + live, dt);
    double* q1 = w1_.q.data() + s.first;
    double* p1 = w1_.p.data() + s.first;
    d.evolve(phase_.store_.q0() + s.first, phase_.store_.p0() + s.first, tau1, q1, p1);
    const double* q = w0_.q.data() + s.first;
    const double* p = w0_.p.data() + s.first;
    for (int k = 0; k < s.n; ++k)  // each mode's sum over the stretch, in place of its modes at the end
      q1[k] = d.steps.sample_sum[k][0] * (q[k] - q1[k]) + d.steps.sample_sum[k][1] * (p[k] - p1[k]);
    double first, last;
    d.end_rows(q1, first, last);
    sum[2 * g] = first, sum[2 * g + 1] = last;
  }
}

void QuietRinging::series(long k0, double dt, long n, const int* slot, double* values) {
  const std::size_t nn = static_cast<std::size_t>(n);
  const double tau0 = tau_of(k0, dt);
  for (std::size_t g = 0; g < phase_.segs_.size(); ++g) {
    const QuietPhase::GrooveRun& s = phase_.segs_[g];
    if (slot[g] < 0 || !(tau0 <= s.sample_dead_tau)) continue;
    const RunShape& d = *s.shape;
    double* q = w1_.q.data() + s.first;  // a working copy
    double* p = w1_.p.data() + s.first;
    std::copy(w0_.q.begin() + s.first, w0_.q.begin() + s.first + s.n, q);
    std::copy(w0_.p.begin() + s.first, w0_.p.begin() + s.first + s.n, p);
    double* first = values + 2 * nn * static_cast<std::size_t>(slot[g]);
    double* last = first + n;
    for (long j = 0; j < n && tau_of(k0 + j, dt) <= s.sample_dead_tau; ++j) {
      d.end_rows(q, first[j], last[j]);
      d.step_sample(q, p);
    }
  }
}

}  // namespace sb::event_detail
