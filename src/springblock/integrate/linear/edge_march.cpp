#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/numerics/affine_crossing.hpp"
#include "springblock/infinity.hpp"
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
  sum_.modes.push_back({mode, index});
  sum_.w.push_back(w);
  sum_.omega.push_back(mode.omega);
  sum_.m2.push_back(mode.omega + 2.0 * mode.alpha);
  sum_.p00.push_back(P[0]), sum_.p01.push_back(P[1]), sum_.p10.push_back(P[2]), sum_.p11.push_back(P[3]);
}

void EdgeMarch::finish(double H) {
  H_ = H;
  for (auto* v : {&now_.q, &now_.p, &next_.q, &next_.p, &scratch_.q, &scratch_.p}) v->resize(sum_.modes.size());
  poly_.ok = true;
  for (const Mode& m : sum_.modes) poly_.ok = poly_.ok && m.mode.fastest_rate() * H_ <= kTaylorReach;
}

double EdgeMarch::affine_reach(double a, double b, double fs) const {
  return gap_.sense == Sense::Abs || b > 0 ? affine_crossing(a, b, fs) : kInf;
}

void EdgeMarch::finish() {
  double omega_max = 0;
  for (const Mode& m : sum_.modes) omega_max = std::max(omega_max, m.mode.omega);
  const double H = grid_step(omega_max);
  for (std::size_t k = 0; k < sum_.modes.size(); ++k) {
    const Transition P = sum_.modes[k].mode.transition(H);
    sum_.p00[k] = P[0], sum_.p01[k] = P[1], sum_.p10[k] = P[2], sum_.p11[k] = P[3];
  }
  finish(H);
}

void EdgeMarch::direct(const double* q0, const double* p0, double tau, double* q, double* qd) {
  DampedMode::eval_all(
      static_cast<int>(sum_.modes.size()), [&](int k) -> const DampedMode& { return sum_.modes[k].mode; }, tau,
      [&](int k, const DampedMode& m, double e) {
        m.eval_decayed(q0[sum_.modes[k].index], p0[sum_.modes[k].index], tau, e, q[k], qd[k]);
      });
}

namespace {

// The modes' weighted sum, sum_k w_k x_k, in four lanes (mode k in lane k % 4, the lanes added
// pairwise): one sum in mode order is a chain of dependent additions, and the march takes one
// at every grid step. F and F' are always summed this way (force_at, gap, expand), so the local
// polynomial at its base is F there to the last bit. x(k) gives mode k's value.
template <class X>
SB_INLINE double lane_sum(int n, const double* __restrict w, X x) {
  double d[4] = {};
  int k = 0;
  for (; k + 4 <= n; k += 4)
    for (int l = 0; l < 4; ++l) d[l] += w[k + l] * x(k + l);
  for (int l = 0; k < n; ++k, ++l) d[l] += w[k] * x(k);
  return (d[0] + d[1]) + (d[2] + d[3]);
}

SB_KERNEL_CLONES double weighted_sum(int n, const double* __restrict w, const double* __restrict x) {
  return lane_sum(n, w, [x](int k) __attribute__((always_inline)) { return x[k]; });
}

// A grid step of every mode and the weighted sum of the new q in one pass over the modes.
SB_KERNEL_CLONES double step_and_weigh(int n, const double* __restrict p00, const double* __restrict p01,
                                       const double* __restrict p10, const double* __restrict p11,
                                       const double* __restrict q, const double* __restrict p, double* __restrict qn,
                                       double* __restrict pn, const double* __restrict w) {
  return lane_sum(n, w, [&](int k) __attribute__((always_inline)) {
    step_mode(k, p00, p01, p10, p11, q, p, qn, pn);
    return qn[k];
  });
}

}  // namespace

double EdgeMarch::advance(const double* q0, const double* p0, double t1, int& since_sync) {
  if (++since_sync < kResync)
    return step_and_weigh(static_cast<int>(sum_.modes.size()), sum_.p00.data(), sum_.p01.data(), sum_.p10.data(),
                          sum_.p11.data(), now_.q.data(), now_.p.data(), next_.q.data(), next_.p.data(),
                          sum_.w.data());
  direct(q0, p0, t1, next_.q.data(), next_.p.data());
  since_sync = 0;
  return weighted(next_.q.data());
}

double EdgeMarch::weighted(const double* x) const {
  return weighted_sum(static_cast<int>(sum_.modes.size()), sum_.w.data(), x);
}

double EdgeMarch::force_at(double tau, const double* q) const { return affine_at(tau) + weighted(q); }

namespace {

// Per mode, the bound on its weighted velocity from its energy, E = |w| sqrt(qd^2 + omega^2 q^2),
// and E / omega, the bound on its weighted displacement. Element by element, so the square roots
// and divisions vectorise; the sums over modes are taken apart, in mode order.
SB_KERNEL_CLONES void mode_energies(int n, const double* __restrict w, const double* __restrict omega,
                                    const double* __restrict q, const double* __restrict qd, double* __restrict E,
                                    double* __restrict E_over_omega) {
  for (int k = 0; k < n; ++k) {
    const double e = std::fabs(w[k]) * std::sqrt(qd[k] * qd[k] + omega[k] * omega[k] * q[k] * q[k]);
    E[k] = e;
    E_over_omega[k] = e / omega[k];
  }
}

}  // namespace

EdgeMarch::Bounds EdgeMarch::bounds() {
  // Energy bounds |qd| <= E, |q| <= E / omega, |q''| = |gamma qd + omega^2 q| <= (gamma + omega) E.
  const int n = static_cast<int>(sum_.modes.size());
  double* E = scratch_.q.data();
  double* E_over_omega = scratch_.p.data();
  mode_energies(n, sum_.w.data(), sum_.omega.data(), now_.q.data(), now_.p.data(), E, E_over_omega);
  double sb = std::fabs(gap_.b), mb = 0.0, m2 = 0.0;
  for (int k = 0; k < n; ++k) {
    sb += E[k];
    mb += E_over_omega[k];
    m2 += sum_.m2[k] * E[k];
  }
  return {mb, sb, m2};
}

double EdgeMarch::force(const double* q0, const double* p0, double tau) {
  if (poly_.on) {
    double F, dF;
    local_eval(tau, F, dF);
    return F;
  }
  direct(q0, p0, tau, scratch_.q.data(), scratch_.p.data());
  return force_at(tau, scratch_.q.data());
}

double EdgeMarch::graze(const double* q0, const double* p0, double fs, double lo, double Flo, double hi,
                        double Fhi, double m2, int depth) {
  const double h = hi - lo;
  if (std::max(measure(Flo), measure(Fhi)) + 0.125 * m2 * h * h < fs) return kInf;
  if (depth >= kMaxDepth || budget_-- <= 0) return kInf;  // below resolution (see header)
  const double mid = 0.5 * (lo + hi), Fm = force(q0, p0, mid);
  if (measure(Fm) >= fs) return mid;
  const double left = graze(q0, p0, fs, lo, Flo, mid, Fm, m2, depth + 1);
  return left != kInf ? left : graze(q0, p0, fs, mid, Fm, hi, Fhi, m2, depth + 1);
}

double EdgeMarch::lower_bound(const double* q0, const double* p0, double fs) {
  direct(q0, p0, 0.0);
  const Bounds B = bounds();
  const double g = fs - measure(force_at(0.0, now_.q.data()));
  if (g <= 0 || gap_.open) return 0.0;
  return safe_skip(g, B, gap_.a, fs);
}

double EdgeMarch::safe_skip(double g, const Bounds& B, double aff, double fs) const {
  const double room = fs - B.mb;
  const bool inside = gap_.sense == Sense::Abs ? (B.mb < fs && std::fabs(aff) <= room) : aff <= room;
  return std::max(B.sb > 0 ? g / B.sb : kInf, inside ? affine_reach(aff, gap_.b, room) : 0.0);
}

double EdgeMarch::first_crossing(const double* q0, const double* p0, double fs, double tau_limit, double t0) {
  double tau = 0;
  direct(q0, p0, 0.0);
  double F = force_at(0.0, now_.q.data());
  Bounds B = bounds();
  int since_sync = 0, since_bounds = 0;
  poly_.on = false;
  bool open = gap_.open;  // tau = 0 sits on the threshold and is not an event (see header)
  hit_limit = false;
  for (;;) {
    if (since_bounds >= kBounds) B = bounds(), since_bounds = 0;
    const double g = fs - measure(F);
    if (!open) {
      if (g <= 0) return tau;  // at tau = 0 or a safe skip's end (at most on the threshold), else bracketed
      if (B.mb <= 1e-16 * std::max(std::fabs(fs), std::fabs(F))) {
        // The modes have died out below round-off: the signal is affine from here on.
        const double t = tau + affine_reach(F, gap_.b, fs);
        hit_limit = t > tau_limit && std::isfinite(t);
        return t <= tau_limit ? t : kInf;
      }
    }
    if (tau >= tau_limit) {
      hit_limit = true;
      return kInf;
    }
    const double skip = open ? 0.0 : safe_skip(g, B, affine_at(tau), fs);
    if (skip >= kJump * H_) {
      tau += skip;
      if (tau > tau_limit) {
        hit_limit = std::isfinite(tau);
        return kInf;
      }
      direct(q0, p0, tau);
      F = force_at(tau, now_.q.data());
      B = bounds();
      since_sync = since_bounds = 0;
      continue;
    }
    const double t1 = tau + H_;
    const double F1 = affine_at(t1) + advance(q0, p0, t1, since_sync);
    // At an open origin the gap is ~0 (on the threshold): bisection's end there is lo itself.
    if (measure(F1) >= fs) {
      expand(q0, p0, tau);
      return refine(q0, p0, fs, t0, tau, open ? fs : fs - measure(F), t1, fs - measure(F1));
    }
    if (!open) {
      // |F''| <= B.m2 on [tau, t1] from the bounds at tau (or earlier); retaken at tau when stale.
      const double peak = std::max(measure(F), measure(F1));
      const auto may_touch = [&] { return peak + 0.125 * B.m2 * H_ * H_ >= fs; };
      if (may_touch() && since_bounds > 0) B = bounds(), since_bounds = 0;
      if (may_touch()) {
        expand(q0, p0, tau);
        budget_ = kGrazeBudget;
        const double where = graze(q0, p0, fs, tau, F, t1, F1, B.m2, 0);
        if (where != kInf)
          return refine(q0, p0, fs, t0, tau, fs - measure(F), where, fs - measure(force(q0, p0, where)));
        poly_.on = false;
      }
    }
    now_.q.swap(next_.q);
    now_.p.swap(next_.p);
    ++since_bounds;
    tau = t1;
    F = F1;
    open = false;
  }
}

}  // namespace sb::event_detail
