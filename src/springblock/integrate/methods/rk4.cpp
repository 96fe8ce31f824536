#include "springblock/integrate/methods/rk4.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "springblock/integrate/events/switching.hpp"
#include "springblock/integrate/step/chain_accel.hpp"
#include "springblock/kernel_clones.hpp"
#include "springblock/sample_schedule.hpp"
#include "springblock/work_profile.hpp"

// The step and the switch screen have AVX2 clones (kernel_clones.hpp). With the screen they made
// accuracy_cost's RK4 settings x1.4-2.2 faster (paper tier, before and after), bit-identical.
namespace sb {
namespace {

// Per-run workspace, allocated once: no allocation inside the step loop.
struct Workspace {
  std::vector<double> a, us, vs, su, sv;
  std::vector<double> mobile;  // 1 = free or sliding, 0 = stuck
  std::vector<double> f_kin;   // signed kinetic friction force of sliding blocks
  // For the end-of-step screen (switch_screen), kept by sync_block like mobile and f_kin.
  struct Screen {
    std::vector<double> slide_dir, f_screen, stop_bias;
  } screen;
  std::vector<int> switched;  // blocks switched at the end of this step, for Observer::switched
  explicit Workspace(int N)
      : a(N), us(N), vs(N), su(N), sv(N), mobile(N), f_kin(N),
        screen{std::vector<double>(N), std::vector<double>(N), std::vector<double>(N)} {}
};

// One intermediate RK4 stage: accumulate the stage slopes (weight 2) and form the next stage
// input y + c h k. A separate function with restrict-qualified parameters lets GCC vectorise
// it (the same loops inlined with restrict locals did not: measured 15-20% on the step).
SB_INLINE void rk4_stage(int N, const double* __restrict u, const double* __restrict v,
                      const double* __restrict a, double ch, double* __restrict us,
                      double* __restrict vs, double* __restrict su, double* __restrict sv) {
  for (int i = 0; i < N; ++i) {
    su[i] += 2.0 * vs[i];
    sv[i] += 2.0 * a[i];
    us[i] = u[i] + ch * vs[i];
    vs[i] = v[i] + ch * a[i];
  }
}

// The accelerations of the whole chain (PerBlock: from each block's springs and mass).
template <bool Coupled, bool Damped, bool PerBlock>
SB_INLINE void chain_accel(const Chain& c, const double* __restrict u, const double* __restrict v, double t,
                           const Workspace& w, double* __restrict a) {
  event_detail::chain_accel<Coupled, Damped, PerBlock>(c, 0, c.N, u, v, t, w.mobile.data(), w.f_kin.data(), a);
}

template <bool Coupled, bool Damped, bool PerBlock>
SB_KERNEL_CLONES void rk4_step(const Chain& c, State& s, Workspace& w, double t, double h) {
  const int N = c.N;
  double* u = s.u.data();
  double* v = s.v.data();
  double* a = w.a.data();
  double* us = w.us.data();
  double* vs = w.vs.data();
  double* su = w.su.data();
  double* sv = w.sv.data();
  const double h2 = 0.5 * h, h6 = h / 6.0;
  chain_accel<Coupled, Damped, PerBlock>(c, u, v, t, w, a);
  // Stage 1 starts the accumulators: su = k1_u = v, sv = k1_v = a.
  std::copy(v, v + N, su);
  std::copy(a, a + N, sv);
  for (int i = 0; i < N; ++i) us[i] = u[i] + h2 * v[i];
  for (int i = 0; i < N; ++i) vs[i] = v[i] + h2 * a[i];
  chain_accel<Coupled, Damped, PerBlock>(c, us, vs, t + h2, w, a);
  rk4_stage(N, u, v, a, h2, us, vs, su, sv);
  chain_accel<Coupled, Damped, PerBlock>(c, us, vs, t + h2, w, a);
  rk4_stage(N, u, v, a, h, us, vs, su, sv);
  chain_accel<Coupled, Damped, PerBlock>(c, us, vs, t + h, w, a);
  for (int i = 0; i < N; ++i) {
    u[i] += h6 * (su[i] + vs[i]);
    v[i] += h6 * (sv[i] + a[i]);
  }
}

// Most steps switch nothing, yet the exact rules below walk every block with branches. This
// branch-free pass (a max reduction, it vectorises) answers "might any block switch?"
// conservatively: a sliding block whose velocity reached zero (-dir v >= 0), or a stuck one
// whose spring force, computed here without the (zero) damping term and in another order,
// reaches its threshold lowered by a relative 1e-9 (far above the rounding of either sum). Only
// then do the exact rules run, so every decision is theirs; the screen skips only steps on
// which they would change nothing. Coefficients: the uniform chain's or per block.
template <class Coefficients>
SB_KERNEL_CLONES bool switch_screen(const Coefficients& k, double slider, const double* __restrict u,
                   const double* __restrict v, const double* __restrict slide_dir,
                   const double* __restrict f_screen, const double* __restrict stop_bias) {
  const int N = k.N;
  auto score = [&](int i, double F) {
    return std::max(std::fabs(F) - f_screen[i], stop_bias[i] - slide_dir[i] * v[i]);
  };
  auto spring = [&](int i) { return force_checked<true, false>(k, i, slider, u, v, 0.0); };
  if (N == 1) return score(0, spring(0)) >= 0.0;
  double worst = std::max(score(0, spring(0)), score(N - 1, spring(N - 1)));
  // GCC keeps a floating-point max reduction scalar (NaN and signed-zero rules) unless told
  // that its order does not matter: a max is exact, so it does not.
#pragma omp simd reduction(max : worst)
  for (int i = 1; i < N - 1; ++i) {
    const double F = force_interior<true, false>(k, i, slider, u, v, 0.0);
    const double slip = std::fabs(F) - f_screen[i];
    const double stop = stop_bias[i] - slide_dir[i] * v[i];
    const double x = slip > stop ? slip : stop;
    worst = worst > x ? worst : x;
  }
  return worst >= 0.0;
}

// Block i's entries in the workspace, from its contact and s.dir: they change only when it switches.
void sync_block(const Chain& c, const State& s, Workspace& w, int i) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const bool sliding = c.contact[i] && s.dir[i] != 0, stuck = c.contact[i] && s.dir[i] == 0;
  w.mobile[i] = (!c.contact[i] || s.dir[i] != 0) ? 1.0 : 0.0;
  w.f_kin[i] = s.dir[i] * c.f_kinetic[i];
  w.screen.slide_dir[i] = c.contact[i] ? s.dir[i] : 0;
  w.screen.f_screen[i] = stuck ? c.f_static[i] * (1.0 - 1e-9) : inf;
  w.screen.stop_bias[i] = sliding ? 0.0 : -inf;
}

// Stick and slip decisions at the end of a step: the event method's rules (switching.hpp) with a
// sliding block's velocity that reached or crossed zero within the step as its located stop, one
// pass in block order. Returns the number of sliding blocks.
int apply_switches(const Chain& c, State& s, Workspace& w) {
  int n_sliding = 0;
  for (int i = 0; i < c.N; ++i) {
    if (!c.contact[i]) continue;
    if (const int made = event_detail::apply_rules(c, s, i, s.dir[i] != 0 && s.v[i] * s.dir[i] <= 0.0)) {
      s.switches += made;
      w.switched.push_back(i);
      sync_block(c, s, w, i);
    }
    n_sliding += s.dir[i] != 0;
  }
  return n_sliding;
}

// apply_switches behind the screen (unless `screen` is off, the tests' reference); `n_sliding`
// is the count after the previous call.
template <bool PerBlock>
int apply_switches_screened(const Chain& c, State& s, Workspace& w, int n_sliding, bool screen) {
  auto screened = [&](const auto& k) {
    return switch_screen(k, c.v_slider * s.t, s.u.data(), s.v.data(), w.screen.slide_dir.data(),
                         w.screen.f_screen.data(), w.screen.stop_bias.data());
  };
  bool maybe = !screen;
  if constexpr (PerBlock) maybe = maybe || screened(c.block_force_coefficients());
  else maybe = maybe || screened(c.force_coefficients());
  return maybe ? apply_switches(c, s, w) : n_sliding;
}

// Steps until the first threshold crossing of a motionless, fully stuck chain whose forces
// grow by K_s v per unit time. Returns a count k >= 1 such that no block exceeds its threshold
// at steps 1..k-1 (a safe jump length); the stepper then checks step k the normal way.
std::int64_t quiet_steps(const Chain& c, const State& s, std::int64_t n, double h, std::int64_t n_end) {
  double k_min = static_cast<double>(n_end - n);
  for (int i = 0; i < c.N; ++i) {
    const double F = c.driving_force(i, s.u.data(), s.v.data(), s.t);
    const double rate = c.k_s(i) * c.v_slider * h;  // force increase per step
    k_min = std::min(k_min, std::floor((c.f_static[i] - F) / rate));
  }
  // Two steps of margin absorb rounding in the closed form; the remaining steps run normally.
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(k_min) - 2);
}

template <bool Coupled, bool Damped, bool PerBlock>
void run_loop(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, double h, bool screen) {
  Workspace w(c.N);
  for (int i = 0; i < c.N; ++i) sync_block(c, s, w, i);
  const std::int64_t stride = SampleSchedule::stride(sample_dt, h);
  const std::int64_t n_end = std::llround(t_end / h);
  const bool all_contact = c.n_contact == c.N;
  // Times are n*h from an integer step count, so long runs do not accumulate rounding.
  std::int64_t n = std::llround(s.t / h);
  s.t = n * h;
  // The work profile's times (--profile) in the event method's kinds: the steps, the switching
  // rules, the quiet jumps and the samples; each a leaf, so they add up.
  auto sample = [&] {
    WorkTimer timer(s.work, s.work.sampling_s);
    ++s.work.samples;
    obs.sample(c, s);
  };
  auto tell_switched = [&] {
    if (!w.switched.empty()) obs.switched(c, s, w.switched), w.switched.clear();
  };
  int n_sliding = apply_switches(c, s, w);
  tell_switched();
  sample();
  while (n < n_end && !obs.wants_stop()) {
    if (all_contact && n_sliding == 0) {
      const std::int64_t jump = [&] {
        WorkTimer timer(s.work, s.work.quiet_s);
        return std::min(quiet_steps(c, s, n, h, n_end), n_end - n);
      }();
      if (jump > 1) {
        // Nothing moves during the jump; emit the samples it covers.
        const std::int64_t target = n + jump - 1;
        for (std::int64_t k = (n / stride + 1) * stride; k <= target; k += stride) {
          s.t = k * h;
          sample();
          if (obs.wants_stop()) return;
        }
        n = target;
        s.t = n * h;
      }
    }
    {
      WorkTimer timer(s.work, s.work.stepping_s);
      rk4_step<Coupled, Damped, PerBlock>(c, s, w, n * h, h);
    }
    ++n;
    s.t = n * h;
    ++s.steps;
    s.rhs_evals += 4;
    {
      WorkTimer timer(s.work, s.work.switching_s);
      n_sliding = apply_switches_screened<PerBlock>(c, s, w, n_sliding, screen);
    }
    tell_switched();
    if (n % stride == 0) sample();
  }
}

template <bool PerBlock>
void run_chain(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs, double h, bool screen) {
  const auto e = c.effects();
  if (e.coupled && e.damped) run_loop<true, true, PerBlock>(c, s, t_end, sample_dt, obs, h, screen);
  else if (e.coupled) run_loop<true, false, PerBlock>(c, s, t_end, sample_dt, obs, h, screen);
  else if (e.damped) run_loop<false, true, PerBlock>(c, s, t_end, sample_dt, obs, h, screen);
  else run_loop<false, false, PerBlock>(c, s, t_end, sample_dt, obs, h, screen);
}

}  // namespace

void Rk4::run(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs) {
  if (c.blocks.uniform()) run_chain<false>(c, s, t_end, sample_dt, obs, h_, screen_);
  else run_chain<true>(c, s, t_end, sample_dt, obs, h_, screen_);
}

}  // namespace sb
