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
//  * refinement of a bracket to round-off in t: Newton on the gap, whose slope every evaluation
//    gives, kept inside the bracket by regula falsi and bisection. A bracket, and a grazing
//    search, never spans more than one grid step from the point whose modes the march holds, so
//    F there is a Taylor polynomial about that point: each mode's derivatives follow from the
//    recurrence q^(j+2) = -gamma q^(j+1) - omega^2 q^(j), and with every mode's fastest rate r
//    satisfying r H <= kTaylorReach (0.52; the grid step gives 0.5) the remainder of order
//    kTaylor = 14 is below (r H)^(kTaylor+1) / (kTaylor+1)! = 4e-17 of the modal amplitude,
//    under round-off. An evaluation then costs kTaylor flops instead of an exp and a sincos per
//    mode. The polynomial's round-off differs from the direct evaluation's, so its root is
//    confirmed by one direct evaluation: the returned point is crossed by the closed form itself
//    (and the refinement goes on by direct evaluations in the rare case it is not). Modes faster
//    than that (strong overdamping) keep the direct evaluations throughout.
// Every mode's energy qd^2 + omega^2 q^2 never grows (damping only removes it), so the bounds
// taken at one point hold for all later times. They cost a sqrt per mode, so the march takes
// them afresh only every kBounds grid steps (and at every direct evaluation) and otherwise uses
// the last ones, which are larger but valid; the grazing test, where a looser bound would cost
// direct evaluations, retakes them at the interval's start whenever the stale ones trigger it,
// so its decisions are those of fresh bounds.
// With an open origin the event function may start on the threshold (a block that has just
// started to slide, v = 0): tau = 0 is then not an event, the first grid interval is searched
// for a sign change only, and the provable skips start from the first grid point.
#include <vector>

#include "springblock/integrate/linear/coords.hpp"
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
  void reset() {
    sum_.modes.clear();
    for (auto* v : {&sum_.w, &sum_.p00, &sum_.p01, &sum_.p10, &sum_.p11, &sum_.omega, &sum_.m2}) v->clear();
  }
  // The grid step used by finish() for modes no faster than omega_max.
  static double grid_step(double omega_max);

  void set_sense(Sense sense, bool origin_open) { gap_.sense = sense, gap_.open = origin_open; }

  // a, b: affine part of F at the start of the quiet phase; fs: the threshold.
  void set_affine(double a, double b) { gap_.a = a, gap_.b = b; }

  // A cheap lower bound on the first crossing (for ordering the searches).
  double lower_bound(const double* q0, const double* p0, double fs);
  // First tau in [0, tau_limit] with |F| >= fs (Upper: F >= fs), or +inf. t0 only sets the
  // round-off scale.
  double first_crossing(const double* q0, const double* p0, double fs, double tau_limit, double t0);

  // After first_crossing returned +inf: true if the search stopped at tau_limit (a crossing may
  // follow later), false if none can ever follow.
  bool hit_limit = false;

 private:
  // Order of the local polynomial and the largest r H it is used at (see the header). Order 20
  // up to r H = 1 (2e-20) would add six terms to every evaluation for nothing a double holds
  // (paper/choices.md).
  static constexpr int kTaylor = 14;
  static constexpr double kTaylorReach = 0.52;
  struct Mode {
    DampedMode mode;  // its omega is the bounds' and the grid's
    int index;
  };
  struct Bounds {
    double mb, sb, m2;  // bounds on |modal F|, |dF| (affine slope included), |F''|
  };
  // The modes at tau into q, qd (one exp and sincos per mode).
  void direct(const double* q0, const double* p0, double tau, double* q, double* qd);
  void direct(const double* q0, const double* p0, double tau) { direct(q0, p0, tau, now_.q.data(), now_.p.data()); }
  // next_ = the modes at t1, one grid step on from now_: by their transitions, or every kResync-th
  // step by the closed form, so the recurrence's round-off never accumulates; weighted(next_.q).
  double advance(const double* q0, const double* p0, double t1, int& since_sync);
  double force_at(double tau, const double* q) const;            // a + b tau + sum w q
  double affine_at(double tau) const { return gap_.a + gap_.b * tau; }
  double weighted(const double* x) const;                        // sum w x (the order of every such sum)
  // From the modes' energies at the march's point (now_); the per-mode terms go to scratch_.
  Bounds bounds();
  double force(const double* q0, const double* p0, double tau);  // F only, direct (scratch state)
  // The gap fs - measure(F) at tau and its slope, from one direct evaluation (dF is the modes'
  // velocities summed: no extra exp or sincos).
  void gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg);
  double measure(double F) const { return gap_.sense == Sense::Abs ? (F < 0 ? -F : F) : F; }
  // First tau >= 0 at which the affine part a + b tau reaches the threshold (inf if never).
  double affine_reach(double a, double b, double fs) const;
  // A skip from a point with gap g, bounds B and affine part aff that provably passes no crossing:
  // none before |F| has changed by g at a rate of at most sb, nor before the affine part alone
  // comes within the modal bound mb of the threshold (0 if it already is).
  double safe_skip(double g, const Bounds& B, double aff, double fs) const;
  // Bracket refinement of first_crossing: the crossed end of [lo, hi] to round-off in t
  // (safeguarded Newton, Illinois regula falsi and bisection as fallbacks).
  double refine(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                double ghi);
  // A point of [lo, hi] with measure(F) >= fs, subdividing while |F''| <= m2 allows a touch (see
  // the header); +inf if there is none to resolution.
  double graze(const double* q0, const double* p0, double fs, double lo, double Flo, double hi, double Fhi,
               double m2, int depth);
  // The Taylor polynomial of F about tau_base (poly_.on), if the modes allow it (poly_.ok),
  // from one direct evaluation there: the march's own modes carry the grid recurrence's
  // round-off, up to ~1e-13 of them, far above what a root to round-off needs.
  // F and dF at tau in [tau_base, tau_base + H] from it.
  void expand(const double* q0, const double* p0, double tau_base);
  void local_eval(double tau, double& F, double& dF);

  // The modes and, apart, the hot data of a grid step and of the bounds, one array each
  // (structure of arrays): the modes' weights in the force (their only copy), each mode's
  // transition over H, [q, qd](tau + H) = [[p00, p01], [p10, p11]] [q, qd](tau), and its omega
  // and omega + gamma (the |q''| bound's factor), so the transition and the bounds' square roots
  // and divisions vectorise and each reads only what it uses.
  struct Sum {
    std::vector<Mode> modes;
    std::vector<double> w, p00, p01, p10, p11, omega, m2;
  };
  // The event function: F's affine part a + b tau, the sense of the threshold, an open origin.
  struct Gap {
    double a = 0, b = 0;
    Sense sense = Sense::Abs;
    bool open = false;
  };
  // The Taylor polynomial of F about base (on: gap() and force() read it), when every mode's
  // fastest rate r has r H <= kTaylorReach (ok, set by finish): F = sum coef_j (tau - base)^j,
  // F' = sum dcoef_j ...
  struct Local {
    bool ok = false, on = false;
    double base = 0;
    double coef[kTaylor + 1] = {};
    double dcoef[kTaylor] = {};
  };
  Sum sum_;
  // The modes at the march's point and at the next grid point; scratch_, a work array read only
  // right after it is written: the direct evaluations off the grid, or the bounds' per-mode terms.
  Coords now_, next_, scratch_;
  Gap gap_;
  Local poly_;
  double H_ = 0;
  int budget_ = 0;  // direct evaluations left for the current grazing search
};

}  // namespace sb::event_detail
