// The quiet phase's output: the grooves' exact u, v at a time (evaluate) and at the samples
// inside the phase (advance_sample, write_sample), from the segments' records begun by
// QuietPhase::begin.
#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/quiet_phase.hpp"

namespace sb::event_detail {

void QuietPhase::evaluate(double t, double* u, double* v) {
  const double tau = t - span_.t0;
  for (const GrooveRun& s : segs_) {
    const RunStore::Run& rec = store_.run(s.first);
    if (tau <= s.dead_tau) store_.write_at(rec, t, u, v);
    else store_.write_path(rec, t, u, v);
  }
}

void QuietPhase::advance_sample(double t, bool ends_only) {
  const double tau = t - span_.t0;
  // The recurrence needs the previous sample one spacing back; the clock's times k dt differ
  // from that by round-off only. Restart from the closed form at every block start (header).
  const double dt = store_.shapes().sample_dt();
  const bool step = cursor_.valid && dt > 0 && std::fabs((t - cursor_.t) - dt) <= 1e-9 * dt &&
                    std::llround(t / dt) % kSampleBlock != 0;
  for (int k : live_) {
    const GrooveRun& s = segs_[k];
    if (!(tau <= (ends_only ? s.sample_dead_tau : s.dead_tau))) continue;
    Coords& x = cursor_.x;
    if (step) s.shape->step_sample(x.q.data() + s.first, x.p.data() + s.first);
    else store_.coords(store_.run(s.first), t, x.q.data(), x.p.data());
  }
  cursor_.t = t;
  cursor_.valid = true;
}

void QuietPhase::write_sample(double t, double* u, double* v, bool ends_only) {
  const double tau = t - span_.t0;
  for (const GrooveRun& s : segs_) {
    // Dead modes, or none (the sample cursor holds none of its slots): its path.
    const RunStore::Run& rec = store_.run(s.first);
    if (tau <= (ends_only ? s.sample_dead_tau : s.dead_tau) && rec.modes)
      store_.write(rec, t, cursor_.x.q.data(), cursor_.x.p.data(), u, v, ends_only);
    else
      store_.write_path(rec, t, u, v, ends_only);
  }
}

}  // namespace sb::event_detail
