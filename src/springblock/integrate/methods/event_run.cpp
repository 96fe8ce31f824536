#include "springblock/integrate/methods/event_run.hpp"

namespace sb::event_detail {

EventRun::EventRun(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, const EventOptions& opt)
    : core_(c, s, t_end, sample_dt, obs, opt), stepped_(core_) {
  if (opt.fast_forward) quiet_ = std::make_unique<QuietEvolve>(core_);
  if (opt.exact_stepper) exact_ = std::make_unique<ExactEvolve>(core_);
}

bool EventRun::exact_now() {
  if (!exact_) return false;
  if (mode_at_ == core_.epochs.now()) return exact_mode_;
  bool fits = true;
  for (const BlockRange& r : core_.active.stepped()) fits = fits && r.size() <= core_.opt.exact_max_run;
  if (!fits && exact_mode_ && exact_->in_step()) exact_->leave();
  exact_mode_ = fits;
  mode_at_ = core_.epochs.now();
  return fits;
}

void EventRun::close_slip_event() {
  WorkProfile& w = core_.s.work;
  if (w.slip_starts > slip_starts_seen_) ++w.slip_events;
  slip_starts_seen_ = w.slip_starts;
}

template <bool Coupled, bool Damped>
void EventRun::run() {
  State& s = core_.s;
  core_.begin();
  while (s.t < core_.t_end && !core_.obs.wants_stop()) {
    const bool lull = quiet_ && core_.sw.n_sliding() == 0;
    if (lull) close_slip_event();
    const bool quiet = lull && quiet_->pays();
    if (!quiet && !core_.active.stepped().empty() && exact_now()) {
      exact_->step();
      continue;
    }
    if (exact_) exact_->pause();
    if (quiet) {
      if (!quiet_->phase()) return;  // the observer stopped the run inside it; its state is exact
    } else if (core_.active.stepped().empty()) {
      core_.jump();
    } else {
      stepped_.step<Coupled, Damped>();
    }
  }
  if (exact_ && exact_->valid() && exact_->in_step()) exact_->write(false);
  core_.finish();
}

template void EventRun::run<true, true>();
template void EventRun::run<true, false>();
template void EventRun::run<false, true>();
template void EventRun::run<false, false>();

}  // namespace sb::event_detail
