#include "springblock/integrate/methods/uncoupled.hpp"

#include <cmath>
#include <queue>
#include <stdexcept>

#include "springblock/integrate/linear/damped_mode.hpp"
#include "springblock/integrate/linear/mode_stop.hpp"
#include "springblock/integrate/events/switching.hpp"
#include "springblock/integrate/numerics/affine_crossing.hpp"
#include "springblock/infinity.hpp"
#include "springblock/sample_schedule.hpp"
#include "springblock/work_profile.hpp"

namespace sb::event_detail {
namespace {

struct Block {
  double t_ref = 0;       // start of the current moving phase
  double x0 = 0, p0 = 0;  // deviation from the particular solution and its rate at t_ref
  double phi = 0;         // friction force of the phase: dir f_kin, 0 in a groove
  unsigned version = 0;   // invalidates stale queue entries
};

class Solver {
 public:
  Solver(const Chain& c, State& s, std::vector<double>* log)
      : c_(c),
        s_(s),
        log_(log),
        b_(c.N),
        friction_{std::vector<double>(c.N, 0.0), std::vector<double>(c.N, 0.0)} {
    for (int i = 0; i < (c.uniform() ? 1 : c.N); ++i) modes_.emplace_back(0.5 * c.gamma, c.k_s(i) / c.mass(i));
  }

  void run(double t_end, double sample_dt, Observer& obs);

 private:
  const DampedMode& mode(int i) const { return modes_[c_.uniform() ? 0 : i]; }
  // Particular solution of moving block i with friction phi at time t.
  double u_p(int i, double phi, double t) const {
    return c_.v_slider * t - phi / c_.k_s(i) - c_.gamma * c_.v_slider / mode(i).omega2;
  }
  void eval(int i, double t, double& u, double& v) {
    const Block& b = b_[i];
    double x, xd;
    mode(i).eval(b.x0, b.p0, t - b.t_ref, x, xd);
    ++evals_;
    u = u_p(i, b.phi, t) + x;
    v = c_.v_slider + xd;
  }
  // Start a moving phase of block i at time t from its current u, v (friction phi).
  void start_moving(int i, double t, double phi) {
    Block& b = b_[i];
    b.t_ref = t;
    b.phi = phi;
    b.x0 = s_.u[i] - u_p(i, phi, t);
    b.p0 = s_.v[i] - c_.v_slider;
    // Released from rest with its pull short of kinetic friction by round-off only (|deficit|
    // <= 1e-9 f_kin, the tolerance of switching.hpp): start from exact balance, x''(0) = 0.
    // Otherwise a clipped pair (f_kin = f_static, released exactly at its threshold) would
    // stop at once and be released again at the same instant, for ever.
    if (phi != 0.0 && s_.v[i] == 0.0) {
      const double deficit = std::copysign(1.0, phi) * (c_.k_s(i) * (c_.v_slider * t - s_.u[i]) - phi);
      if (deficit < 0.0 && deficit >= -1e-9 * std::fabs(phi)) b.x0 = c_.gamma * c_.v_slider / mode(i).omega2;
    }
  }
  double first_stop(int i);
  void schedule(int i, double t_next);
  // Apply the stick/slip rules to block i at time t (after its event, or at the start).
  void apply_rules_at(int i, double t, bool event_here);
  void materialise(double t);
  // Block i's friction force as a + b t until its next event (for sample_affine): a stuck
  // block's is its driving force K_s (v t - u_i), a sliding block's its constant kinetic
  // friction. It changes only at the block's own events (per_block stretches).
  void update_friction(int i) {
    if (!c_.contact[i]) return;
    if (s_.dir[i] == 0) friction_.a[i] = -c_.k_s(i) * s_.u[i], friction_.b[i] = c_.k_s(i) * c_.v_slider;
    else friction_.a[i] = s_.dir[i] * c_.f_kinetic[i], friction_.b[i] = 0.0;
  }

  const Chain& c_;
  State& s_;
  std::vector<double>* log_;
  std::vector<Block> b_;
  std::vector<DampedMode> modes_;  // each block's oscillator on its slider spring: one for a chain of equal blocks
  struct {
    std::vector<double> a, b;
  } friction_;  // each block's friction force a + b t between its events
  long long evals_ = 0;
  CascadeGuard cascade_;
  struct Entry {
    double t;
    int i;
    unsigned version;
    bool operator>(const Entry& o) const { return t > o.t || (t == o.t && i > o.i); }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
};

double Solver::first_stop(int i) {
  const Block& b = b_[i];
  const double tau = first_stop_tau(mode(i), b.x0, b.p0, s_.dir[i], c_.v_slider, b.t_ref, evals_);
  return tau == kInf ? kInf : b.t_ref + tau;
}

void Solver::schedule(int i, double t_next) {
  Block& b = b_[i];
  ++b.version;
  if (t_next < kInf) queue_.push({t_next, i, b.version});
}

void Solver::apply_rules_at(int i, double t, bool event_here) {
  s_.t = t;
  int made = 0;
  {
    // The work profile's kinds as the coupled event method has them: the rules here, the
    // block's next event time below (event location).
    WorkTimer timer(s_.work, s_.work.switching_s);
    ++s_.work.switch_instants;
    // The chain's rules (switching.hpp) on this one block until it stops changing.
    for (;;) {
      const int m = apply_rules(c_, s_, i, event_here);
      event_here = false;
      made += m;
      cascade_.add(c_, t, m);
      if (m == 0) break;
    }
    s_.switches += made;
    if (made > 0 && log_ && (log_->empty() || log_->back() != t)) log_->push_back(t);
    update_friction(i);
  }
  WorkTimer timer(s_.work, s_.work.event_location_s);
  if (s_.dir[i] != 0) {
    start_moving(i, t, s_.dir[i] * c_.f_kinetic[i]);
    schedule(i, first_stop(i));
  } else {
    // Stuck: F(t') = F(t) + K_s v_s (t' - t) reaches +-f_static (never when nothing loads it).
    const double F = c_.k_s(i) * (c_.v_slider * t - s_.u[i]), rate = c_.k_s(i) * c_.v_slider;
    schedule(i, t + affine_crossing(F, rate, c_.f_static[i]));
  }
}

void Solver::materialise(double t) {
  for (int i = 0; i < c_.N; ++i)
    if (!c_.contact[i] || s_.dir[i] != 0) eval(i, t, s_.u[i], s_.v[i]);
}

void Solver::run(double t_end, double sample_dt, Observer& obs) {
  const int N = c_.N;
  const double t0 = s_.t;
  for (int i = 0; i < N; ++i) {
    if (!c_.contact[i]) {
      start_moving(i, t0, 0.0);  // grooves move for ever, no events
      continue;
    }
    if (s_.dir[i] != 0) {
      start_moving(i, t0, s_.dir[i] * c_.f_kinetic[i]);
      schedule(i, first_stop(i));
      update_friction(i);
    } else {
      const auto switches_before = s_.switches;
      apply_rules_at(i, t0, false);
      if (s_.switches != switches_before) obs.switched(c_, s_, SwitchedBlocks::one(i));
    }
  }
  const bool friction_only = obs.reads_only_friction();
  auto sample = [&](double t) {
    WorkTimer timer(s_.work, s_.work.sampling_s);
    ++s_.work.samples;
    s_.t = t;
    if (!friction_only) materialise(t);
    obs.sample(c_, s_);
  };
  sample(t0);
  SampleSchedule clock(sample_dt, t0);
  while (!obs.wants_stop()) {
    // Drop entries made stale by a later reschedule.
    while (!queue_.empty() && queue_.top().version != b_[queue_.top().i].version) queue_.pop();
    const double t_event = queue_.empty() ? kInf : queue_.top().t;
    const double t_sample = clock.next();
    if (t_event <= t_sample && t_event <= t_end) {
      const int i = queue_.top().i;
      queue_.pop();
      // The block's state at its event: a sliding block is at rest there, a stuck one unmoved.
      if (s_.dir[i] != 0) {
        WorkTimer timer(s_.work, s_.work.stepping_s);
        eval(i, t_event, s_.u[i], s_.v[i]);
        s_.v[i] = 0.0;
      }
      apply_rules_at(i, t_event, true);  // an event always switches its block
      obs.switched(c_, s_, SwitchedBlocks::one(i));
      ++s_.steps;
      continue;
    }
    if (t_sample > t_end) break;
    if (friction_only) {
      // Until the next event every friction force is affine in t: the observer may take all
      // the samples before it at once (samples k dt < t_event and < t_end). A sample exactly at
      // t_end comes through sample(), as in the coupled integrator, so a run's samples are cut
      // into stretches the same way whatever its end (FanOut relies on it).
      const double t_stop = std::min(t_event, t_end);
      const long long k = clock.index(), k_end = clock.first_at_or_after(t_stop);
      const long used = [&] {
        WorkTimer timer(s_.work, s_.work.sampling_s);
        return obs.sample_affine(c_, s_, static_cast<long>(k), sample_dt, static_cast<long>(k_end - k),
                                 AffineForces{friction_.a.data(), friction_.b.data(), true});
      }();
      if (used > 0) {
        s_.work.stretch_samples += used;
        clock.advance(used);
        s_.t = clock.time_of(clock.index() - 1);
        continue;
      }
    }
    sample(t_sample);
    clock.advance();
  }
  const double t_stop = obs.wants_stop() ? s_.t : t_end;
  s_.t = t_stop;
  materialise(t_stop);
  s_.rhs_evals += (evals_ + N - 1) / N;
}

}  // namespace

void run_uncoupled(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs,
                   std::vector<double>* log) {
  if (c.K_int != 0.0) throw std::logic_error("run_uncoupled: the chain has internal springs");
  Solver(c, s, log).run(t_end, sample_dt, obs);
}

}  // namespace sb::event_detail
