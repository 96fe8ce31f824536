#pragma once
// First threshold crossing of a sum of damped modes: a stuck block's force next to ringing
// groove segments (quiet phase) or short exactly propagated runs (active_set.hpp), or a sliding
// block's velocity in such a run.
//
// The signal is F(tau) = a + b tau + sum_k w_k q_k(tau), q_k damped oscillators. Two senses:
//  * Abs:   the event is |F| >= fs (a stuck block's threshold, either direction);
//  * Upper: the event is F >= fs (one-sided: used for -dir v reaching a sliding block's stop).
// The gap g = fs - |F| (or fs - F) is searched for its first root with three tools, cheapest first:
//  * skips that provably cannot pass a root: g / (bound on |dF|), or the time the affine part
//    needs to come within the modal envelope of the threshold. Each costs one direct evaluation
//    (exp / sincos per mode), so it is used only when it skips many grid steps;
//  * otherwise a uniform grid of step H = kGrid / omega_max advanced by each mode's exact 2x2
//    transition matrix (a few flops per mode, no transcendental calls). A sign change between
//    grid points is a bracket. A root that rises and falls back between two grid points (a
//    grazing touch) is excluded by |F''| <= M2: |F| <= max(|F_a|, |F_b|) + M2 h^2 / 8 on the
//    interval; where that bound does not exclude it, the interval is subdivided (direct
//    evaluations) until it does or a point beyond the threshold is found. The subdivision stops
//    at 2^-kMaxDepth of a grid step: a touch that exceeds the threshold by less than
//    M2 (H 2^-kMaxDepth)^2 / 8 is below resolution, the same limit as the bisection of the
//    Dormand-Prince event search (round-off in t);
//  * refinement of a bracket to round-off in t (direct evaluations): Newton on the gap, whose
//    slope every evaluation gives, kept inside the bracket by regula falsi and bisection.
// Every mode's energy qd^2 + omega^2 q^2 never grows (damping only removes it), so the bounds
// taken at one point hold for all later times.
// With an open origin the event function may start on the threshold (a block that has just
// started to slide, v = 0): tau = 0 is then not an event, the first grid interval is searched
// for a sign change only, and the provable skips start from the first grid point.
#include <vector>

#include "springblock/integrate/linear/damped_mode.hpp"

namespace sb::event_detail {

class EdgeMarch {
 public:
  enum class Sense { Abs, Upper };
  // One mode of an adjacent segment: weight in F, the mode, and its flat index in q0 / p0.
  void add_mode(double w, const DampedMode& mode, int index);
  // After all modes are added: the grid step from the fastest mode, transition matrices.
  void finish();
  // The same with a grid step H fixed by the caller and each mode's transition over H given as
  // P = {p00, p01, p10, p11} (precomputed once per mode, so no transcendental call here).
  void add_mode(double w, const DampedMode& mode, int index, const double* P);
  void finish(double H);
  // Forget the modes (the storage is kept for reuse).
  void reset() { modes_.clear(); }
  // The grid step used by finish() for modes no faster than omega_max.
  static double grid_step(double omega_max);

  void set_sense(Sense sense, bool origin_open) { sense_ = sense, open_ = origin_open; }

  // a, b: affine part of F at the start of the quiet phase; fs: the threshold.
  void set_affine(double a, double b) { a_ = a, b_ = b; }
  double a() const { return a_; }

  // A cheap lower bound on the first crossing (for ordering the searches).
  double lower_bound(const double* q0, const double* p0, double fs);
  // First tau in [0, tau_limit] with |F| >= fs (Upper: F >= fs), or +inf. t0 only sets the
  // round-off scale.
  double first_crossing(const double* q0, const double* p0, double fs, double tau_limit, double t0);

  // After first_crossing returned +inf: true if the search stopped at tau_limit (a crossing may
  // follow later), false if none can ever follow.
  bool hit_limit = false;
  // Diagnostics of the last searches: direct (transcendental) evaluations and grid steps.
  long direct_evals = 0, grid_steps = 0;

 private:
  struct Mode {
    double w, omega, m2;  // weight, sqrt(omega^2), (omega + gamma) for the |q''| bound
    DampedMode mode;
    double p00, p01, p10, p11;  // [q, qd](tau + H) = P [q, qd](tau)
    int index;
  };
  struct Sums {
    double F, dF, mb, sb, m2;  // F, dF/dtau, bounds on |modal F|, |modal dF|, |F''|
  };
  void direct(const double* q0, const double* p0, double tau);  // q_, qd_ at tau
  void grid_step();                                              // q_, qd_ advanced by H
  Sums sums(double tau) const;
  double force(const double* q0, const double* p0, double tau);  // F only, direct
  // The gap fs - measure(F) at tau and its slope, from one direct evaluation (dF is the modes'
  // velocities summed: no extra exp or sincos).
  void gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg);
  double measure(double F) const { return sense_ == Sense::Abs ? (F < 0 ? -F : F) : F; }
  // First tau >= 0 at which the affine part a + b tau reaches the threshold (inf if never).
  double affine_reach(double a, double b, double fs) const;
  // A skip that provably passes no crossing: the time until the affine part at tau (aff) comes
  // within the modal bound mb of the threshold (0 if it already is).
  double envelope_skip(double aff, double mb, double fs) const;
  // Bracket refinement of first_crossing: the crossed end of [lo, hi] to round-off in t
  // (safeguarded Newton, Illinois regula falsi and bisection as fallbacks).
  double refine(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                double ghi);
  bool graze(const double* q0, const double* p0, double fs, double lo, double Flo, double hi, double Fhi,
             double m2, int depth, double& where);

  std::vector<Mode> modes_;
  std::vector<double> q_, qd_;
  double a_ = 0, b_ = 0, H_ = 0;
  Sense sense_ = Sense::Abs;
  bool open_ = false;
  int budget_ = 0;  // direct evaluations left for the current grazing search
};

}  // namespace sb::event_detail
