// The quiet phase's output: the grooves' exact u, v at a time (evaluate) and at the samples
// inside the phase (sample), from the modal solution begun by QuietPhase::begin.
#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/quiet_phase.hpp"

namespace sb::event_detail {

void QuietPhase::to_physical(const GrooveRun& s, double t, bool live, const double* q, const double* qd,
                             double* u, double* v) const {
  const RunBasis& d = *s.basis;
  for (int r = 0; r < s.n; ++r) {
    u[s.first + r] = A_[s.offset + r] + B_[s.offset + r] * t;
    v[s.first + r] = B_[s.offset + r];
  }
  if (!live) return;
  // Column-major Q: accumulate mode by mode so the inner loop runs down a contiguous column.
  for (int k = 0; k < s.n; ++k) {
    const double* col = d.Q.data() + static_cast<std::ptrdiff_t>(k) * s.n;
    const double qk = q[k], qdk = qd[k];
    double* uu = u + s.first;
    double* vv = v + s.first;
    for (int r = 0; r < s.n; ++r) {
      uu[r] += col[r] * qk;
      vv[r] += col[r] * qdk;
    }
  }
}

void QuietPhase::row_to_physical(const GrooveRun& s, int r, double t, const double* q, const double* qd,
                                 double* u, double* v) const {
  const RunBasis& d = *s.basis;
  double du = 0, dv = 0;
  if (q != nullptr) {
    // Row r of Q (stored by column: stride n), or the contiguous copy of an end row; the same
    // products summed in the same order either way.
    const bool end_row = r == 0 || r == s.n - 1;
    const double* row = r == 0 ? d.first_row.data() : r == s.n - 1 ? d.last_row.data() : d.Q.data() + r;
    const int stride = end_row ? 1 : s.n;
    for (int k = 0; k < s.n; ++k) {
      du += row[k * stride] * q[k];
      dv += row[k * stride] * qd[k];
    }
  }
  u[s.first + r] = A_[s.offset + r] + B_[s.offset + r] * t + du;
  v[s.first + r] = B_[s.offset + r] + dv;
}

void QuietPhase::evaluate(double t, double* u, double* v) const {
  const double tau = t - t0_;
  double q[64], qd[64];  // modes evaluated in blocks of 64: no allocation
  for (const GrooveRun& s : segs_) {
    const RunBasis& d = *s.basis;
    const bool live = tau <= s.dead_tau;
    to_physical(s, t, false, nullptr, nullptr, u, v);
    if (!live) continue;
    for (int k0 = 0; k0 < s.n; k0 += 64) {
      const int k1 = std::min(s.n, k0 + 64);
      DampedMode::eval_all(k1 - k0, [&](int k) -> const DampedMode& { return d.modes[k0 + k]; }, tau,
                           [&](int k, const DampedMode& m, double e) {
                             m.eval_decayed(q0_[s.offset + k0 + k], p0_[s.offset + k0 + k], tau, e, q[k], qd[k]);
                           });
      for (int k = k0; k < k1; ++k) {
        const double* col = d.Q.data() + static_cast<std::ptrdiff_t>(k) * s.n;
        for (int r = 0; r < s.n; ++r) {
          u[s.first + r] += col[r] * q[k - k0];
          v[s.first + r] += col[r] * qd[k - k0];
        }
      }
    }
  }
}

void QuietPhase::set_sample_dt(double dt) {
  sample_dt_ = dt;
  bases_.set_sample_dt(dt);
}

void QuietPhase::sample(double t, double* u, double* v, bool ends_only) {
  advance_sample(t, ends_only);
  write_sample(t, u, v, ends_only);
}

void QuietPhase::advance_sample(double t, bool ends_only) {
  const double tau = t - t0_;
  // The recurrence needs the previous sample one spacing back; the clock's times k dt differ
  // from that by round-off only. Restart from the closed form at every block start (header).
  const bool step = sample_valid_ && sample_dt_ > 0 && std::fabs((t - ts_) - sample_dt_) <= 1e-9 * sample_dt_ &&
                    std::llround(t / sample_dt_) % kSampleBlock != 0;
  for (const GrooveRun& s : segs_) {
    // An observer that reads only contact forces (ends_only) takes the modes as gone once they
    // are below the settle scales; one that reads every row gets them to round-off.
    const bool live = tau <= (ends_only ? s.sample_dead_tau : s.dead_tau);
    if (!live) continue;
    double* q = qs_.data() + s.offset;
    double* qd = qds_.data() + s.offset;
    const RunBasis& d = *s.basis;
    if (step) {
      d.step_sample(q, qd);
    } else {
      DampedMode::eval_all(s.n, [&](int k) -> const DampedMode& { return d.modes[k]; }, tau,
                           [&](int k, const DampedMode& m, double e) {
                             m.eval_decayed(q0_[s.offset + k], p0_[s.offset + k], tau, e, q[k], qd[k]);
                           });
    }
  }
  ts_ = t;
  sample_valid_ = true;
}

void QuietPhase::save_cursor() {
  qs_kept_ = qs_, qds_kept_ = qds_;
  ts_kept_ = ts_, sample_valid_kept_ = sample_valid_;
}

void QuietPhase::restore_cursor() {
  qs_ = qs_kept_, qds_ = qds_kept_;  // copies: the kept cursor may be needed again
  ts_ = ts_kept_, sample_valid_ = sample_valid_kept_;
}

void QuietPhase::write_sample(double t, double* u, double* v, bool ends_only) const {
  const double tau = t - t0_;
  for (const GrooveRun& s : segs_) {
    const bool live = tau <= (ends_only ? s.sample_dead_tau : s.dead_tau);
    const double* q = qs_.data() + s.offset;
    const double* qd = qds_.data() + s.offset;
    if (ends_only) {
      // Interior rows are left as they are: the caller's observer does not read them.
      const double* lq = live ? q : nullptr;  // dead modes: the affine part alone
      if (s.left_stuck) row_to_physical(s, 0, t, lq, qd, u, v);
      if (s.right_stuck) row_to_physical(s, s.n - 1, t, lq, qd, u, v);
    } else {
      to_physical(s, t, live, q, qd, u, v);
    }
  }
}

void QuietPhase::friction_sums(double t, double& sum_abs, double& sum_signed) {
  const double tau = t - t0_;
  if (!interior_ready_) {
    // Every interior force has the slider's slope K_s v (next_threshold's affine crossings).
    interior_.reset(affine_a_.data(), static_cast<int>(affine_a_.size()), slider_slope_);
    interior_ready_ = true;
  }
  interior_.at(tau, sum_abs, sum_signed);
  // The end rows' modal displacement of each live segment (dead ones: none, as in write_sample).
  for (std::size_t k = 0; k < segs_.size(); ++k) {
    const GrooveRun& s = segs_[k];
    double first = 0, last = 0;
    if (tau <= s.sample_dead_tau) s.basis->end_rows(qs_.data() + s.offset, first, last);
    end_dots_[2 * k] = first, end_dots_[2 * k + 1] = last;
  }
  for (const Edge& e : edges_) {
    double f = e.fa + e.fb * tau;
    for (int n = 0; n < e.nseg; ++n) f += K_int_ * end_dots_[2 * e.seg[n] + (e.row[n] == 0 ? 0 : 1)];
    sum_abs += std::fabs(f);
    sum_signed += f;
  }
}

}  // namespace sb::event_detail
