#pragma once
// One trajectory, several observers ("views").
//
// Scenes that differ only in how mu_s and mu_d are read off mu(t) (the extraction rules) or in
// how long they run see the same trajectory: no integrator's path up to a time t depends on
// where the run will end (the end only clips the last step), so a shorter run is a prefix of a
// longer one. The ensemble therefore simulates such a group once, to its longest duration, and
// hands every sample to each view whose own run would have taken it.
//
// Stretches of affine samples (Observer::sample_affine) are the delicate part: an observer sums
// a stretch in closed form, and how a stretch is cut into prefixes changes the rounding of those
// sums. FanOut offers each view exactly the stretches a run of its own would have offered it
// (from the view's next unseen sample to the end of the stretch, or to the view's end: a run's
// affine stretches stop short of a sample exactly at its end, which it takes through sample()),
// and reports to the integrator the shortest prefix any view took, so views that took more skip
// the samples they already have. A view's result is then the same, to the last bit, as its own
// run gives (tests/unit/test_shared_trajectory.cpp, ends on sample times included).
#include <cstdint>
#include <functional>
#include <vector>

#include "springblock/observe/observer.hpp"

namespace sb {

class FanOut final : public Observer {
 public:
  // Whether a run of the integrator in use, ending at t_end, takes a sample at time t.
  using Within = std::function<bool(double t, double t_end)>;

  struct View {
    Observer* obs = nullptr;
    double t_end = 0;
    // Work counters of the shared run at the view's last sample (a run of its own would report
    // these plus the steps between that sample and its end).
    std::int64_t steps = 0, rhs_evals = 0, switches = 0;
    long long next_k = 0;  // index of the first sample the view has not seen yet
  };

  FanOut(std::vector<View> views, double sample_dt, Within within);

  void sample(const Chain& chain, const State& state) override;
  void sample_ringing(const Chain& chain, const State& state, RingingForces& f) override;
  // A switch goes to each view whose own run would have made it: one not stopped, at a time
  // within its end (the runs' switches up to there are the shared run's).
  void switched(const Chain& chain, const State& state, SwitchedBlocks blocks) override;
  bool takes_active_forces() const override;
  void sample_active(const Chain& chain, const State& state, const ActiveForces& f) override;
  void follow_forces(const Chain& chain, const State& state, const ActiveForces& f) override;
  long sample_affine(const Chain& chain, const State& state, long k0, double dt, long n,
                     const AffineForces& f) override;
  // A view is offered the block only as a run of its own would offer it: whole, and only if it
  // ends before the view's end; views that take it skip its samples, which the integrator then
  // serves one by one to the others if any declined.
  long sample_sums(const Chain& chain, const State& state, long k0, double dt, long n, SampleStretch& stretch) override;
  // The run stops when every view wants it to; a view that wants to stop gets no more samples.
  bool wants_stop() const override;
  bool reads_groove_interiors() const override;
  bool reads_only_friction() const override;
  // Positions are needed where a view that takes the sample at t needs them.
  bool needs_positions_at(double t) const override;

  const std::vector<View>& views() const { return views_; }

 private:
  long long index_of(double t) const;
  static long long end_index(const View& v, long long k0, long long k_stop, double dt);
  void record(View& v, const State& s);
  // The sample at s.t to every view whose own run would take it (take(observer) hands it over).
  template <class Take>
  void deal(const State& s, Take take);

  std::vector<View> views_;
  double sample_dt_;
  Within within_;
};

}  // namespace sb
