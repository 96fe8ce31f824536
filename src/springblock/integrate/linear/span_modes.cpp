#include "springblock/integrate/linear/span_modes.hpp"

#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/run_stiffness.hpp"
#include "springblock/kernel_clones.hpp"

namespace sb::event_detail {
namespace {

// The longest step in radians of the fastest rate: a step turns every mode by at most 0.75 rad,
// so the screen's Hermite allowance M4 H^4 / 384 is ~1/1200 of a row's amplitude and the Taylor
// remainder over a step (degree kDegree + 1 of u, so kDegree of its velocity) below
// 0.75^14 / 14! ~ 2e-13 of it. Chosen by measurement (paper/choices.md, Integration): 0.5 rad with
// degree 10 and 1 rad with degree 14 cost a few per cent more per switch, 0.35 rad with degree 8
// some 5 % more.
constexpr double kStepRadians = 0.75;
// Grid steps between restarts of the recurrence from the closed form (its round-off grows by a
// few ulp of the modes per step).
constexpr int kSpanResync = 256;

// Every mode of a run advanced by its transition over H: element-wise, so it vectorises.
SB_KERNEL_CLONES void grid_transition(int n, const double* __restrict p00, const double* __restrict p01,
                                      const double* __restrict p10, const double* __restrict p11,
                                      const double* __restrict q, const double* __restrict p,
                                      double* __restrict qn, double* __restrict pn) {
  for (int k = 0; k < n; ++k) {
    qn[k] = p00[k] * q[k] + p01[k] * p[k];
    pn[k] = p10[k] * q[k] + p11[k] * p[k];
  }
}

// q = Q^T x and p = Q^T y for the n x n Q given by rows (Qr), accumulated row by row.
SB_KERNEL_CLONES void rows_times(int n, const double* __restrict Qr, const double* __restrict x,
                                 const double* __restrict y, double* __restrict q, double* __restrict p) {
  for (int k = 0; k < n; ++k) q[k] = 0.0, p[k] = 0.0;
  for (int r = 0; r < n; ++r) {
    const double* row = Qr + static_cast<std::size_t>(r) * n;
    const double xr = x[r], yr = y[r];
    for (int k = 0; k < n; ++k) {
      q[k] += row[k] * xr;
      p[k] += row[k] * yr;
    }
  }
}

}  // namespace

SpanModes::SpanModes(const Chain& c)
    : N_(c.N),
      K_s_(c.K_s),
      K_int_(c.K_int),
      m_(c.m),
      gamma_(c.gamma),
      bases_(c),
      paths_(c),
      span_of_(c.N, -1),
      A_(c.N),
      B_(c.N),
      du_(c.N),
      dv_(c.N),
      bound_{std::vector<double>(c.N), std::vector<double>(c.N), std::vector<double>(c.N), std::vector<double>(c.N)},
      q_(c.N),
      p_(c.N),
      qn_(c.N),
      pn_(c.N),
      q0_(c.N),
      p0_(c.N),
      sE_(c.N),
      rhs_(c.N),
      scratch_u_(c.N),
      scratch_v_(c.N) {
  // Every run's modes are below sqrt((K_s + 4 K_int) / m); an overdamped mode decays no faster
  // than gamma. H is set by the faster of the two, so the Taylor bound above holds for all.
  H_ = kStepRadians / std::max(c.omega_max(), c.gamma);
}

const SpanModes::Shape& SpanModes::shape(int n, bool left, bool right) {
  // A flat index by (n, left, right): every projection looks its shape up.
  const std::size_t slot = 4 * static_cast<std::size_t>(n) + 2 * left + right;
  if (slot >= index_.size()) index_.resize(slot + 1, nullptr);
  if (index_[slot] != nullptr) return *index_[slot];
  Shape sh;
  sh.basis = &bases_.get(n, left, right);
  sh.path = &paths_.get(n, left, right);
  sh.Qr.resize(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < n; ++k) sh.Qr[static_cast<std::size_t>(r) * n + k] = sh.basis->Q(r, k);
  for (const DampedMode& m : sh.basis->modes) {
    const Transition P = m.transition(H_);
    sh.p00.push_back(P[0]), sh.p01.push_back(P[1]), sh.p10.push_back(P[2]), sh.p11.push_back(P[3]);
    // |q'| <= sqrt(E), |q''| <= (gamma + omega) sqrt(E), |q'''| <= (gamma (gamma + omega) + omega^2)
    // sqrt(E), from q'' = -gamma q' - omega^2 q and omega |q| <= sqrt(E).
    // and q^(j+2) = -gamma q^(j+1) - omega^2 q^(j) for the higher ones.
    const double w = m.omega, c2 = gamma_ + w, c3 = gamma_ * c2 + m.omega2;
    const double c4 = gamma_ * c3 + m.omega2 * c2, c5 = gamma_ * c4 + m.omega2 * c3;
    sh.w2.push_back(m.omega2);
    sh.c[0].push_back(c2), sh.c[1].push_back(c3), sh.c[2].push_back(c4), sh.c[3].push_back(c5);
  }
  // K's tridiagonal factors (Thomas' elimination, off-diagonal -K_int): K^-1 f in O(n) per run.
  for (int k = 0; k < n; ++k) {
    const double d = run_stiffness_diagonal(K_s_, K_int_, n, k, left, right);
    const double pivot = k == 0 ? d : d + K_int_ * sh.upper[k - 1];
    sh.inv_pivot.push_back(1.0 / pivot);
    sh.upper.push_back(-K_int_ / pivot);
  }
  index_[slot] = &shapes_.emplace(std::make_tuple(n, left, right), std::move(sh)).first->second;
  return *index_[slot];
}

void SpanModes::project(const Chain& c, const State& s, const std::vector<BlockRange>& spans,
                        const std::uint8_t* switched) {
  // Slots are the blocks' own indices, so a kept run's modes and path stay where they are.
  kept_.swap(spans_);
  spans_.clear();
  const bool current = t_ == s.t;
  for (const BlockRange& r : spans) {
    const int k = span_of_[r.lo];
    bool keep = current && k >= 0 && kept_[k].lo == r.lo && kept_[k].hi == r.hi;
    for (int i = std::max(r.lo - 1, 0); keep && i < std::min(r.hi + 1, N_); ++i) keep = !switched[i];
    if (keep) spans_.push_back(kept_[k]), spans_.back().fresh = false;
    else spans_.push_back({r.lo, r.hi, nullptr, s.t, 0, false, true});
  }
  for (const Span& sp : kept_) std::fill(span_of_.begin() + sp.lo, span_of_.begin() + sp.hi, -1);
  for (std::size_t k = 0; k < spans_.size(); ++k)
    std::fill(span_of_.begin() + spans_[k].lo, span_of_.begin() + spans_[k].hi, static_cast<int>(k));
  ranges_ = spans;
  t_ = s.t;
  for (Span& sp : spans_)
    if (sp.shape == nullptr) project_one(c, s, sp);
}

// The particular solution (kinetic friction enters as a constant force, so A gains
// -K^-1 f_kin, taken through the modes), then the modal coordinates of the deviation from it.
void SpanModes::project_one(const Chain& c, const State& s, Span& sp) {
  const int lo = sp.lo, hi = sp.hi, n = hi - lo;
  const bool left = lo > 0, right = hi < N_;
  const Shape& sh = shape(n, left, right);
  const RunBasis& b = *sh.basis;
  sp.shape = &sh;
  sp.grooves = true;
  for (int i = lo; i < hi && sp.grooves; ++i) sp.grooves = !c.contact[i];
  const double uL = left ? s.u[lo - 1] : 0.0, uR = right ? s.u[hi] : 0.0;
  for (int k = 0; k < n; ++k) {
    A_[lo + k] = sh.path->a0[k] + uL * sh.path->gL[k] + uR * sh.path->gR[k];
    B_[lo + k] = sh.path->B[k];
  }
  bool friction = false;
  for (int row = 0; row < n; ++row) friction = friction || s.dir[lo + row] != 0;
  if (friction) {
    // A gains -K^-1 f_kin: the shape's tridiagonal factors, forward and back (O(n)).
    double* y = rhs_.data() + lo;
    for (int row = 0; row < n; ++row) {
      const double f = s.dir[lo + row] * c.f_kinetic[lo + row];
      y[row] = (row == 0 ? f : f + K_int_ * y[row - 1]) * sh.inv_pivot[row];
    }
    for (int row = n - 2; row >= 0; --row) y[row] -= sh.upper[row] * y[row + 1];
    for (int row = 0; row < n; ++row) A_[lo + row] -= y[row];
  }
  // The deviation from the path at s.t, then its modal coordinates Q^T x (rows of Q in turn, so
  // the loop over modes vectorises; each mode still sums its rows in order).
  double* x = rhs_.data() + lo;
  double* y = scratch_u_.data();
  for (int row = 0; row < n; ++row) {
    x[row] = s.u[lo + row] - A_[lo + row] - B_[lo + row] * s.t;
    y[row] = s.v[lo + row] - B_[lo + row];
  }
  rows_times(n, sh.Qr.data(), x, y, q_.data() + lo, p_.data() + lo);
  for (int k = 0; k < n; ++k) {
    const double qk = q_[lo + k], pk = p_[lo + k];
    q0_[lo + k] = qk;
    p0_[lo + k] = pk;
    sE_[lo + k] = std::sqrt(pk * pk + b.modes[k].omega2 * qk * qk);
  }
  // What the projection's round-off leaves of each row the screen reads (the end rows, a stuck
  // neighbour's force, and the sliding blocks', their stops) at s.t. A row sums modes of the whole
  // run, so a block at rest beside fast ones reads a velocity of ~1e-16 of theirs instead of 0:
  // enough, below the stop margin eps_v, to stop a block the instant it restarts. Such a row
  // keeps the difference as a constant, so it starts exactly where the state says; so do its
  // derivative bounds.
  for (int row = 0; row < n; ++row) {
    const int i = lo + row;
    du_[i] = 0.0, dv_[i] = 0.0;
    if (row != 0 && row != n - 1 && s.dir[i] == 0) continue;
    du_[i] = s.u[i] - (A_[i] + B_[i] * s.t + row_dot(i, q_.data()));
    dv_[i] = s.v[i] - (B_[i] + row_dot(i, p_.data()));
    set_bounds(sp, row);
  }
}

void SpanModes::direct(const Span& sp, const double* q, const double* p, double tau, double* qo,
                       double* po) const {
  const auto& modes = sp.shape->basis->modes;
  DampedMode::eval_all(
      sp.hi - sp.lo, [&](int k) -> const DampedMode& { return modes[k]; }, tau,
      [&](int k, const DampedMode& m, double e) {
        m.eval_decayed(q[sp.lo + k], p[sp.lo + k], tau, e, qo[sp.lo + k], po[sp.lo + k]);
      });
}

void SpanModes::advance(double h) {
  h_ = h;
  for (Span& sp : spans_) {
    const int n = sp.hi - sp.lo;
    if (h == H_ && sp.since + 1 < kSpanResync) {
      const Shape& sh = *sp.shape;
      grid_transition(n, sh.p00.data(), sh.p01.data(), sh.p10.data(), sh.p11.data(), q_.data() + sp.lo,
                      p_.data() + sp.lo, qn_.data() + sp.lo, pn_.data() + sp.lo);
      ++sp.since;
    } else {
      // A step off the grid, or the restart: from the projection itself when it is due.
      const bool resync = h == H_;
      if (resync) direct(sp, q0_.data(), p0_.data(), (t_ + h) - sp.t0, qn_.data(), pn_.data());
      else direct(sp, q_.data(), p_.data(), h, qn_.data(), pn_.data());
      sp.since = 0;
    }
  }
}

void SpanModes::take(double t) {
  std::swap(q_, qn_);
  std::swap(p_, pn_);
  t_ = t;
  for (Span& sp : spans_) sp.fresh = false;  // the rows have left the projected state
}

void SpanModes::take_at(double tau, double t) {
  for (const Span& sp : spans_) direct(sp, q_.data(), p_.data(), tau, qn_.data(), pn_.data());
  take(t);
}

}  // namespace sb::event_detail
