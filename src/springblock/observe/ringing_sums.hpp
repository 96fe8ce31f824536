#pragma once
// The friction sums sum_i |f_i| and sum_i f_i over the contact blocks, from the forces an
// integrator knows exactly in a quiet phase (RingingForces): at the sample it serves, over a
// stretch of samples at once, and bounds on them over a stretch. What an observer of mu(t) needs
// without any block's position written.
#include <vector>

#include "springblock/observe/common_slope_sum.hpp"
#include "springblock/observe/ringing_forces.hpp"

namespace sb {

class RingingSums {
 public:
  explicit RingingSums(RingingForces& forces);
  RingingForces& forces() const { return f_; }

  // The sums at the sample the integrator serves, time t. Rounds differently from summing the
  // forces of written rows, not otherwise different.
  void at(double t, double& sum_abs, double& sum_signed);
  // The same two sums added over the n samples at t_k = k dt, k = k0 .. k0 + n - 1: in closed
  // form for every force that cannot change sign over them (each |f_i| is then +-f_i, and the
  // ringing's sum over equally spaced samples is RingingForces::sums), sample by sample for a
  // force beside a groove whose sign the bounds cannot fix (from RingingForces::series; the other
  // terms are not visited). A force beside no groove is affine with the common slope and crosses
  // zero at a known time: the samples on either side of it are summed apart. False (nothing
  // summed) when the ringing has no closed-form sum. Depends on k0 and n only, not on what was
  // sampled before.
  bool window(long k0, double dt, long n, double& sum_abs, double& sum_signed);
  // Bounds on the sums at() gives at samples k0 .. k0 + n - 1, for an observer after their
  // maximum: at sample k0 + j each sum lies within `reach` of the straight line from its value
  // `first` at j = 0 to `last` at j = n - 1 (evaluated as first + (last - first) j / (n - 1)),
  // round-off of the sums, the line and the bounds included. False when some force may change
  // sign over them.
  struct Envelope {
    double abs_first, abs_last, signed_first, signed_last, reach;
  };
  bool envelope(long k0, double dt, long n, Envelope& env);

 private:
  // The interior forces' sums, t0 and the edges of the forces' current phase, and at()'s split
  // of the edges (split_edges) for the phase's end as the forces know it.
  void prepare();
  void split_edges(double tau_end);
  // window's and envelope's test, and an edge's reach.
  bool keeps_signs(double tau0, double tau_last, bool need_sums);
  double edge_reach(const EdgeForce& e) const;
  // window's share of the flagged edges: their forces summed sample by sample.
  void unsure_sums(long k0, double dt, long n, double& sum_abs, double& sum_signed);

  RingingForces& f_;
  CommonSlopeSum interior_;         // the contact blocks with no groove neighbour
  long interior_of_ = -1;           // the phase interior_ holds (RingingForces::phase)
  double t0_ = 0;
  const std::vector<EdgeForce>* edges_ = nullptr;
  // at()'s edges: those beside a live group or whose affine force may change sign before the
  // phase ends are summed at each sample (listed); every other one keeps its sign over the whole
  // phase, so |f| = sign(f) f and their sums are one affine function of tau, added up once.
  struct Split {
    std::vector<int> listed;
    double abs_a = 0, abs_b = 0, signed_a = 0, signed_b = 0;
    double tau_end = -1;           // the phase end it was made for
    std::vector<char> live;        // per group: live in this phase
  };
  Split split_;
  std::vector<double> now_;         // per term: its value (at; the groups not live stay 0)
  std::vector<double> terms_;       // per term: its sum (window)
  std::vector<double> bound_;       // per term: bound on it from a stretch's first sample on
  std::vector<char> unsure_;        // per edge: its sign not fixed by the bounds
  std::vector<int> slot_;           // unsure_sums: per group, its place in values_ (-1: none)
  std::vector<double> values_;      // unsure_sums: those groups' terms, sample by sample
};

}  // namespace sb
