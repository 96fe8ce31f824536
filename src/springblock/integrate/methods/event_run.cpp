#include "springblock/integrate/methods/event_run.hpp"

#include <algorithm>

namespace sb::event_detail {

EventRun::EventRun(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, const EventOptions& opt)
    : c_(c),
      s_(s),
      t_end_(t_end),
      obs_(obs),
      opt_(opt),
      // An observer that reads only contact blocks' forces needs the groove segments' end rows
      // at quiet-phase samples (O(N) per sample instead of O(sum n^2) for long grooves).
      ends_only_(!obs.reads_groove_interiors()),
      control_(c, opt.tol),
      dp_(c.N),
      search_(c.N),
      sw_(c.N),
      shapes_(c),
      store_(c, shapes_),
      // Settled grooves are a form of fast-forward (they drop a transient below the tolerance),
      // so they follow the same switch; the closed-form crossings of stuck blocks are exact
      // either way.
      active_(c, store_, opt.fast_forward, control_.atol_u(), control_.atol_v(), opt.modal_max_run,
              opt.modal_max_groove, t_end),
      clock_(sample_dt, s.t),
      sample_(s),
      fa_(c.N),
      fb_(c.N) {
  shapes_.set_sample_dt(sample_dt);
  if (opt.exact_stepper) {
    spans_ = std::make_unique<SpanModes>(c, store_);
    screen_ = std::make_unique<SpanScreen>(c);
    spans_friction_only_ = obs.reads_only_friction();
    spans_switched_.assign(c.N, 0);
  }
  if (opt.fast_forward) {
    quiet_ = std::make_unique<QuietPhase>(c, store_);
    if (ends_only_) quiet_->set_sample_scales(active_.settle_eps_u(), active_.settle_eps_v());
  }
}

void EventRun::reclassify(bool from_scratch) {
  if (from_scratch)
    active_.rebuild(c_, s_);
  else
    active_.update(c_, s_, sw_.touched(), sw_.touched_list());
  if (spans_)
    for (int i : sw_.touched_list())
      if (!spans_switched_[i]) spans_switched_[i] = 1, spans_switched_list_.push_back(i);
  sw_.clear_touched();
  dp_.set_frozen(s_.u.data(), active_.stepped());
  spans_valid_ = false;
  mode_valid_ = false;
  stage1_valid_ = false;
}

// Only the exact runs the switch reads or re-projects are brought to s.t first, unless the
// switch may stop every sliding block (every sliding block is flagged: only flagged blocks
// switch, and one that starts stops none): a quiet phase begins from the whole state. (Not after
// settling: that would overwrite the v = 0 of the blocks that just stopped.)
bool EventRun::may_go_quiet() const {
  int stopping = 0;
  for (int i : sw_.flagged()) stopping += s_.dir[i] != 0;
  return stopping >= sw_.n_sliding();
}

void EventRun::switch_now() {
  WorkTimer timer(s_.work, s_.work.switching_s);
  ++s_.work.switch_instants;
  if (may_go_quiet())
    active_.materialise(s_.t, s_.u.data(), s_.v.data());
  else
    active_.materialise_near(s_.t, s_.u.data(), s_.v.data(), sw_.flagged());
  if (sw_.apply(c_, s_) > 0 && opt_.switch_log) opt_.switch_log->push_back(s_.t);
  if (!sw_.touched_list().empty()) obs_.switched(c_, s_, sw_.touched_list());
  reclassify();
}

void EventRun::promote_runs() {
  if (!(s_.t >= active_.next_promotion())) return;
  WorkTimer timer(s_.work, s_.work.switching_s);
  // The promoted runs are projected from the state: the exact stepper writes its runs first (the
  // others are kept by the next projection: nothing beside them switched).
  if (spans_ && spans_valid_) write_spans(false);
  if (!active_.promote_runs(c_, s_)) return;
  dp_.set_frozen(s_.u.data(), active_.stepped());
  spans_valid_ = false;
  stage1_valid_ = false;
}

void EventRun::take_step_end(const std::vector<BlockRange>& spans) {
  for (const auto& sp : spans) {
    std::copy(dp_.u1() + sp.lo, dp_.u1() + sp.hi, s_.u.begin() + sp.lo);
    std::copy(dp_.v1() + sp.lo, dp_.v1() + sp.hi, s_.v.begin() + sp.lo);
  }
}

void EventRun::sample_if_due() {
  if (!clock_.due(s_.t)) return;
  WorkTimer timer(s_.work, s_.work.sampling_s);
  ++s_.work.samples;
  if (spans_valid_) write_spans(spans_friction_only_);
  active_.materialise(s_.t, s_.u.data(), s_.v.data(), true, ends_only_);
  obs_.sample(c_, s_);
  clock_.advance();
}

// Everything but the kinematics that an observer reads from a sample: the work counters and how
// many contact blocks have slid (the all-slipped end of loading). A stale count there once
// deferred the end of loading to the next active phase that happened to hold a sample, so mu_s
// depended on the sample spacing (test FirstPeak.EndOfLoadingDoesNotDependOnSampleSpacing).
void EventRun::stamp_sample() {
  sample_.steps = s_.steps, sample_.rhs_evals = s_.rhs_evals, sample_.switches = s_.switches;
  sample_.n_slipped_once = s_.n_slipped_once;
}

void EventRun::jump_exact() {
  const auto next = active_.next_crossing();
  const double t_stop = std::min({clock_.next(), t_end_, next.t});
  if (t_stop > s_.t) {
    s_.t = t_stop;
    ++s_.steps;  // one exact step (State::steps counts accepted steps, of any kind)
    ++s_.work.exact_jumps;
  }
  if (next.t <= s_.t) {
    if (next.recheck) {
      WorkTimer timer(s_.work, s_.work.switching_s);
      active_.recheck(c_, s_);
    } else {
      sw_.flag(next.block);
      switch_now();
    }
  }
  stage1_valid_ = false;
  sample_if_due();
}

}  // namespace sb::event_detail
