#include "springblock/integrate/event_driven.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "springblock/integrate/active_set.hpp"
#include "springblock/integrate/dopri5.hpp"
#include "springblock/integrate/event_search.hpp"
#include "springblock/integrate/quiet_phase.hpp"
#include "springblock/integrate/sample_grid.hpp"
#include "springblock/integrate/switching.hpp"
#include "springblock/integrate/uncoupled.hpp"

namespace sb {
namespace {

using event_detail::ActiveSet;
using event_detail::Dopri5;
using event_detail::EventSearch;
using event_detail::QuietPhase;
using event_detail::Switching;

// Sample times are k * sample_dt from an integer k, so long runs do not accumulate rounding.
struct SampleClock {
  double dt;
  long long k;
  double next() const { return static_cast<double>(k) * dt; }
};

template <bool Coupled, bool Damped>
void run_loop(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, double tol,
              bool fast_forward, int modal_max_run, int modal_max_groove, std::vector<double>* log_) {
  const int N = c.N;
  // Error scales: the spring stretch at the threshold, F_n / K_s, and the velocity of an
  // oscillation of that amplitude at the slider frequency.
  const double len = c.F_n / c.K_s, omega_s = std::sqrt(c.K_s / c.m);
  const double atol_u = tol * len, atol_v = tol * omega_s * len, rtol = tol;
  const double omega_max = std::sqrt((c.K_s + 4.0 * c.K_int) / c.m);
  double h = 0.5 * std::pow(tol, 0.2) / omega_max;

  // All workspaces allocated once per run.
  Dopri5 dp(N);
  EventSearch search(N);
  Switching sw(N);
  // Settled grooves are a form of fast-forward (they drop a transient below the tolerance), so
  // they follow the same switch; the closed-form crossings of stuck blocks are exact either way.
  ActiveSet active(c, fast_forward, atol_u, atol_v, modal_max_run, modal_max_groove, t_end);
  active.set_sample_dt(sample_dt);
  std::unique_ptr<QuietPhase> quiet;
  if (fast_forward) {
    quiet = std::make_unique<QuietPhase>(c);
    quiet->set_sample_dt(sample_dt);
  }
  State sample = s;  // buffer for samples served from the exact quiet-phase solution
  // Everything but the kinematics that an observer reads from a sample: the work counters and
  // how many contact blocks have slid (the all-slipped end of loading). A stale count there
  // once deferred the end of loading to the next active phase that happened to hold a sample,
  // so mu_s depended on the sample spacing (test FirstPeak.EndOfLoadingDoesNotDependOnSampleSpacing).
  auto stamp_sample = [&] {
    sample.steps = s.steps, sample.rhs_evals = s.rhs_evals, sample.switches = s.switches;
    sample.n_slipped_once = s.n_slipped_once;
  };
  std::vector<double> fa(N), fb(N);  // affine contact forces a + b t once a quiet phase's modes died
  // An observer that reads only contact blocks' forces needs the groove segments' end rows at
  // quiet-phase samples (O(N) per sample instead of O(sum n^2) for long grooves).
  const bool ends_only = !obs.reads_groove_interiors();
  if (quiet && ends_only) quiet->set_sample_scales(active.settle_eps_u(), active.settle_eps_v());

  // After every switch: which runs are stepped, which stuck blocks are watched.
  auto reclassify = [&] {
    active.rebuild(c, s, sw.touched());
    sw.clear_touched();
    dp.set_frozen(s.u.data());
  };
  // Settle the switches flagged at s.t. Only the exact runs the switch reads or re-projects are
  // brought to s.t first, unless the switch may stop every sliding block (only flagged blocks
  // switch): a quiet phase begins from the whole state. (Not after settling: that would
  // overwrite the v = 0 of the blocks that just stopped.)
  auto switch_now = [&] {
    if (static_cast<std::size_t>(sw.n_sliding()) <= sw.flagged().size())
      active.materialise(s.t, s.u.data(), s.v.data());
    else
      active.materialise_near(s.t, s.u.data(), s.v.data(), sw.flagged());
    if (sw.settle(c, s) > 0 && log_) log_->push_back(s.t);
    reclassify();
  };

  sw.sync(c, s);
  sw.settle(c, s, true);
  reclassify();
  obs.sample(c, s);
  SampleClock clock{sample_dt, static_cast<long long>(std::floor(s.t / sample_dt)) + 1};
  bool stage1_valid = false;

  // The stepped blocks take the end of the last attempted step.
  auto take_step_end = [&](const std::vector<event_detail::Span>& spans) {
    for (const auto& sp : spans) {
      std::copy(dp.u1() + sp.lo, dp.u1() + sp.hi, s.u.begin() + sp.lo);
      std::copy(dp.v1() + sp.lo, dp.v1() + sp.hi, s.v.begin() + sp.lo);
    }
  };
  auto sample_if_due = [&] {
    if (s.t == clock.next()) {
      active.materialise(s.t, s.u.data(), s.v.data(), true, ends_only);
      obs.sample(c, s);
      ++clock.k;
    }
  };

  while (s.t < t_end && !obs.wants_stop()) {
    if (fast_forward && sw.n_sliding() == 0) {
      // Quiet phase: exact until the first threshold crossing (or the end of the run).
      quiet->begin(c, s.t, s.u.data(), s.v.data());
      const auto next = quiet->next_threshold(c, t_end);
      // Contact blocks do not move in a quiet phase: copy them once, update the grooves per sample.
      if (clock.next() < next.t) {
        std::copy(s.u.begin(), s.u.end(), sample.u.begin());
        std::copy(s.v.begin(), s.v.end(), sample.v.begin());
        std::copy(s.dir.begin(), s.dir.end(), sample.dir.begin());
      }
      // Once every groove's modes have died out, every contact block's force is affine in t:
      // the observer may take the rest of the phase's samples at once (sample_affine).
      const double dead_after = quiet->all_dead_after();
      bool affine_ready = false;
      while (clock.next() < next.t) {
        if (clock.next() >= dead_after) {
          if (!affine_ready) {
            quiet->affine_forces(c, s.u.data(), fa.data(), fb.data());
            affine_ready = true;
          }
          // Samples k dt < next.t, counted exactly as the clock will produce them.
          const long long k_end = event_detail::first_sample_at_or_after(next.t, sample_dt, clock.k);
          sample.t = clock.next();
          stamp_sample();
          const long used = obs.sample_affine(c, sample, static_cast<long>(clock.k), sample_dt,
                                              static_cast<long>(k_end - clock.k), fa.data(), fb.data());
          if (used > 0) {
            clock.k += used;
            if (obs.wants_stop()) {
              const double t_last = static_cast<double>(clock.k - 1) * sample_dt;
              quiet->evaluate(t_last, s.u.data(), s.v.data());
              s.t = t_last;
              return;
            }
            continue;
          }
        }
        sample.t = clock.next();
        quiet->sample(sample.t, sample.u.data(), sample.v.data(), ends_only);
        stamp_sample();
        obs.sample(c, sample);
        ++clock.k;
        if (obs.wants_stop()) {
          quiet->evaluate(sample.t, s.u.data(), s.v.data());
          s.t = sample.t;
          return;
        }
      }
      quiet->evaluate(next.t, s.u.data(), s.v.data());
      s.t = next.t;
      if (next.block >= 0) sw.flag(next.block);
      if (sw.settle(c, s) > 0 && log_) log_->push_back(s.t);
      // Every groove is exact at s.t. Grooves settled before the quiet phase stay settled: their
      // stuck ends have not moved, so their A + B t is still their path.
      reclassify();
      stage1_valid = false;
      sample_if_due();
      continue;
    }

    const auto& spans = active.stepped();
    if (spans.empty()) {
      // Everything that moves is exact (modal or settled runs): go straight to the next event,
      // sample or the end of the run.
      const auto next = active.next_crossing();
      const double t_stop = std::min({clock.next(), t_end, next.t});
      if (t_stop > s.t) {
        s.t = t_stop;
        ++s.steps;  // one exact step (State::steps counts accepted steps, of any kind)
      }
      if (next.t <= s.t) {
        if (next.recheck) {
          active.recheck(c, s);
        } else {
          sw.flag(next.block);
          switch_now();
        }
      }
      stage1_valid = false;
      sample_if_due();
      continue;
    }
    if (!stage1_valid) {
      dp.first_stage<Coupled, Damped>(c, spans, s.u.data(), s.v.data(), s.t, sw.mobile(), sw.f_kin());
      ++s.rhs_evals;
      stage1_valid = true;
    }
    // Shorten the step to land exactly on the next sample, the next closed-form crossing of a
    // stuck block, or the end of the run.
    const auto crossing = active.next_crossing();
    if (crossing.t <= s.t) {
      if (crossing.recheck) {
        active.recheck(c, s);  // nothing switched: stage 1 stays valid
      } else {
        sw.flag(crossing.block);
        switch_now();
        stage1_valid = false;
      }
      continue;
    }
    const double t_stop = std::min({clock.next(), t_end, crossing.t});
    const bool clipped = s.t + h >= t_stop;
    const double h_try = clipped ? t_stop - s.t : h;
    const double err = dp.attempt<Coupled, Damped>(c, spans, s.u.data(), s.v.data(), s.t, h_try, sw.mobile(),
                                                   sw.f_kin(), atol_u, atol_v, rtol);
    s.rhs_evals += 6;
    const double factor = err == 0.0 ? 5.0 : std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
    if (!(err <= 1.0)) {
      h = h_try * std::min(factor, 1.0);
      continue;
    }
    const double theta = search.locate(c, s, dp, h_try, active);
    if (theta <= 1.0) {
      // Redo the step to exactly the earliest event time, switch there, restart.
      const double h_event = theta * h_try;
      if (h_event > 0.0) {
        dp.attempt<Coupled, Damped>(c, spans, s.u.data(), s.v.data(), s.t, h_event, sw.mobile(), sw.f_kin(),
                                    atol_u, atol_v, rtol);
        s.rhs_evals += 6;
        take_step_end(spans);
        s.t = (theta == 1.0 && clipped) ? t_stop : s.t + h_event;
        ++s.steps;
      }
      for (int i : search.hits()) sw.flag(i);
      // A closed-form crossing due at the same instant switches with them.
      if (theta == 1.0 && clipped && t_stop == crossing.t && !crossing.recheck) sw.flag(crossing.block);
      switch_now();
      stage1_valid = false;
      sample_if_due();
      continue;
    }
    take_step_end(spans);
    dp.accept_fsal();
    s.t = clipped ? t_stop : s.t + h_try;
    ++s.steps;
    h = clipped ? std::max(h, h_try * factor) : h_try * factor;
    if (clipped && t_stop == crossing.t && crossing.recheck) {
      active.recheck(c, s);
    } else if (clipped && t_stop == crossing.t) {
      sw.flag(crossing.block);
      switch_now();
      stage1_valid = false;
    } else {
      // Ringing grooves whose transient has died leave the stepped set (stage 1 of the others
      // stays valid: nothing switched).
      active.retire_settled(c, s);
    }
    sample_if_due();
  }
  active.materialise(s.t, s.u.data(), s.v.data());
}

}  // namespace

void EventDriven::run(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs) {
  const auto e = c.effects();
  // Without internal springs every block is its own system: solved exactly, block by block
  // (uncoupled.hpp). With fast-forward off the stepper runs instead (the tests' reference).
  if (!e.coupled && fast_forward_) {
    event_detail::run_uncoupled(c, s, t_end, sample_dt, obs, switch_log_);
    return;
  }
  const int mm = modal_max_run_, mg = modal_max_groove_;
  if (e.coupled && e.damped) run_loop<true, true>(c, s, t_end, sample_dt, obs, tol_, fast_forward_, mm, mg, switch_log_);
  else if (e.coupled) run_loop<true, false>(c, s, t_end, sample_dt, obs, tol_, fast_forward_, mm, mg, switch_log_);
  else if (e.damped) run_loop<false, true>(c, s, t_end, sample_dt, obs, tol_, fast_forward_, mm, mg, switch_log_);
  else run_loop<false, false>(c, s, t_end, sample_dt, obs, tol_, fast_forward_, mm, mg, switch_log_);
}

}  // namespace sb
