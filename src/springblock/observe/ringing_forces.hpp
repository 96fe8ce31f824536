#pragma once
// What an integrator knows exactly of the contact blocks' friction forces while every contact
// block is stuck (a quiet phase of the event method): each force is affine in tau = t - t0 plus,
// for a block beside grooves, the spring to each groove row next to it times that row's ringing. The ringing
// is a sum of damped modes, whose values at equally spaced samples the integrator can add up and
// bound without visiting each sample. An observer turns this into whatever it reads (sum |f|,
// sum f, a block's own force), so no integrator computes an observable.
//
// The ringing comes in groups (a groove run between stuck blocks), each with two terms: the
// ringing of its first row and of its last (equal for a run of one block). Term 2 g + e is end e
// of group g.
#include <vector>

namespace sb {

// A contact block beside grooves: its force is fa + fb tau + sum over its n ringing terms of
// k[r] times term[r] (k: the spring to that groove block).
struct EdgeForce {
  double fa = 0, fb = 0;
  int n = 0;
  int term[2] = {-1, -1};
  double k[2] = {0, 0};
};

class RingingForces {
 public:
  virtual ~RingingForces() = default;

  virtual double t0() const = 0;
  // Changes whenever the description below does (a new quiet phase).
  virtual long phase() const = 0;
  // The contact blocks beside no groove: forces a + slope tau, a at tau = 0, one common slope.
  virtual const std::vector<double>& interior() const = 0;
  virtual double interior_slope() const = 0;
  virtual const std::vector<EdgeForce>& edges() const = 0;
  virtual int groups() const = 0;

  // The groups whose terms may be nonzero in this phase (the others are 0 throughout), and a
  // time after every sample of the phase (tau < tau_end; +inf while the phase's end is unknown).
  // An observer that reads every sample can then sum once per phase what cannot change there.
  virtual const std::vector<int>& live_groups() const = 0;
  virtual double tau_end() const = 0;
  // The live groups' terms at the sample the integrator is serving (tau = its time - t0); 0
  // where the group's modes are below the sample scales. The other groups' entries are not
  // written.
  virtual void terms_now(double tau, double* x) const = 0;
  // From the sample at tau0 on: bound[term] >= |term| at every later time (0 for a group whose
  // modes no longer count). With sums_wanted, false when some group's modes have no closed-form
  // sample sum (then sums() cannot be asked for this stretch).
  virtual bool bounds(double tau0, bool sums_wanted, double* bound) = 0;
  // After bounds() at the first of them: every term summed over the samples t_k = k dt,
  // k = k0 .. k0 + n - 1 (a group's samples after its modes stop counting add 0).
  virtual void sums(long k0, double dt, long n, double* sum) = 0;
  // After bounds() at the first of them: the terms of the groups with slot[g] >= 0 at each of
  // those samples, values[2 n slot[g] + e n + j] for end e and sample j (the caller zeroes them;
  // samples after the modes stop counting are left so).
  virtual void series(long k0, double dt, long n, const int* slot, double* values) = 0;
};

}  // namespace sb
