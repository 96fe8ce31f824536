#pragma once
// A quiet phase's contact forces as observers read them (RingingForces): the affine parts and
// segment ends QuietPhase keeps, and its segments' end rows at a sample, summed over samples (the
// geometric series of each mode's sample transition: Transitions::sample_sum) and bounded from a
// sample on (each mode's energy never grows: row_deviation_bound). The groups are the phase's
// segments, their two terms the modal parts of a segment's first and last rows.
#include "springblock/integrate/linear/coords.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/observe/ringing_forces.hpp"

namespace sb::event_detail {

class QuietRinging final : public RingingForces {
 public:
  explicit QuietRinging(const QuietPhase& phase);

  double t0() const override { return phase_.span_.t0; }
  long phase() const override { return phase_.interior_.phase; }
  const std::vector<double>& interior() const override { return phase_.interior_.a; }
  double interior_slope() const override { return phase_.slider_slope_; }
  const std::vector<EdgeForce>& edges() const override { return phase_.edges_.forces; }
  int groups() const override { return static_cast<int>(phase_.segs_.size()); }
  const std::vector<int>& live_groups() const override { return phase_.live_; }
  double tau_end() const override { return phase_.span_.next - phase_.span_.t0; }

  // From the sample cursor (QuietPhase::advance_sample of the same time).
  void terms_now(double tau, double* x) const override;
  // The bounds come from the modes at tau0 itself, never from an earlier sample's, so what an
  // observer does with a stretch depends on the phase and the stretch only, not on which samples
  // were served before it.
  bool bounds(double tau0, bool sums_wanted, double* bound) override;
  void sums(long k0, double dt, long n, double* sum) override;
  // By the sample recurrence from the modes at the first sample, as advance_sample brings them.
  void series(long k0, double dt, long n, const int* slot, double* values) override;

  // Whether sums() was asked since the last clear (the work profile counts such samples apart).
  bool summed() const { return summed_; }
  void clear_summed() { summed_ = false; }

 private:
  double tau_of(long k, double dt) const { return static_cast<double>(k) * dt - phase_.span_.t0; }

  const QuietPhase& phase_;
  // Per slot: the modes at a stretch's first sample (bounds); work space of sums and series.
  Coords w0_, w1_;
  bool summed_ = false;
};

}  // namespace sb::event_detail
