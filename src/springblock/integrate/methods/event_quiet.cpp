#include <algorithm>

#include "springblock/integrate/methods/event_quiet.hpp"

namespace sb::event_detail {
namespace {

// A SampleStretch from the quiet phase's forces and a callable giving one sample's state.
template <class At>
class StretchOf final : public SampleStretch {
 public:
  StretchOf(RingingForces& forces, At at) : forces_(forces), at_(std::move(at)) {}
  RingingForces& forces() override { return forces_; }
  const State& at(long k) override { return at_(k); }

 private:
  RingingForces& forces_;
  At at_;
};

}  // namespace

QuietEvolve::QuietEvolve(EventCore& core)
    : core_(core), quiet_(core.c, core.store), ringing_(quiet_), sample_(core.s), fa_(core.c.N), fb_(core.c.N) {
  if (core.opt.ends_only) quiet_.set_sample_scales(core.active.settle_eps_u(), core.active.settle_eps_v());
}

bool QuietEvolve::pays() const {
  const double t_event = std::min(core_.active.next_real(), core_.t_end);
  return core_.clock.first_at_or_after(t_event) - core_.clock.index() >= kMinSamples;
}

bool QuietEvolve::phase() {
  State& s = core_.s;
  const QuietPhase::Next next = [&] {
    WorkTimer timer(s.work, s.work.quiet_s);
    // The phase begins from the whole state: the settled and modal runs from their records (the
    // stepped ones are the stepper's, written when the last sliding block stopped).
    core_.active.materialise(s.t, s.u.data(), s.v.data());
    quiet_.begin(core_.c, s.t, s.u.data(), s.v.data());
    return quiet_.next_threshold(core_.c, core_.t_end);
  }();
  if (!serve_samples(next.t)) return false;
  {
    WorkTimer timer(s.work, s.work.quiet_s);
    quiet_.evaluate(next.t, s.u.data(), s.v.data());
    quiet_.release();
  }
  s.t = next.t;
  // Every groove is exact at s.t. Grooves settled before the quiet phase stay settled: their
  // stuck ends have not moved, so their A + B t is still their path.
  if (next.block >= 0) core_.sw.flag(next.block);
  core_.switch_now(false);
  core_.sample_if_due();
  return true;
}

// The samples before t_next from the quiet phase's closed form; false when the observer stopped
// the run at one of them (the state is then exact at that sample).
bool QuietEvolve::serve_samples(double t_next) {
  if (!(core_.clock.next() < t_next)) return true;
  WorkTimer timer(core_.s.work, core_.s.work.sampling_s);
  // Contact blocks do not move in a quiet phase: copy them once, update the grooves per sample.
  std::copy(core_.s.u.begin(), core_.s.u.end(), sample_.u.begin());
  std::copy(core_.s.v.begin(), core_.s.v.end(), sample_.v.begin());
  std::copy(core_.s.dir.begin(), core_.s.dir.end(), sample_.dir.begin());
  const double dead_after = quiet_.all_dead_after();
  affine_ready_ = false;
  long long next_offer = core_.clock.index();  // a declined stretch is not offered again sample by sample
  while (core_.clock.next() < t_next) {
    // An affine stretch, else a block of sums, else one sample.
    long used = core_.clock.next() >= dead_after ? sample_affine_stretch(t_next) : 0;
    if (used <= 0 && core_.opt.ends_only && core_.clock.index() >= next_offer)
      used = offer_block(std::min(t_next, dead_after), next_offer);
    if (used <= 0) {
      serve_sample(core_.clock.next());
      used = 1;
    }
    if (took_samples(used)) return false;
  }
  return true;
}

// One sample at t from the quiet phase's modes. An observer of contact forces alone gets them as
// the modes describe them (sample_ringing), and the rows only where it needs positions too.
void QuietEvolve::serve_sample(double t) {
  ++core_.s.work.samples;
  stamp_sample(t);
  quiet_.advance_sample(t, core_.opt.ends_only);
  if (!core_.opt.ends_only || core_.obs.needs_positions_at(t))
    quiet_.write_sample(t, sample_.u.data(), sample_.v.data(), core_.opt.ends_only);
  if (core_.opt.ends_only) core_.obs.sample_ringing(core_.c, sample_, ringing_);
  else core_.obs.sample(core_.c, sample_);
}

// The clock past `used` samples (one served, or those an observer took at once); true when it
// then wants to stop, the state brought to the last of them.
bool QuietEvolve::took_samples(long used) {
  core_.clock.advance(used);
  if (!core_.obs.wants_stop()) return false;
  const double t_last = core_.clock.time_of(core_.clock.index() - 1);
  quiet_.evaluate(t_last, core_.s.u.data(), core_.s.v.data());
  core_.s.t = t_last;
  return true;
}

// The samples from the clock's next to the next multiple of QuietPhase::kSampleBlock, before
// t_stop, offered as one stretch (Observer::sample_sums) with the forces' closed-form sums over it
// and bounds from its start (RingingForces), for an observer of the mu_d window or of the
// loading peak; the samples taken, 0 if none (next_offer: the first sample at which a stretch is
// offered again). The stretch ends where the sample recurrence restarts (an aligned index) or
// where the phase's samples end, so the samples after it are served as they would be without
// it; a sample looked at inside it (at) is brought there by the recurrence through every sample
// before it, the doubles one-by-one service gives.
long QuietEvolve::offer_block(double t_stop, long long& next_offer) {
  const long long k0 = core_.clock.index();
  const long block = QuietPhase::kSampleBlock;
  const long long k_end = std::min((k0 / block + 1) * block, core_.clock.first_at_or_after(t_stop));
  const long n = static_cast<long>(k_end - k0);
  if (n <= 0) return 0;
  const double dt = core_.clock.dt();
  long long cursor = k0 - 1;  // the last sample advance_sample was brought to in this stretch
  ringing_.clear_summed();
  StretchOf stretch(ringing_, [&](long k) -> const State& {
        // Several observers of one trajectory (FanOut) each look in order from the stretch's
        // start: a look behind the cursor replays the recurrence from there.
        if (cursor < k0) quiet_.save_cursor();
        else if (k < cursor) quiet_.restore_cursor(), cursor = k0 - 1;
        while (cursor < k) quiet_.advance_sample(core_.clock.time_of(++cursor), true);
        stamp_sample(core_.clock.time_of(k));
        if (core_.obs.needs_positions_at(sample_.t))
          quiet_.write_sample(sample_.t, sample_.u.data(), sample_.v.data(), true);
        return sample_;
      });
  stamp_sample(core_.clock.next());
  const long used = core_.obs.sample_sums(core_.c, sample_, static_cast<long>(k0), dt, n, stretch);
  if (used < n && cursor >= k0) quiet_.restore_cursor();
  // Declined: its samples are served one by one. Offering its second half again, and so on,
  // cost more mode evaluations than it saved (callgrind, periodic:10,10 N = 360 1 s x4: 1669 M
  // against 1666 M).
  next_offer = k_end;
  if (used > 0) (ringing_.summed() ? core_.s.work.summed_samples : core_.s.work.peak_samples) += used;
  return used;
}

long QuietEvolve::sample_affine_stretch(double t_next) {
  if (!affine_ready_) {
    quiet_.affine_forces(core_.c, core_.s.u.data(), fa_.data(), fb_.data());
    affine_ready_ = true;
  }
  // Samples k dt < t_next, counted exactly as the clock will produce them.
  const long long k0 = core_.clock.index(), k_end = core_.clock.first_at_or_after(t_next);
  stamp_sample(core_.clock.next());
  const long used = core_.obs.sample_affine(core_.c, sample_, static_cast<long>(k0), core_.clock.dt(),
                                            static_cast<long>(k_end - k0), AffineForces{fa_.data(), fb_.data()});
  if (used > 0) core_.s.work.stretch_samples += used;
  return used;
}

// Everything but the kinematics that an observer reads from a sample at t: its time, the work
// counters and how many contact blocks have slid (the all-slipped end of loading). A stale count
// there would defer the end of loading to the next active phase that holds a sample, so mu_s would
// depend on the sample spacing (test FirstPeak.EndOfLoadingDoesNotDependOnSampleSpacing).
void QuietEvolve::stamp_sample(double t) {
  const State& s = core_.s;
  sample_.t = t;
  sample_.steps = s.steps, sample_.rhs_evals = s.rhs_evals, sample_.switches = s.switches;
  sample_.n_slipped_once = s.n_slipped_once;
}

}  // namespace sb::event_detail
