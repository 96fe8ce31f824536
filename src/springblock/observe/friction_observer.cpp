#include "springblock/observe/friction_observer.hpp"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>

#include "springblock/chain_force.hpp"
#include "springblock/kernel_clones.hpp"

namespace sb {

namespace {
// The force on each of blocks lo..hi-1 (all interior: 0 < i < N - 1) if it is stuck (v = 0: no
// damping term), as sample() reads it. Element-wise, so it vectorises; the entries of sliding
// blocks are computed too, and not read.
SB_KERNEL_CLONES void stuck_forces(const ForceCoefficients& k, int lo, int hi, double slider,
                                   const double* __restrict u, double* __restrict f) {
  for (int i = lo; i < hi; ++i) f[i] = force_interior<true, false>(k, i, slider, u, nullptr, 0.0);
}
// The same on a chain whose blocks differ, with each block's springs in Chain::driving_force's
// order of additions (force_checked_interior), so that a stuck block's force has the same doubles
// whichever of the two computes it.
SB_KERNEL_CLONES void stuck_forces(const BlockForceCoefficients& k, int lo, int hi, double slider,
                                   const double* __restrict u, const double* __restrict v, double* __restrict f) {
  for (int i = lo; i < hi; ++i) f[i] = force_checked_interior<true>(k, i, slider, u, v, 0.0);
}

// The friction force of every block summed over the chain, |F| and F: a sliding block's kinetic
// force dir f_kinetic in place of its entry of f, a groove's entry 0 (f holds 0 there, and so does
// f_kinetic). kLanes running sums, block i in lane i % kLanes, added pairwise at the end: one
// sum over the blocks in order is a chain of dependent additions (4 cycles each), most of a
// sample's time on a chain of 200 blocks; kLanes of them run side by side and vectorise. The
// lanes are fixed, not the vector width, so every clone adds the same doubles in the same order.
constexpr int kLanes = 4;
SB_KERNEL_CLONES void friction_sums(int n, const double* __restrict f, const std::int8_t* __restrict dir,
                                    const double* __restrict f_kinetic, double& sum_abs, double& sum_signed) {
  double a[kLanes] = {}, g[kLanes] = {};
  int i = 0;
  for (; i + kLanes <= n; i += kLanes)
    for (int l = 0; l < kLanes; ++l) {
      const double fi = dir[i + l] != 0 ? dir[i + l] * f_kinetic[i + l] : f[i + l];
      a[l] += std::fabs(fi);
      g[l] += fi;
    }
  for (int l = 0; i < n; ++i, ++l) {
    const double fi = dir[i] != 0 ? dir[i] * f_kinetic[i] : f[i];
    a[l] += std::fabs(fi);
    g[l] += fi;
  }
  static_assert(kLanes == 4, "the pairwise total below adds four lanes");
  sum_abs = (a[0] + a[1]) + (a[2] + a[3]);
  sum_signed = (g[0] + g[1]) + (g[2] + g[3]);
}
// The totals a stretch of affine samples from t_first needs (affine_totals.hpp), summed over the
// contact blocks in block order, each force with its sign at t_first.
AffineTotals block_order_totals(const std::vector<std::pair<int, int>>& contact_runs, const State& s,
                                const double* a, const double* b, double t_first) {
  AffineTotals sum;
  sum.t_sign = std::numeric_limits<double>::infinity();
  for (const auto& [lo, hi] : contact_runs)
    for (int i = lo; i < hi; ++i)  // s.dir is constant across the stretch: nothing switches in it
      sum = sum + affine_share(a[i], b[i], s.dir[i] != 0, t_first);
  return sum;
}
}  // namespace

RingingSums& FrictionObserver::ringing(RingingForces& f) {
  if (!ringing_ || &ringing_->forces() != &f) ringing_ = std::make_unique<RingingSums>(f);
  return *ringing_;
}

// Nothing slides while the integrator offers its forces this way (a quiet phase).
void FrictionObserver::sample_ringing(const Chain& c, const State& s, RingingForces& f) {
  double sum_abs, sum_signed;
  ringing(f).at(s.t, sum_abs, sum_signed);
  record(c, s, sum_abs / cfg_.F_load, sum_signed / cfg_.F_load, 0);
}

void FrictionObserver::sample(const Chain& c, const State& s) {
  // The contact blocks, listed once as runs of consecutive blocks: grooves carry no friction
  // and are skipped without a test.
  if (contact_runs_.empty() && c.n_contact > 0) {
    for (int i = 0; i < c.N; ++i) {
      if (!c.contact[i]) continue;
      if (contact_runs_.empty() || contact_runs_.back().second != i) contact_runs_.push_back({i, i + 1});
      else contact_runs_.back().second = i + 1;
    }
    f_contact_.assign(c.N, 0.0);
  }
  const double* u = s.u.data();
  const std::int8_t* dir = s.dir.data();
  const ForceCoefficients k = c.force_coefficients();
  // Every contact block's force if stuck, a run at a time (the chain's ends by the checked
  // form); grooves keep the 0 they were given. Then the friction forces summed over the chain
  // (friction_sums; the order of the additions is a choice of round-off, paper/choices.md).
  double* f = f_contact_.data();
  int n_sliding = 0;
  const bool per_block = !c.blocks.uniform();  // each block's own springs: Chain::driving_force
  for (const auto& [lo, hi] : contact_runs_) {
    const int first = std::max(lo, 1), last = std::min(hi, c.N - 1);
    if (first < last && per_block)
      stuck_forces(c.block_force_coefficients(), first, last, c.v_slider * s.t, u, s.v.data(), f);
    else if (first < last)
      stuck_forces(k, first, last, c.v_slider * s.t, u, f);
    // A chain end's force by the checked form; a one-block run at an end is taken once.
    if (lo == 0 || lo == c.N - 1) f[lo] = c.driving_force(lo, u, s.v.data(), s.t);
    if (hi - 1 != lo && hi == c.N) f[hi - 1] = c.driving_force(hi - 1, u, s.v.data(), s.t);
    for (int i = lo; i < hi; ++i) n_sliding += dir[i] != 0;
  }
  double sum_abs, sum_signed;
  friction_sums(c.N, f, dir, c.f_kinetic.data(), sum_abs, sum_signed);
  record(c, s, sum_abs / cfg_.F_load, sum_signed / cfg_.F_load, n_sliding);
}

void FrictionObserver::follow_forces(const Chain& c, const State& s, const ActiveForces& f) {
  // A live block's leaf holds 0 (its force is read at the sample); a sliding one's sign is its
  // direction's, fixed while it slides.
  auto put = [&](int i) { active_->set(i, f.a[i], f.b[i], f.kind[i] == ActiveForces::kSliding, s.t); };
  if (!active_ || f.all_changed) {
    if (!active_) active_ = std::make_unique<AffineForceTree>(c);
    for (int i = 0; i < c.N; ++i)
      if (c.contact[i]) put(i);
    return;
  }
  for (int i : f.changed) put(i);
}

void FrictionObserver::sample_active(const Chain& c, const State& s, const ActiveForces& f) {
  follow_forces(c, s, f);
  const AffineTotals& known = active_->at(s.t);
  double sum_abs = known.A + known.B * s.t, sum_signed = known.As + known.Bs * s.t;
  for (int i : f.live) {
    const double fi = friction_force(c, s, i);
    sum_abs += std::fabs(fi);
    sum_signed += fi;
  }
  record(c, s, sum_abs / cfg_.F_load, sum_signed / cfg_.F_load, known.n_sliding);
}

void FrictionObserver::record(const Chain& c, const State& s, double mu, double mu_signed, int n_sliding) {
  last_t_ = s.t;

  bool begun_here = false;  // the sample that ends loading or opens the dynamic phase is in no window
  if (!slipped_) {
    if (mu > running_max_) {
      running_max_ = mu;
      t_max_ = s.t;
    }
    running_max_signed_ = std::max(running_max_signed_, mu_signed);
    // End of the loading phase: mu_s is the peak reached up to it.
    if (ends_at_next_sample(c, s) || (tests_drop() && falls(mu, running_max_))) {
      slipped_ = true;
      t_slip_ = s.t;
      begun_here = true;
    }
  }
  if (slipped_ && !dynamic_) {
    if (dynamic_begins(c, s)) dynamic_ = true, t_dynamic_ = s.t, begun_here = true;
  } else if (dynamic_ && !begun_here && s.t >= t_dynamic_ + cfg_.mu_d_skip_s) {
    sum_mu_ += mu;
    sum_mu_signed_ += mu_signed;
    ++n_window_;
  }

  if (cfg_.keep_series) series_.push_back({s.t, mu, mu_signed, n_sliding});
  while (stress_due(s.t)) add_snapshot(c, s.t, [&](int i) { return friction_force(c, s, i); });
  if (cfg_.progress_ns) cfg_.progress_ns->store(static_cast<std::int64_t>(s.t * 1e9), std::memory_order_relaxed);
}

void FrictionObserver::switched(const Chain& c, const State& s, SwitchedBlocks blocks) {
  switched_totals_.switched(blocks.begin(), blocks.end());
  if (cfg_.peak_rule != ExtractionRules::PeakRule::SlidOrEvent || slipped_ || large_event_) return;
  // The open event's distinct blocks only grow; one that ended at this instant is the last one
  // recorded. Rounded up, with a margin for the product's round-off (0.1 x 30 is 3, not 4).
  loading_events_.switched(c, s, blocks);
  const auto& done = loading_events_.events();
  const int blocks_now = std::max(loading_events_.under_way().blocks, done.empty() ? 0 : done.back().blocks);
  const double need = std::ceil(cfg_.peak_event_fraction * c.n_contact * (1.0 - 1e-12));
  large_event_ = blocks_now >= need;
}

bool FrictionObserver::tests_drop() const {
  using R = ExtractionRules::PeakRule;
  return cfg_.peak_rule == R::Drop || cfg_.peak_rule == R::SlidOrDrop || cfg_.peak_rule == R::SlidOrRelativeDrop;
}

bool FrictionObserver::falls(double mu, double running_max) const {
  return cfg_.peak_rule == ExtractionRules::PeakRule::SlidOrRelativeDrop
             ? mu < (1.0 - cfg_.peak_drop_fraction) * running_max
             : mu < running_max - cfg_.peak_drop;
}

namespace {
bool every_contact_block_slid(const Chain& c, const State& s) {
  return !s.slipped_once.empty() && s.n_slipped_once >= c.n_contact;
}
}  // namespace

bool FrictionObserver::dynamic_begins(const Chain& c, const State& s) const {
  return cfg_.peak_rule == ExtractionRules::PeakRule::Drop || every_contact_block_slid(c, s);
}

bool FrictionObserver::ends_at_next_sample(const Chain& c, const State& s) const {
  return (tests_all_slid() && every_contact_block_slid(c, s)) || large_event_;
}

long FrictionObserver::sample_affine(const Chain& c, const State& s, long k0, double dt, long n,
                                     const AffineForces& f) {
  // A stretch feeds the statistics, the series and the stress snapshots alike (record_stretch),
  // so keeping mu(t) or taking snapshots never changes mu_s or mu_d (served one by one instead,
  // they would differ in the last bits: FrictionObserver.KeepingTheSeriesChangesNoStatistic*).
  if (n <= 0 || contact_runs_.empty()) return 0;
  auto t_of = [&](long k) { return static_cast<double>(k) * dt; };
  const double t_first = t_of(k0);
  const double *a = f.a, *b = f.b;
  // The stretch ends before the first sample at which some block's force changes sign. The
  // totals over the contact blocks are kept from stretch to stretch where the forces change only
  // at their own block's switches (the same signs, summed in the tree's order), or are summed
  // here in block order.
  const AffineTotals sum = f.per_block ? switched_totals_.at(c, s, a, b, t_first)
                                       : block_order_totals(contact_runs_, s, a, b, t_first);
  const double A = sum.A, B = sum.B, As = sum.As, Bs = sum.Bs, t_sign = sum.t_sign;
  const int n_sliding = sum.n_sliding;
  long m = std::min(n, kMaxAffineSamples);
  while (m > 0 && t_of(k0 + m - 1) >= t_sign) --m;  // usually none: forces rarely change sign
  if (m <= 0) return 0;
  const double inv = 1.0 / cfg_.F_load;
  auto mu = [&](long k) { return (A + B * t_of(k)) * inv; };
  auto mu_signed = [&](long k) { return (As + Bs * t_of(k)) * inv; };
  long taken = m;
  if (!slipped_) {
    // Nothing slips inside the stretch, so neither every block having slid nor a slip event can
    // end loading here (if one already does, the first sample must end it: served by sample()).
    if (ends_at_next_sample(c, s)) return 0;
    if (tests_drop()) {
      // A drop rule: loading ends at the first sample that falls from the running max; the max
      // of an affine sequence is at one end, so the running max is monotone: stop before any
      // sample that falls (that one goes to sample()).
      double rmax = running_max_;
      for (taken = 0; taken < m; ++taken) {
        const double x = mu(k0 + taken);
        if (falls(x, rmax)) break;
        rmax = std::max(rmax, x);
      }
      if (taken == 0) return 0;
    }
    // Running maximum over the samples taken: at one end of the stretch (first one on a tie).
    const double first = mu(k0), last = mu(k0 + taken - 1);
    if (first > running_max_) running_max_ = first, t_max_ = t_of(k0);
    if (last > running_max_) running_max_ = last, t_max_ = t_of(k0 + taken - 1);
    running_max_signed_ = std::max({running_max_signed_, mu_signed(k0), mu_signed(k0 + taken - 1)});
  } else if (!dynamic_) {
    // Between the end of loading and the whole surface's slip: no window sample here, unless
    // every block has slid already (then the first sample opens the dynamic phase: sample()).
    if (dynamic_begins(c, s)) return 0;
  } else {
    // Dynamic phase: the window sums over the samples at or after its start.
    const double t_win = t_dynamic_ + cfg_.mu_d_skip_s;
    long j0 = 0;
    while (j0 < m && t_of(k0 + j0) < t_win) ++j0;
    const long cnt = m - j0;
    if (cnt > 0) {
      // sum over k of t_k = dt * (sum of k), exact in integers up to 2^53.
      const long kk0 = k0 + j0, kk1 = k0 + m - 1;
      const double sum_k = 0.5 * static_cast<double>(kk0 + kk1) * static_cast<double>(cnt);
      sum_mu_ += (A * cnt + B * dt * sum_k) * inv;
      sum_mu_signed_ += (As * cnt + Bs * dt * sum_k) * inv;
      n_window_ += cnt;
    }
  }
  // The series and the stress snapshots of the samples taken, from the same affine forces.
  const long k_end = k0 + taken;
  if (cfg_.keep_series)
    for (long k = k0; k < k_end; ++k) series_.push_back({t_of(k), mu(k), mu_signed(k), n_sliding});
  if (stress_due(t_of(k_end - 1)))  // a snapshot falls in the stretch (rare: no per-sample test)
    for (long k = k0; k < k_end; ++k)
      while (stress_due(t_of(k)))
        add_snapshot(c, t_of(k), [&](int i) { return c.contact[i] ? a[i] + b[i] * t_of(k) : 0.0; });
  last_t_ = t_of(k_end - 1);
  if (cfg_.progress_ns) cfg_.progress_ns->store(static_cast<std::int64_t>(last_t_ * 1e9), std::memory_order_relaxed);
  return taken;
}

long FrictionObserver::sample_sums(const Chain& c, const State& s_stretch, long k0, double dt, long n,
                                   SampleStretch& stretch) {
  if (n <= 0 || contact_runs_.empty() || wants_stop()) return 0;
  if (!slipped_) return loading_stretch(c, s_stretch, k0, dt, n, stretch);
  auto t_of = [&](long k) { return static_cast<double>(k) * dt; };
  if (!dynamic_ && dynamic_begins(c, s_stretch)) return 0;  // the first sample opens it: sample()
  const double t_win = dynamic_ ? t_dynamic_ + cfg_.mu_d_skip_s : std::numeric_limits<double>::infinity();
  const bool before = t_of(k0 + n - 1) < t_win, inside = t_of(k0) >= t_win;
  if (!before && !inside) return 0;
  RingingSums& sums = ringing(stretch.forces());
  if (inside) {
    double sum_abs, sum_signed;
    if (!sums.window(k0, dt, n, sum_abs, sum_signed)) return 0;
    sum_mu_ += sum_abs / cfg_.F_load;
    sum_mu_signed_ += sum_signed / cfg_.F_load;
    n_window_ += n;
  }
  const long k_end = k0 + n;
  if (cfg_.keep_series || stress_due(t_of(k_end - 1)))
    for (long k = k0; k < k_end; ++k) {
      const State& s = stretch.at(k);
      // The values sample_ringing() would record for the series (nothing slides in such a block).
      if (cfg_.keep_series) {
        double sum_abs, sum_signed;
        sums.at(s.t, sum_abs, sum_signed);
        series_.push_back({s.t, sum_abs / cfg_.F_load, sum_signed / cfg_.F_load, 0});
      }
      while (stress_due(s.t)) add_snapshot(c, s.t, [&](int i) { return friction_force(c, s, i); });
    }
  last_t_ = t_of(k_end - 1);
  if (cfg_.progress_ns) cfg_.progress_ns->store(static_cast<std::int64_t>(last_t_ * 1e9), std::memory_order_relaxed);
  return n;
}

// Loading: mu_s is the largest sample and t_peak the first one that reaches it, so a sample
// whose upper bound is below the largest lower bound in the stretch (or below the running
// maximum) can change neither; the others are looked at in order and recorded as record() would,
// which gives the mu_s, t_peak and signed peak of one-by-one service bit for bit. Not with a
// series or a snapshot (they read every sample), under a drop rule where a sample might fall,
// nor once the rule's end holds (the first sample ends loading).
long FrictionObserver::loading_stretch(const Chain& c, const State& s, long k0, double dt, long n,
                                       SampleStretch& stretch) {
  auto t_of = [&](long k) { return static_cast<double>(k) * dt; };
  if (cfg_.keep_series || stress_due(t_of(k0 + n - 1))) return 0;
  if (ends_at_next_sample(c, s)) return 0;
  RingingSums& sums = ringing(stretch.forces());
  RingingSums::Envelope e{};
  if (!sums.envelope(k0, dt, n, e)) return 0;
  const double F = cfg_.F_load;
  // A drop rule ends loading at the first sample that falls from the running maximum, which is
  // at most the larger of today's and the stretch's upper bound: if no sample's lower bound is
  // below what that maximum would let fall (with a margin for the division by F), none ends
  // loading here, and the stretch is taken as under the all-slipped rule. Otherwise it is left to
  // sample(), one by one.
  if (tests_drop()) {
    const double highest = std::max(running_max_, (std::max(e.abs_first, e.abs_last) + e.reach) / F);
    const double lowest = (std::min(e.abs_first, e.abs_last) - e.reach) / F;
    const double margin = 1e-9 * std::max(1.0, std::fabs(highest));
    if (falls(lowest - margin, highest)) return 0;
  }
  auto line = [n](double first, double last, long j) {
    return n == 1 ? first : first + (last - first) * (static_cast<double>(j) / static_cast<double>(n - 1));
  };
  const double floor_abs = std::max(std::max(e.abs_first, e.abs_last) - e.reach, running_max_ * F);
  const double floor_signed = std::max(std::max(e.signed_first, e.signed_last) - e.reach, running_max_signed_ * F);
  for (long j = 0; j < n; ++j) {
    if (line(e.abs_first, e.abs_last, j) + e.reach < floor_abs &&
        line(e.signed_first, e.signed_last, j) + e.reach < floor_signed)
      continue;
    const State& x = stretch.at(k0 + j);
    double sum_abs, sum_signed;
    sums.at(x.t, sum_abs, sum_signed);
    const double mu = sum_abs / F;
    if (mu > running_max_) running_max_ = mu, t_max_ = x.t;
    running_max_signed_ = std::max(running_max_signed_, sum_signed / F);
  }
  last_t_ = t_of(k0 + n - 1);
  if (cfg_.progress_ns) cfg_.progress_ns->store(static_cast<std::int64_t>(last_t_ * 1e9), std::memory_order_relaxed);
  return n;
}

bool FrictionObserver::stress_due(double t) const {
  return next_stress_ < cfg_.stress_times_s.size() && t >= cfg_.stress_times_s[next_stress_];
}

void FrictionObserver::add_snapshot(const Chain& c, double t, const std::function<double(int)>& friction) {
  StressSnapshot snap{t, std::vector<double>(c.N), std::vector<double>(c.N)};
  for (int i = 0; i < c.N; ++i) {
    const double f = friction(i);
    snap.f_over_Fn[i] = c.contact[i] ? f / c.F_n : 0.0;
    snap.sigma_over_P[i] = f / cfg_.block_area_P;
  }
  stress_.push_back(std::move(snap));
  ++next_stress_;
}

bool FrictionObserver::wants_stop() const {
  if (cfg_.interrupt && cfg_.interrupt->load(std::memory_order_relaxed)) return true;
  return cfg_.stop_after_mu_s && slipped_ && next_stress_ >= cfg_.stress_times_s.size();
}

}  // namespace sb
