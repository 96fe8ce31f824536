// The event method's quiet phase: every contact block stuck, the grooves propagated exactly
// (linear/quiet_phase.hpp) to the first threshold crossing, with the samples inside served from
// the closed form. Exact, except that an observer of contact forces only gets groove modes below
// the settle scales dropped (QuietPhase::set_sample_scales); once every groove has rung down the
// observer may take the rest of the phase's samples as one affine stretch (sample_affine).
#include <algorithm>

#include "springblock/integrate/methods/event_run.hpp"

namespace sb::event_detail {
namespace {

// A SampleStretch from three callables (the quiet phase's sums, its envelope, one sample's state).
template <class Sums, class Env, class At>
class StretchOf final : public SampleStretch {
 public:
  StretchOf(Sums sums, Env env, At at) : sums_(std::move(sums)), env_(std::move(env)), at_(std::move(at)) {}
  bool sums(long k0, long n, double& sum_abs, double& sum_signed) override { return sums_(k0, n, sum_abs, sum_signed); }
  bool envelope(long k0, long n, Envelope& e) override { return env_(k0, n, e); }
  const State& at(long k) override { return at_(k); }

 private:
  Sums sums_;
  Env env_;
  At at_;
};

}  // namespace

bool EventRun::quiet_phase() {
  // A quiet phase that follows sliding closes a slip event (the work profile's unit).
  if (s_.work.slip_starts > slip_starts_seen_) ++s_.work.slip_events;
  slip_starts_seen_ = s_.work.slip_starts;
  QuietPhase::Next next;
  {
    WorkTimer timer(s_.work, s_.work.quiet_s);
    quiet_->begin(c_, s_.t, s_.u.data(), s_.v.data());
    next = quiet_->next_threshold(c_, t_end_);
  }
  if (!serve_quiet_samples(next.t)) return false;
  {
    WorkTimer timer(s_.work, s_.work.quiet_s);
    quiet_->evaluate(next.t, s_.u.data(), s_.v.data());
    quiet_->release();
  }
  s_.t = next.t;
  {
    WorkTimer timer(s_.work, s_.work.switching_s);
    ++s_.work.switch_instants;
    if (next.block >= 0) sw_.flag(next.block);
    if (sw_.apply(c_, s_) > 0 && opt_.switch_log) opt_.switch_log->push_back(s_.t);
    if (!sw_.touched_list().empty()) obs_.switched(c_, s_, sw_.touched_list());
    // Every groove is exact at s.t. Grooves settled before the quiet phase stay settled: their
    // stuck ends have not moved, so their A + B t is still their path.
    reclassify();
  }
  stage1_valid_ = false;
  sample_if_due();
  return true;
}

// The samples before t_next from the quiet phase's closed form; false when the observer stopped
// the run at one of them (the state is then exact at that sample).
bool EventRun::serve_quiet_samples(double t_next) {
  if (!(clock_.next() < t_next)) return true;
  WorkTimer timer(s_.work, s_.work.sampling_s);
  // Contact blocks do not move in a quiet phase: copy them once, update the grooves per sample.
  std::copy(s_.u.begin(), s_.u.end(), sample_.u.begin());
  std::copy(s_.v.begin(), s_.v.end(), sample_.v.begin());
  std::copy(s_.dir.begin(), s_.dir.end(), sample_.dir.begin());
  const double dead_after = quiet_->all_dead_after();
  affine_ready_ = false;
  long long next_offer = clock_.index();  // a declined stretch is not offered again sample by sample
  while (clock_.next() < t_next) {
    if (clock_.next() >= dead_after) {
      bool stopped = false;
      if (sample_affine_stretch(t_next, stopped)) {
        if (stopped) return false;
        continue;
      }
    }
    bool stopped = false;
    if (ends_only_ && clock_.index() >= next_offer && offer_block(std::min(t_next, dead_after), stopped, next_offer)) {
      if (stopped) return false;
      continue;
    }
    sample_.t = clock_.next();
    serve_quiet_sample();
    clock_.advance();
    if (obs_.wants_stop()) {
      quiet_->evaluate(sample_.t, s_.u.data(), s_.v.data());
      s_.t = sample_.t;
      return false;
    }
  }
  return true;
}

// One sample at sample_.t from the quiet phase's modes. An observer of contact forces alone gets
// the friction sums straight from the modes (QuietPhase::friction_sums), and the rows only where
// it needs positions too.
void EventRun::serve_quiet_sample() {
  ++s_.work.samples;
  stamp_sample();
  quiet_->advance_sample(sample_.t, ends_only_);
  sample_.presummed.valid = ends_only_;
  if (ends_only_) {
    quiet_->friction_sums(sample_.t, sample_.presummed.abs, sample_.presummed.signed_sum);
    sample_.presummed.n_sliding = 0;  // nothing slides in a quiet phase
  }
  if (!ends_only_ || obs_.needs_positions_at(sample_.t))
    quiet_->write_sample(sample_.t, sample_.u.data(), sample_.v.data(), ends_only_);
  obs_.sample(c_, sample_);
  sample_.presummed.valid = false;
}

// The clock past `used` samples an observer took at once; if it then wants to stop, the state is
// brought to the last of them.
void EventRun::took_samples(long used, bool& stopped) {
  clock_.advance(used);
  if (obs_.wants_stop()) {
    const double t_last = clock_.time_of(clock_.index() - 1);
    quiet_->evaluate(t_last, s_.u.data(), s_.v.data());
    s_.t = t_last;
    stopped = true;
  }
}

// The samples from the clock's next to the next multiple of QuietPhase::kSampleBlock, before
// t_stop, offered as one stretch (Observer::sample_sums) with its closed-form sums (window_sums)
// for an observer of the mu_d window and bounds on each sample (envelope) for an observer of the
// loading peak; false when it was not taken (next_offer: the first sample at which a stretch is
// offered again). The stretch ends where the sample recurrence restarts (an aligned index) or
// where the phase's samples end, so the samples after it are served as they would be without
// it; a sample looked at inside it (at) is brought there by the recurrence through every sample
// before it, the doubles one-by-one service gives.
bool EventRun::offer_block(double t_stop, bool& stopped, long long& next_offer) {
  const long long k0 = clock_.index();
  const long block = QuietPhase::kSampleBlock;
  const long long k_end = std::min((k0 / block + 1) * block, clock_.first_at_or_after(t_stop));
  const long n = static_cast<long>(k_end - k0);
  if (n <= 0) return false;
  const double dt = clock_.dt();
  long long cursor = k0 - 1;  // the last sample advance_sample was brought to in this stretch
  bool summed = false;
  StretchOf stretch(
      [&](long k, long m, double& sum_abs, double& sum_signed) {
        return summed = quiet_->window_sums(k, dt, m, sum_abs, sum_signed);
      },
      [&](long k, long m, SampleStretch::Envelope& e) { return quiet_->envelope(k, dt, m, e); },
      [&](long k) -> const State& {
        // Several observers of one trajectory (FanOut) each look in order from the stretch's
        // start: a look behind the cursor replays the recurrence from there.
        if (cursor < k0) quiet_->save_cursor();
        else if (k < cursor) quiet_->restore_cursor(), cursor = k0 - 1;
        while (cursor < k) quiet_->advance_sample(clock_.time_of(++cursor), true);
        sample_.t = clock_.time_of(k);
        stamp_sample();
        sample_.presummed.valid = true;
        quiet_->friction_sums(sample_.t, sample_.presummed.abs, sample_.presummed.signed_sum);
        sample_.presummed.n_sliding = 0;
        if (obs_.needs_positions_at(sample_.t))
          quiet_->write_sample(sample_.t, sample_.u.data(), sample_.v.data(), true);
        return sample_;
      });
  sample_.t = clock_.next();
  stamp_sample();
  const long used = obs_.sample_sums(c_, sample_, static_cast<long>(k0), dt, n, stretch);
  sample_.presummed.valid = false;
  if (used < n && cursor >= k0) quiet_->restore_cursor();
  // Declined: its samples are served one by one. Offering its second half again, and so on,
  // cost more mode evaluations than it saved (callgrind, periodic:10,10 N = 360 1 s x4: 1669 M
  // against 1666 M).
  next_offer = k_end;
  if (used <= 0) return false;
  (summed ? s_.work.summed_samples : s_.work.peak_samples) += used;
  took_samples(used, stopped);
  return true;
}

bool EventRun::sample_affine_stretch(double t_next, bool& stopped) {
  if (!affine_ready_) {
    quiet_->affine_forces(c_, s_.u.data(), fa_.data(), fb_.data());
    affine_ready_ = true;
  }
  // Samples k dt < t_next, counted exactly as the clock will produce them.
  const long long k0 = clock_.index(), k_end = clock_.first_at_or_after(t_next);
  sample_.t = clock_.next();
  stamp_sample();
  const long used = obs_.sample_affine(c_, sample_, static_cast<long>(k0), clock_.dt(), static_cast<long>(k_end - k0),
                                       AffineForces{fa_.data(), fb_.data()});
  if (used <= 0) return false;
  s_.work.stretch_samples += used;
  took_samples(used, stopped);
  return true;
}

}  // namespace sb::event_detail
