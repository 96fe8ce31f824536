#include "springblock/integrate/linear/edge_march.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sb::event_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Grid step in units of 1 / omega_max: the fastest mode turns by half a radian per step, so
// the grazing bound M2 H^2 / 8 is ~1/32 of the modal amplitude and rarely needs subdividing.
constexpr double kGrid = 0.5;
// A provably safe skip replaces grid steps only when it saves this many of them: a direct
// evaluation (exp and sincos per mode) costs roughly as much as 16 grid steps.
constexpr double kJump = 16.0;
// The grid recurrence is restarted from the closed form this often, so its round-off
// (a few ulp per step of the modal part) never accumulates beyond ~1e-13 of it.
constexpr int kResync = 256;
constexpr int kMaxDepth = 30;   // grazing subdivision: 2^-30 of a grid step (~1e-15 s)
constexpr int kGrazeBudget = 96;  // direct evaluations per grazing search

}  // namespace

void EdgeMarch::add_mode(double w, const DampedMode& mode, int index) {
  const double omega = std::sqrt(mode.omega2);
  modes_.push_back({w, omega, omega + 2.0 * mode.alpha, mode, 0, 0, 0, 0, index});
}

double EdgeMarch::grid_step(double omega_max) { return kGrid / omega_max; }

void EdgeMarch::add_mode(double w, const DampedMode& mode, int index, const double* P) {
  const double omega = std::sqrt(mode.omega2);
  modes_.push_back({w, omega, omega + 2.0 * mode.alpha, mode, P[0], P[1], P[2], P[3], index});
}

void EdgeMarch::finish(double H) {
  H_ = H;
  q_.resize(modes_.size());
  qd_.resize(modes_.size());
}

double EdgeMarch::affine_reach(double a, double b, double fs) const {
  if (sense_ == Sense::Abs) {
    if (b == 0.0) return kInf;
    return std::max(((b > 0 ? fs : -fs) - a) / b, 0.0);
  }
  return b > 0 ? std::max((fs - a) / b, 0.0) : kInf;
}

void EdgeMarch::finish() {
  double omega_max = 0;
  for (const Mode& m : modes_) omega_max = std::max(omega_max, m.omega);
  H_ = kGrid / omega_max;
  for (Mode& m : modes_) {
    m.mode.eval(1.0, 0.0, H_, m.p00, m.p10);
    m.mode.eval(0.0, 1.0, H_, m.p01, m.p11);
  }
  q_.assign(modes_.size(), 0.0);
  qd_.assign(modes_.size(), 0.0);
}

void EdgeMarch::direct(const double* q0, const double* p0, double tau) {
  ++direct_evals;
  DampedMode::eval_all(
      static_cast<int>(modes_.size()), [&](int k) -> const DampedMode& { return modes_[k].mode; }, tau,
      [&](int k, const DampedMode& m, double e) {
        m.eval_decayed(q0[modes_[k].index], p0[modes_[k].index], tau, e, q_[k], qd_[k]);
      });
}

void EdgeMarch::grid_step() {
  ++grid_steps;
  for (std::size_t k = 0; k < modes_.size(); ++k) {
    const Mode& m = modes_[k];
    const double q = q_[k], qd = qd_[k];
    q_[k] = m.p00 * q + m.p01 * qd;
    qd_[k] = m.p10 * q + m.p11 * qd;
  }
}

EdgeMarch::Sums EdgeMarch::sums(double tau) const {
  Sums s{a_ + b_ * tau, b_, 0.0, std::fabs(b_), 0.0};
  for (std::size_t k = 0; k < modes_.size(); ++k) {
    const Mode& m = modes_[k];
    s.F += m.w * q_[k];
    s.dF += m.w * qd_[k];
    // Energy bounds |qd| <= E, |q| <= E / omega, |q''| = |gamma qd + omega^2 q| <= (gamma + omega) E.
    const double E = std::fabs(m.w) * std::sqrt(qd_[k] * qd_[k] + m.omega * m.omega * q_[k] * q_[k]);
    s.sb += E;
    s.mb += E / m.omega;
    s.m2 += m.m2 * E;
  }
  return s;
}

double EdgeMarch::force(const double* q0, const double* p0, double tau) {
  direct(q0, p0, tau);
  double F = a_ + b_ * tau;
  for (std::size_t k = 0; k < modes_.size(); ++k) F += modes_[k].w * q_[k];
  return F;
}

bool EdgeMarch::graze(const double* q0, const double* p0, double fs, double lo, double Flo, double hi,
                      double Fhi, double m2, int depth, double& where) {
  const double h = hi - lo;
  if (std::max(measure(Flo), measure(Fhi)) + 0.125 * m2 * h * h < fs) return false;
  if (depth >= kMaxDepth || budget_-- <= 0) return false;  // below resolution (see header)
  const double mid = 0.5 * (lo + hi), Fm = force(q0, p0, mid);
  if (measure(Fm) >= fs) {
    where = mid;
    return true;
  }
  return graze(q0, p0, fs, lo, Flo, mid, Fm, m2, depth + 1, where) ||
         graze(q0, p0, fs, mid, Fm, hi, Fhi, m2, depth + 1, where);
}

double EdgeMarch::lower_bound(const double* q0, const double* p0, double fs) {
  direct(q0, p0, 0.0);
  const Sums s = sums(0.0);
  const double g = fs - measure(s.F);
  if (g <= 0 || open_) return 0.0;
  return std::max(s.sb > 0 ? g / s.sb : kInf, envelope_skip(a_, s.mb, fs));
}

double EdgeMarch::envelope_skip(double aff, double mb, double fs) const {
  // No crossing while the affine part stays within the modal bound mb of the threshold.
  const double room = fs - mb;
  const bool inside = sense_ == Sense::Abs ? (mb < fs && std::fabs(aff) <= room) : aff <= room;
  return inside ? affine_reach(aff, b_, room) : 0.0;
}

void EdgeMarch::gap(const double* q0, const double* p0, double fs, double tau, double& g, double& dg) {
  direct(q0, p0, tau);
  double F = a_ + b_ * tau, dF = b_;
  for (std::size_t k = 0; k < modes_.size(); ++k) F += modes_[k].w * q_[k], dF += modes_[k].w * qd_[k];
  g = fs - measure(F);
  dg = (sense_ == Sense::Abs && F < 0) ? dF : -dF;
}

// Shrink a bracket with gap g = fs - measure(F) > 0 at lo and <= 0 at hi to round-off in t;
// returns the crossed end. Every evaluation gives the gap's slope for free (gap()), so the next
// point is Newton's, aimed a quarter of the tolerance past its root estimate: once the estimate
// is that good the point lands on the far side and closes the bracket. A Newton point outside
// the bracket, or a Newton step that did not halve it, hands one iteration to regula falsi with
// the Illinois modification (bisection when the secant point is not well inside), which keeps
// the bracket at every iteration. A smooth gap takes ~5 direct evaluations instead of the ~10 of
// regula falsi alone.
double EdgeMarch::refine(const double* q0, const double* p0, double fs, double t0, double lo, double glo, double hi,
                         double ghi) {
  int kept = 0;  // +1: lo kept last time, -1: hi kept last time
  bool was_newton = false;
  double x = 0, gx = 0, dgx = 0, w_before = kInf;  // x, gx, dgx: the last evaluation (it > 0)
  for (int it = 0; it < 200; ++it) {
    const double w = hi - lo, tol = 4e-16 * std::fabs(t0 + hi);
    if (!(w > tol)) break;
    double mid = kInf;
    if (it > 0 && dgx != 0 && !(was_newton && w > 0.5 * w_before)) {
      const double step = -gx / dgx;
      mid = x + step + std::copysign(0.25 * tol, step);
      if (!(mid > lo && mid < hi)) mid = kInf;
    }
    was_newton = mid != kInf;
    if (!was_newton) {
      mid = hi - ghi * (hi - lo) / (ghi - glo);
      if (!(mid > lo + 1e-3 * w && mid < hi - 1e-3 * w)) mid = 0.5 * (lo + hi);
    }
    w_before = w;
    gap(q0, p0, fs, mid, gx, dgx);
    x = mid;
    if (gx > 0) {
      lo = mid, glo = gx;
      if (kept == -1) ghi *= 0.5;
      kept = -1;
    } else {
      hi = mid, ghi = gx;
      if (kept == 1) glo *= 0.5;
      kept = 1;
    }
  }
  return hi;
}

double EdgeMarch::first_crossing(const double* q0, const double* p0, double fs, double tau_limit, double t0) {
  double tau = 0;
  direct(q0, p0, 0.0);
  Sums S = sums(0.0);
  int since_sync = 0;
  bool open = open_;  // tau = 0 sits on the threshold and is not an event (see header)
  hit_limit = false;
  for (;;) {
    const double g = fs - measure(S.F);
    if (!open) {
      if (g <= 0) return tau;  // only at tau = 0: later crossings are bracketed below
      if (S.mb <= 1e-16 * std::max(std::fabs(fs), std::fabs(S.F))) {
        // The modes have died out below round-off: the signal is affine from here on.
        const double t = tau + affine_reach(S.F, b_, fs);
        hit_limit = t > tau_limit && std::isfinite(t);
        return t <= tau_limit ? t : kInf;
      }
    }
    if (tau >= tau_limit) {
      hit_limit = true;
      return kInf;
    }
    // No crossing before |F| has changed by g at a rate of at most sb, nor before the affine
    // part alone comes within the modal bound mb of the threshold.
    const double skip = open ? 0.0 : std::max(S.sb > 0 ? g / S.sb : kInf, envelope_skip(a_ + b_ * tau, S.mb, fs));
    if (skip >= kJump * H_) {
      const double next = tau + skip;
      if (next > tau_limit) {
        hit_limit = std::isfinite(next);
        return kInf;
      }
      direct(q0, p0, next);
      S = sums(next);
      since_sync = 0;
      if (measure(S.F) >= fs) return next;  // a safe skip ends at most on the threshold
      tau = next;
      continue;
    }
    const double t1 = tau + H_;
    if (++since_sync >= kResync) {
      direct(q0, p0, t1);
      since_sync = 0;
    } else {
      grid_step();
    }
    const Sums S1 = sums(t1);
    // At an open origin the gap is ~0 (on the threshold): bisection's end there is lo itself.
    if (measure(S1.F) >= fs) return refine(q0, p0, fs, t0, tau, open ? fs : fs - measure(S.F), t1, fs - measure(S1.F));
    if (!open && std::max(measure(S.F), measure(S1.F)) + 0.125 * S.m2 * H_ * H_ >= fs) {
      budget_ = kGrazeBudget;
      double where = 0;
      const bool hit = graze(q0, p0, fs, tau, S.F, t1, S1.F, S.m2, 0, where);
      if (hit) return refine(q0, p0, fs, t0, tau, fs - measure(S.F), where, fs - measure(force(q0, p0, where)));
      direct(q0, p0, t1);  // the grazing search moved the mode state: restore it at t1
      since_sync = 0;
    }
    tau = t1;
    S = S1;
    open = false;
  }
}

}  // namespace sb::event_detail
