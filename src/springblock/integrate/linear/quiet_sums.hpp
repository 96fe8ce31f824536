#pragma once
// The friction sums of a quiet phase's samples (quiet_phase.hpp), in closed form: what an
// observer of mu(t) alone needs, without the rows written. Each contact block's force is its
// affine part (QuietPhase::Edge::fa + fb tau, or for a block beside no groove its force at t0
// plus the slider's slope, summed over all such blocks at once by CommonSlopeSum) plus K_int
// times its segments' end rows' modal parts.
#include <vector>

#include "springblock/integrate/linear/common_slope_sum.hpp"
#include "springblock/integrate/linear/coords.hpp"
#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/observe/observer.hpp"

namespace sb::event_detail {

class QuietSums {
 public:
  explicit QuietSums(const QuietPhase& phase);

  // After QuietPhase::advance_sample(t, true): the sums over the contact blocks of |f_i| and f_i
  // at t, from the sample cursor (the settle-scale cut of ends_only samples applies). Rounds
  // differently from summing the forces of the written rows, not otherwise different.
  void at(double t, double& sum_abs, double& sum_signed);
  // The same two sums added over the n samples at t_k = k dt, k = k0 .. k0 + n - 1: in closed
  // form for every contact block's force that cannot change sign over them (each |f_i| is then
  // +-f_i, and f_i is affine plus modes, whose sum over equally spaced samples is a geometric
  // series: Transitions::sample_sum), sample by sample for a force beside a groove whose sign the
  // bounds cannot fix (its segments' end rows by the sample recurrence; the other segments are
  // not visited). Costs two direct evaluations of each live mode instead of a recurrence step and
  // a dot product per mode and sample. The modes are cut where samples cut them
  // (sample_dead_tau), so the sums are those of at() over the same samples up to round-off. A
  // force beside no groove is affine with the slider's slope and crosses zero at a known time:
  // the samples on either side of it are summed apart. False (nothing summed) when a mode has no
  // closed-form sum. Reads the phase's records only, not its sample cursor: the sums depend on k0
  // and n only, not on what was sampled before.
  bool window(long k0, double dt, long n, double& sum_abs, double& sum_signed);
  // For an observer of the loading peak: bounds on the sums at() gives at the samples
  // k0 .. k0 + n - 1 (SampleStretch::Envelope), when no contact block's force can change sign
  // over them; false otherwise.
  bool envelope(long k0, double dt, long n, SampleStretch::Envelope& env);

 private:
  // The interior forces' sums made for the phase's current start.
  void prepare();
  // window's and envelope's test, and an edge's modal reach.
  bool keeps_signs(double tau0, double tau_last, bool need_sums);
  double edge_reach(const QuietPhase::Edge& e) const;
  // window's share of the flagged edges: their forces summed sample by sample.
  void unsure_sums(long k0, double dt, long n, double& sum_abs, double& sum_signed);

  const QuietPhase& phase_;
  CommonSlopeSum interior_;         // the contact blocks with no groove neighbour
  long interior_of_ = -1;           // the phase interior_ holds (QuietPhase::phases())
  std::vector<double> end_dots_;    // per segment: first and last row . q (at, window)
  Coords w0_, w1_;                  // per slot: modes at the window's first sample and past its last live one
  std::vector<double> end_bound_;   // per segment: bounds on its first and last rows' modal part
  std::vector<char> unsure_;        // per edge: its sign not fixed by the bounds
  std::vector<int> slot_;           // unsure_sums: per segment, its place in row_values_ (-1: none)
  std::vector<double> row_values_;  // unsure_sums: those rows' modal parts, sample by sample
};

}  // namespace sb::event_detail
