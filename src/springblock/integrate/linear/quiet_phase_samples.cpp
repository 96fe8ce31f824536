// The quiet phase's output: the grooves' exact u, v at a time (evaluate) and at the samples
// inside the phase (sample), from the segments' records begun by QuietPhase::begin.
#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/quiet_phase.hpp"

namespace sb::event_detail {

void QuietPhase::write_segment(const GrooveRun& s, double t, bool live, const double* q, const double* qd,
                               double* u, double* v, bool ends_only) {
  const RunStore::Run& rec = store_.run(s.first);
  if (!ends_only) {
    if (live) store_.write(rec, t, q, qd, u, v);
    else store_.write_path(rec, t, u, v);
    return;
  }
  // Interior rows are left as they are: the caller's observer does not read them.
  for (int i : {s.left_stuck ? s.first : -1, s.right_stuck ? s.first + s.n - 1 : -1}) {
    if (i < 0) continue;
    u[i] = live ? store_.row_u(i, t, q) : store_.path_u(i, t);
    v[i] = live ? store_.row_v(i, qd) : store_.B(i);
  }
}

void QuietPhase::evaluate(double t, double* u, double* v) {
  const double tau = t - t0_;
  for (const GrooveRun& s : segs_) {
    const bool live = tau <= s.dead_tau;
    if (live) store_.coords(store_.run(s.first), t, wq1_.data(), wp1_.data());
    write_segment(s, t, live, wq1_.data(), wp1_.data(), u, v, false);
  }
}

void QuietPhase::set_sample_dt(double dt) { store_.shapes().set_sample_dt(dt); }

void QuietPhase::sample(double t, double* u, double* v, bool ends_only) {
  advance_sample(t, ends_only);
  write_sample(t, u, v, ends_only);
}

void QuietPhase::advance_sample(double t, bool ends_only) {
  const double tau = t - t0_;
  // The recurrence needs the previous sample one spacing back; the clock's times k dt differ
  // from that by round-off only. Restart from the closed form at every block start (header).
  const double dt = store_.shapes().sample_dt();
  const bool step = sample_valid_ && dt > 0 && std::fabs((t - ts_) - dt) <= 1e-9 * dt &&
                    std::llround(t / dt) % kSampleBlock != 0;
  for (const GrooveRun& s : segs_) {
    // An observer that reads only contact forces (ends_only) takes the modes as gone once they
    // are below the settle scales; one that reads every row gets them to round-off.
    const bool live = tau <= (ends_only ? s.sample_dead_tau : s.dead_tau);
    if (!live) continue;
    if (step) s.shape->step_sample(qs_.data() + s.first, qds_.data() + s.first);
    else store_.coords(store_.run(s.first), t, qs_.data(), qds_.data());
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

void QuietPhase::write_sample(double t, double* u, double* v, bool ends_only) {
  const double tau = t - t0_;
  for (const GrooveRun& s : segs_) {
    const bool live = tau <= (ends_only ? s.sample_dead_tau : s.dead_tau);
    write_segment(s, t, live, qs_.data(), qds_.data(), u, v, ends_only);
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
    if (tau <= s.sample_dead_tau) s.shape->end_rows(qs_.data() + s.first, first, last);
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
