#include "springblock/integrate/linear/modal_runs.hpp"
#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/numerics/infinity.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sb::event_detail {
namespace {

// The sample recurrence restarts from the closed form this often, so its round-off never
// accumulates (the same rule as the quiet phase's samples).
constexpr int kSampleResync = 64;

}  // namespace

ModalRuns::ModalRuns(const Chain& c)
    : N_(c.N),
      K_int_(c.K_int),
      eps_v_(kStopMargin * c.v_slider),
      // One grid step for every run: the fastest mode any run can have is below
      // sqrt((K_s + 4 K_int) / m), so the per-mode transitions are computed once per basis.
      H_(EdgeMarch::grid_step(c.omega_max())),
      modes_(c),
      shapes_(c),
      run_of_(c.N, -1),
      A_(c.N),
      B_(c.N),
      amp_(c.N, std::numeric_limits<double>::infinity()),
      q0_(c.N),
      p0_(c.N),
      acc0_(c.N),
      qc_(c.N),
      qdc_(c.N),
      cq_(c.N),
      cp_(c.N),
      vq_(c.N),
      va_(c.N),
      rhs_(c.N) {}

void ModalRuns::set_sample_dt(double dt) {
  sample_dt_ = dt;
  modes_.set_sample_dt(dt);
}

const ModalRuns::Basis& ModalRuns::basis(int n, bool left, bool right) {
  const auto key = std::make_tuple(n, left, right);
  auto it = bases_.find(key);
  if (it != bases_.end()) return it->second;
  Basis b;
  b.run = &modes_.get(n, left, right);
  for (int k = 0; k < n; ++k) b.grid.push_back(b.run->modes[k].transition(H_));
  // The affine path's pieces of this shape (affine_paths.hpp): the same particular solution as
  // every other run's.
  b.path = &shapes_.get(n, left, right);
  return bases_.emplace(key, std::move(b)).first->second;
}

void ModalRuns::add(const Chain& c, const State& s, int lo, int hi, bool grooves) {
  ++projections;
  const int n = hi - lo;
  const bool left = lo > 0, right = hi < N_;
  const Basis& b = basis(n, left, right);
  const double uL = left ? s.u[lo - 1] : 0.0, uR = right ? s.u[hi] : 0.0;
  // Kinetic friction enters as a constant force: A gains -K^-1 f_kin (zero for grooves only).
  bool friction = false;
  for (int r = 0; r < n; ++r) {
    rhs_[r] = s.dir[lo + r] * c.f_kinetic[lo + r];
    friction = friction || rhs_[r] != 0.0;
  }
  Eigen::Map<const Eigen::MatrixXd> Q(b.run->Q.data(), n, n);
  Eigen::VectorXd fk_modal;
  if (friction) fk_modal = Q.transpose() * Eigen::Map<const Eigen::VectorXd>(rhs_.data(), n);
  for (int r = 0; r < n; ++r) {
    B_[lo + r] = b.path->B[r];
    A_[lo + r] = b.path->a0[r] + uL * b.path->gL[r] + uR * b.path->gR[r];
  }
  if (friction) {
    for (int k = 0; k < n; ++k) fk_modal[k] /= b.run->modes[k].omega2 * c.m;
    for (int r = 0; r < n; ++r) A_[lo + r] -= Q.row(r).dot(fk_modal);
  }
  // Modal coordinates of the deviation from u_p at s.t, and each mode's acceleration (the
  // initial slope of its velocity, which is a damped mode of the same kind).
  for (int k = 0; k < n; ++k) {
    double qk = 0, pk = 0;
    for (int r = 0; r < n; ++r) {
      const int i = lo + r;
      qk += Q(r, k) * (s.u[i] - A_[i] - B_[i] * s.t);
      pk += Q(r, k) * (s.v[i] - B_[i]);
    }
    q0_[lo + k] = qk;
    p0_[lo + k] = pk;
    acc0_[lo + k] = -c.gamma * pk - b.run->modes[k].omega2 * qk;
  }
  set_end_amplitudes(*b.run, lo, hi);
  Run run{lo, hi, &b, s.t, s.t, 0, false, grooves};
  if (grooves) run.settled_after = s.t + transient_envelope(*b.run, q0_.data() + lo, p0_.data() + lo).time_below(eps_u_, eps_v_settle_);
  for (int i = lo; i < hi; ++i) run_of_[i] = static_cast<int>(runs_.size());
  runs_.push_back(run);
}

// The runs' order in runs_ means nothing (each writes and searches its own blocks), so the last
// one fills the gap.
void ModalRuns::drop(int lo) {
  const int k = run_of_[lo];
  for (int i = runs_[k].lo; i < runs_[k].hi; ++i) run_of_[i] = -1;
  if (k + 1 < static_cast<int>(runs_.size())) {
    runs_[k] = runs_.back();
    for (int i = runs_[k].lo; i < runs_[k].hi; ++i) run_of_[i] = k;
  }
  runs_.pop_back();
}

void ModalRuns::clear() {
  for (const Run& r : runs_)
    for (int i = r.lo; i < r.hi; ++i) run_of_[i] = -1;
  runs_.clear();
}

// The end rows' bounds from the projection (envelope.hpp); interior rows are not bounded (+inf).
void ModalRuns::set_end_amplitudes(const RunBasis& b, int lo, int hi) {
  for (int i = lo; i < hi; ++i) amp_[i] = std::numeric_limits<double>::infinity();
  for (int row : {0, hi - lo - 1}) amp_[lo + row] = row_deviation_bound(b, row, q0_.data() + lo, p0_.data() + lo);
}

void ModalRuns::coords(const Run& r, double t, double* q, double* qd) const {
  const double tau = t - r.t0;
  const auto& modes = r.basis->run->modes;
  DampedMode::eval_all(
      r.hi - r.lo, [&](int k) -> const DampedMode& { return modes[k]; }, tau,
      [&](int k, const DampedMode& m, double e) { m.eval_decayed(q0_[r.lo + k], p0_[r.lo + k], tau, e, q[k], qd[k]); });
}

void ModalRuns::scratch_at(Run& r, double t) {
  if (r.scratch_t == t) return;
  coords(r, t, cq_.data() + r.lo, cp_.data() + r.lo);
  r.scratch_t = t;
}

double ModalRuns::u(int i, double t) const {
  const Run& r = runs_[run_of_[i]];
  const int n = r.hi - r.lo, row = i - r.lo;
  const double tau = t - r.t0;
  double x = A_[i] + B_[i] * t;
  const auto& modes = r.basis->run->modes;
  DampedMode::eval_all(n, [&](int k) -> const DampedMode& { return modes[k]; }, tau,
                       [&](int k, const DampedMode& m, double e) {
                         double q, qd;
                         m.eval_decayed(q0_[r.lo + k], p0_[r.lo + k], tau, e, q, qd);
                         x += r.basis->run->Q(row, k) * q;
                       });
  return x;
}

void ModalRuns::rows(const Run& r, double t, const double* q, const double* qd, int r0, int r1, int dr, double* u,
                     double* v) const {
  const int n = r.hi - r.lo;
  for (int row = r0; row < r1; row += dr) {
    double x = A_[r.lo + row] + B_[r.lo + row] * t, y = B_[r.lo + row];
    for (int k = 0; k < n; ++k) {
      x += r.basis->run->Q(row, k) * q[k];
      y += r.basis->run->Q(row, k) * qd[k];
    }
    u[r.lo + row] = x;
    v[r.lo + row] = y;
  }
}

void ModalRuns::materialise(double t, double* u, double* v, bool at_sample, bool ends_only) {
  for (Run& r : runs_) {
    const int n = r.hi - r.lo;
    double* q = qc_.data() + r.lo;
    double* qd = qdc_.data() + r.lo;
    const bool step = at_sample && r.cursor && sample_dt_ > 0 &&
                      std::fabs((t - r.tc) - sample_dt_) <= 1e-9 * sample_dt_ && r.since + 1 < kSampleResync;
    if (step) {
      for (int k = 0; k < n; ++k) {
        const auto& P = r.basis->run->sample[k];
        const double a = q[k], b = qd[k];
        q[k] = P[0] * a + P[1] * b;
        qd[k] = P[2] * a + P[3] * b;
      }
      ++r.since;
    } else if (at_sample) {
      coords(r, t, q, qd);
      r.since = 0;
    } else {
      scratch_at(r, t);  // off-sample evaluations must not move the cursor
      q = cq_.data() + r.lo, qd = cp_.data() + r.lo;
    }
    if (at_sample) r.tc = t, r.cursor = true;
    if (ends_only && r.grooves && n > 2) rows(r, t, q, qd, 0, n, n - 1, u, v);
    else rows(r, t, q, qd, 0, n, 1, u, v);
  }
}

void ModalRuns::materialise_run(int i, double t, double* u, double* v) {
  Run& r = runs_[run_of_[i]];
  scratch_at(r, t);
  rows(r, t, cq_.data() + r.lo, cp_.data() + r.lo, 0, r.hi - r.lo, 1, u, v);
}

}  // namespace sb::event_detail
