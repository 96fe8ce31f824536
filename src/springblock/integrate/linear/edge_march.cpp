#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/numerics/infinity.hpp"
#include "springblock/kernel_clones.hpp"

#include <algorithm>
#include <cmath>

namespace sb::event_detail {
namespace {

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
// Grid steps between fresh energy bounds (see the header): a grid step turns the fastest mode by
// half a radian, so stale bounds are at most 8 steps old, where damping has taken a few per cent
// of them, while the sqrt per mode they cost is paid an eighth as often.
constexpr int kBounds = 8;

}  // namespace

void EdgeMarch::add_mode(double w, const DampedMode& mode, int index) {
  const double P[4] = {0, 0, 0, 0};  // set by finish()
  add_mode(w, mode, index, P);
}

double EdgeMarch::grid_step(double omega_max) { return kGrid / omega_max; }

void EdgeMarch::add_mode(double w, const DampedMode& mode, int index, const double* P) {
  modes_.push_back({mode.omega + 2.0 * mode.alpha, mode.fastest_rate(), mode, index});
  w_.push_back(w);
  p00_.push_back(P[0]), p01_.push_back(P[1]), p10_.push_back(P[2]), p11_.push_back(P[3]);
}

void EdgeMarch::finish(double H) {
  H_ = H;
  for (auto* v : {&q_, &qd_, &qn_, &qdn_, &qs_, &qds_}) v->resize(modes_.size());
  taylor_ok_ = true;
  for (const Mode& m : modes_) taylor_ok_ = taylor_ok_ && m.rate * H_ <= kTaylorReach;
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
  for (const Mode& m : modes_) omega_max = std::max(omega_max, m.mode.omega);
  H_ = kGrid / omega_max;
  for (std::size_t k = 0; k < modes_.size(); ++k) {
    modes_[k].mode.eval(1.0, 0.0, H_, p00_[k], p10_[k]);
    modes_[k].mode.eval(0.0, 1.0, H_, p01_[k], p11_[k]);
  }
  for (auto* v : {&q_, &qd_, &qn_, &qdn_, &qs_, &qds_}) v->assign(modes_.size(), 0.0);
  taylor_ok_ = true;
  for (const Mode& m : modes_) taylor_ok_ = taylor_ok_ && m.rate * H_ <= kTaylorReach;
}

void EdgeMarch::direct(const double* q0, const double* p0, double tau, double* q, double* qd) {
  ++direct_evals;
  DampedMode::eval_all(
      static_cast<int>(modes_.size()), [&](int k) -> const DampedMode& { return modes_[k].mode; }, tau,
      [&](int k, const DampedMode& m, double e) {
        m.eval_decayed(q0[modes_[k].index], p0[modes_[k].index], tau, e, q[k], qd[k]);
      });
}

namespace {
// Every mode advanced by its transition over H: element-wise, so it vectorises (restrict).
SB_KERNEL_CLONES void transition(int n, const double* __restrict p00, const double* __restrict p01,
                                 const double* __restrict p10, const double* __restrict p11,
                                 const double* __restrict q, const double* __restrict qd, double* __restrict qn,
                                 double* __restrict qdn) {
  for (int k = 0; k < n; ++k) {
    qn[k] = p00[k] * q[k] + p01[k] * qd[k];
    qdn[k] = p10[k] * q[k] + p11[k] * qd[k];
  }
}
}  // namespace

void EdgeMarch::grid_step() {
  ++grid_steps;
  transition(static_cast<int>(modes_.size()), p00_.data(), p01_.data(), p10_.data(), p11_.data(), q_.data(),
             qd_.data(), qn_.data(), qdn_.data());
}

// The modes' weighted sum, sum_k w_k x_k, in four lanes (mode k in lane k % 4, the lanes added
// pairwise): one sum in mode order is a chain of dependent additions, and the march takes one
// at every grid step. F and F' are always summed this way (force_at, gap, expand), so the local
// polynomial at its base is F there to the last bit.
double EdgeMarch::weighted(const double* x) const {
  const double* w = w_.data();
  const int n = static_cast<int>(modes_.size());
  double d[4] = {};
  int k = 0;
  for (; k + 4 <= n; k += 4)
    for (int l = 0; l < 4; ++l) d[l] += w[k + l] * x[k + l];
  for (int l = 0; k < n; ++k, ++l) d[l] += w[k] * x[k];
  return (d[0] + d[1]) + (d[2] + d[3]);
}

double EdgeMarch::force_at(double tau, const double* q) const { return (a_ + b_ * tau) + weighted(q); }

EdgeMarch::Bounds EdgeMarch::bounds(const double* q, const double* qd) const {
  Bounds B{0.0, std::fabs(b_), 0.0};
  for (std::size_t k = 0; k < modes_.size(); ++k) {
    const Mode& m = modes_[k];
    // Energy bounds |qd| <= E, |q| <= E / omega, |q''| = |gamma qd + omega^2 q| <= (gamma + omega) E.
    const double E = std::fabs(w_[k]) * std::sqrt(qd[k] * qd[k] + m.mode.omega * m.mode.omega * q[k] * q[k]);
    B.sb += E;
    B.mb += E / m.mode.omega;
    B.m2 += m.m2 * E;
  }
  return B;
}

double EdgeMarch::force(const double* q0, const double* p0, double tau) {
  if (local_) {
    double F, dF;
    local_eval(tau, F, dF);
    return F;
  }
  direct(q0, p0, tau, qs_.data(), qds_.data());
  return force_at(tau, qs_.data());
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
  const Bounds B = bounds(q_.data(), qd_.data());
  const double g = fs - measure(force_at(0.0, q_.data()));
  if (g <= 0 || open_) return 0.0;
  return std::max(B.sb > 0 ? g / B.sb : kInf, envelope_skip(a_, B.mb, fs));
}

double EdgeMarch::envelope_skip(double aff, double mb, double fs) const {
  // No crossing while the affine part stays within the modal bound mb of the threshold.
  const double room = fs - mb;
  const bool inside = sense_ == Sense::Abs ? (mb < fs && std::fabs(aff) <= room) : aff <= room;
  return inside ? affine_reach(aff, b_, room) : 0.0;
}

double EdgeMarch::first_crossing(const double* q0, const double* p0, double fs, double tau_limit, double t0) {
  double tau = 0;
  direct(q0, p0, 0.0);
  double F = force_at(0.0, q_.data());
  Bounds B = bounds(q_.data(), qd_.data());
  int since_sync = 0, since_bounds = 0;
  local_ = false;
  bool open = open_;  // tau = 0 sits on the threshold and is not an event (see header)
  hit_limit = false;
  for (;;) {
    if (since_bounds >= kBounds) B = bounds(q_.data(), qd_.data()), since_bounds = 0;
    const double g = fs - measure(F);
    if (!open) {
      if (g <= 0) return tau;  // only at tau = 0: later crossings are bracketed below
      if (B.mb <= 1e-16 * std::max(std::fabs(fs), std::fabs(F))) {
        // The modes have died out below round-off: the signal is affine from here on.
        const double t = tau + affine_reach(F, b_, fs);
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
    const double skip = open ? 0.0 : std::max(B.sb > 0 ? g / B.sb : kInf, envelope_skip(a_ + b_ * tau, B.mb, fs));
    if (skip >= kJump * H_) {
      const double next = tau + skip;
      if (next > tau_limit) {
        hit_limit = std::isfinite(next);
        return kInf;
      }
      direct(q0, p0, next);
      F = force_at(next, q_.data());
      B = bounds(q_.data(), qd_.data());
      since_sync = since_bounds = 0;
      if (measure(F) >= fs) return next;  // a safe skip ends at most on the threshold
      tau = next;
      continue;
    }
    const double t1 = tau + H_;
    if (++since_sync >= kResync) {
      direct(q0, p0, t1, qn_.data(), qdn_.data());
      since_sync = 0;
    } else {
      grid_step();
    }
    const double F1 = force_at(t1, qn_.data());
    // At an open origin the gap is ~0 (on the threshold): bisection's end there is lo itself.
    if (measure(F1) >= fs) {
      expand(q0, p0, tau);
      return refine(q0, p0, fs, t0, tau, open ? fs : fs - measure(F), t1, fs - measure(F1));
    }
    if (!open) {
      // |F''| <= m2 on [tau, t1] from the bounds at tau (or earlier); retaken at tau when stale.
      const double peak = std::max(measure(F), measure(F1));
      double m2 = B.m2;
      if (peak + 0.125 * m2 * H_ * H_ >= fs && since_bounds > 0) {
        B = bounds(q_.data(), qd_.data()), since_bounds = 0;
        m2 = B.m2;
      }
      if (peak + 0.125 * m2 * H_ * H_ >= fs) {
        expand(q0, p0, tau);
        budget_ = kGrazeBudget;
        double where = 0;
        if (graze(q0, p0, fs, tau, F, t1, F1, m2, 0, where))
          return refine(q0, p0, fs, t0, tau, fs - measure(F), where, fs - measure(force(q0, p0, where)));
        local_ = false;
      }
    }
    q_.swap(qn_);
    qd_.swap(qdn_);
    ++since_bounds;
    tau = t1;
    F = F1;
    open = false;
  }
}

}  // namespace sb::event_detail
