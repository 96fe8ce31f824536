#pragma once
// mu(t), the sliding count, the first-peak mu_s, the dynamic-phase mu_d and stress snapshots.
//
// mu(t) = sum_i |f_i| / F_load, the modulus of each block's friction force summed over the
// chain. The paper's single-block theory averages the modulus of the static force (its eq. 8),
// and its K_int = 0 simulations follow that theory; with signed forces the K_int = 0 average
// would equal mu_d exactly in both regimes. The signed sum is recorded too (mu_signed).
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include <memory>

#include "springblock/observe/observer.hpp"
#include "springblock/observe/ringing_sums.hpp"
#include "springblock/observe/slip_events.hpp"
#include "springblock/run_control.hpp"

namespace sb {

struct Sample {
  double t, mu, mu_signed;
  int n_sliding;
};

struct StressSnapshot {
  double t;
  std::vector<double> f_over_Fn;        // friction on block / its own normal force (0 in grooves)
  std::vector<double> sigma_over_P;     // friction on block / (l_x l_y) / P
};

struct FrictionObserverConfig {
  double F_load = 1;
  // The scene's defaults (ExtractionRules); the thresholds are read only by their rules.
  ExtractionRules::PeakRule peak_rule = ExtractionRules{}.peak_rule;
  double peak_drop = ExtractionRules{}.peak_drop;                    // Drop, SlidOrDrop
  double peak_drop_fraction = ExtractionRules{}.peak_drop_fraction;  // SlidOrRelativeDrop
  double peak_event_fraction = ExtractionRules{}.peak_event_fraction;  // SlidOrEvent
  double mu_d_skip_s = 0;         // start of the mu_d window after the first slip
  double block_area_P = 1;        // l_x l_y P, for sigma/P
  bool keep_series = false;
  bool stop_after_mu_s = false;
  std::vector<double> stress_times_s;
  const std::atomic<bool>* interrupt = nullptr;
  std::atomic<std::int64_t>* progress_ns = nullptr;  // simulated time done, for ETA
};

class FrictionObserver final : public Observer {
 public:
  explicit FrictionObserver(FrictionObserverConfig cfg) : cfg_(std::move(cfg)) {}
  void sample(const Chain& chain, const State& state) override;
  // mu(t) from the forces the integrator knows (RingingSums::at), without the positions.
  void sample_ringing(const Chain& chain, const State& state, RingingForces& f) override;
  // mu(t) and mu_signed(t) are affine across such a stretch (up to the first sign change of a
  // block's force): the running maximum, the end of loading and the mu_d window sums are then
  // closed-form sums over the samples, O(1) per sample instead of O(contact blocks).
  long sample_affine(const Chain& chain, const State& state, long k0, double dt, long n,
                     const AffineForces& f) override;
  // The most samples one sample_affine takes. Its scans are linear in them, and the integrator
  // checks for an interrupt and the progress moves only between calls: with a small sample_dt a
  // stretch can hold 10^12 samples. 2^24 is at most ~11 ms of scanning (a run at sample_dt
  // 1e-10 s took 1.6e10 samples as stretches in 10.5 s, everything included), and above the
  // samples of any whole run the reproduction makes (at most 1.44e7), whose sums it leaves as
  // they are.
  static constexpr long kMaxAffineSamples = 1L << 24;
  // The blocks whose forces changed, for the totals of per-block stretches.
  void switched(const Chain& chain, const State& state, SwitchedBlocks blocks) override;
  // After loading, mu_s is fixed and only the mu_d window's sums are still to come: a block of
  // samples before the window is taken without a value, one inside it as its sums, one across
  // the window's start is left to sample(). The series and snapshots of a block taken come from
  // SampleStretch::at, and do not change the sums.
  // Before it (loading), a stretch is taken from its bounds (RingingSums::envelope) where they
  // show which samples may hold the peak: only those are looked at (loading_stretch).
  long sample_sums(const Chain& chain, const State& state, long k0, double dt, long n,
                   SampleStretch& stretch) override;
  // mu(t) of an active phase from the forces the integrator knows: the affine and sliding ones
  // summed in a tree kept from sample to sample (active_), the live ones read from the state.
  bool takes_active_forces() const override { return true; }
  void sample_active(const Chain& chain, const State& state, const ActiveForces& f) override;
  void follow_forces(const Chain& chain, const State& state, const ActiveForces& f) override;
  bool wants_stop() const override;
  // mu(t) and stress snapshots need only contact blocks' forces (their own and their direct
  // neighbours' positions); groove interiors are never read.
  bool reads_groove_interiors() const override { return false; }
  bool reads_only_friction() const override { return true; }
  // mu(t) comes from the forces of a sample_ringing; positions only for a snapshot.
  bool needs_positions_at(double t) const override { return stress_due(t); }

  // Results.
  bool slipped() const { return slipped_; }
  double mu_s() const { return slipped_ ? running_max_ : std::numeric_limits<double>::quiet_NaN(); }
  double max_mu() const { return running_max_; }
  // The same peak of the signed friction sum (the other reading of the paper's "sum of all the
  // friction forces", paper/choices.md): recorded beside mu_s to measure what the choice is worth.
  double mu_s_signed() const { return slipped_ ? running_max_signed_ : std::numeric_limits<double>::quiet_NaN(); }
  double t_peak() const { return t_max_; }
  double t_slip() const { return t_slip_; }
  double mu_d() const { return n_window_ ? sum_mu_ / n_window_ : std::numeric_limits<double>::quiet_NaN(); }
  double mu_d_signed() const {
    return n_window_ ? sum_mu_signed_ / n_window_ : std::numeric_limits<double>::quiet_NaN();
  }
  std::int64_t window_samples() const { return n_window_; }
  double last_t() const { return last_t_; }
  const std::vector<Sample>& series() const { return series_; }
  const std::vector<StressSnapshot>& stress() const { return stress_; }

 private:
  long loading_stretch(const Chain& c, const State& s, long k0, double dt, long n, SampleStretch& stretch);
  // One sample's mu(t), mu_signed(t) and sliding count into the peak, the window and the series.
  void record(const Chain& c, const State& s, double mu, double mu_signed, int n_sliding);
  // Which of the loading phase's end conditions the rule tests (ExtractionRules::PeakRule).
  bool tests_all_slid() const { return cfg_.peak_rule != ExtractionRules::PeakRule::Drop; }
  bool tests_drop() const;
  // A sample of mu below this threshold ends loading under a drop rule (the running max given).
  bool falls(double mu, double running_max) const;
  // Whether the next sample ends loading whatever its mu: every contact block has slid (for the
  // rules that test it) or a large enough slip event has happened (SlidOrEvent). Neither changes
  // between switches.
  bool ends_at_next_sample(const Chain& c, const State& s) const;
  // The mu_d window is measured from the whole surface's first slip (every contact block has
  // slid once), whichever reading ends loading for mu_s, so that mu_d does not depend on how
  // mu_s is read; under the pure drop rule, from the end of its loading phase.
  bool dynamic_begins(const Chain& c, const State& s) const;
  // The sums of the forces f describe, kept for the next phase of the same run.
  RingingSums& ringing(RingingForces& f);
  // A stress snapshot is due at a sample at time t (the first sample at or after its time).
  bool stress_due(double t) const;
  // Record one at time t from each block's friction force.
  void add_snapshot(const Chain& c, double t, const std::function<double(int)>& friction);

  FrictionObserverConfig cfg_;
  double running_max_ = -1, t_max_ = 0, t_slip_ = std::numeric_limits<double>::quiet_NaN();
  double running_max_signed_ = -std::numeric_limits<double>::infinity();
  bool slipped_ = false;
  bool dynamic_ = false;  // the dynamic phase, whose window gives mu_d, has begun at t_dynamic_
  double t_dynamic_ = std::numeric_limits<double>::quiet_NaN();
  double sum_mu_ = 0, sum_mu_signed_ = 0;
  std::int64_t n_window_ = 0;
  double last_t_ = 0;
  std::size_t next_stress_ = 0;
  std::vector<Sample> series_;
  std::vector<StressSnapshot> stress_;
  // The contact blocks as runs [lo, hi) of consecutive blocks, built on the first sample.
  std::vector<std::pair<int, int>> contact_runs_;
  std::vector<double> f_contact_;  // per block: its friction force at the current sample (sample())
  SwitchedTotals switched_totals_;  // a per-block run's stretch totals (AffineForces::per_block)
  std::unique_ptr<RingingSums> ringing_;  // the sums of the integrator's exact forces (sample_ringing)
  std::unique_ptr<AffineForceTree> active_;  // the known forces of active phases (sample_active)
  // SlidOrEvent: the slip events of the loading phase, and whether one has moved enough blocks.
  SlipEventObserver loading_events_;
  bool large_event_ = false;
};

}  // namespace sb
