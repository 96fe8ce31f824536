#pragma once
// An observer that hands every sample to a friction observer, for tests that watch or change one
// kind of call: blocks of quiet-phase samples offered as sums (sample_sums) it declines, so they
// come one by one; a test overrides whatever else it watches.
#include "springblock/integrate/integrator.hpp"
#include "springblock/observe/friction_observer.hpp"
#include "springblock/scene.hpp"

namespace sbtest {

class Forwarding : public sb::Observer {
 public:
  explicit Forwarding(sb::FrictionObserver& inner) : inner_(inner) {}
  void sample(const sb::Chain& c, const sb::State& s) override { inner_.sample(c, s); }
  void sample_ringing(const sb::Chain& c, const sb::State& s, sb::RingingForces& f) override {
    inner_.sample_ringing(c, s, f);
  }
  long sample_affine(const sb::Chain& c, const sb::State& s, long k0, double dt, long n,
                     const sb::AffineForces& f) override {
    return inner_.sample_affine(c, s, k0, dt, n, f);
  }
  void switched(const sb::Chain& c, const sb::State& s, sb::SwitchedBlocks blocks) override {
    inner_.switched(c, s, blocks);
  }
  bool wants_stop() const override { return inner_.wants_stop(); }
  bool reads_groove_interiors() const override { return inner_.reads_groove_interiors(); }
  bool reads_only_friction() const override { return inner_.reads_only_friction(); }
  bool needs_positions_at(double t) const override { return inner_.needs_positions_at(t); }

 protected:
  sb::FrictionObserver& inner_;
};

// The plain reference of the faster routes: it takes no affine stretch, no quiet-phase sums and
// not the integrator's known forces, and needs every position, so the integrator serves each
// sample one by one from the state with its positions written.
class PerSample : public Forwarding {
 public:
  using Forwarding::Forwarding;
  void sample_ringing(const sb::Chain& c, const sb::State& s, sb::RingingForces& f) override {
    sb::Observer::sample_ringing(c, s, f);
  }
  long sample_affine(const sb::Chain&, const sb::State&, long, double, long, const sb::AffineForces&) override {
    return 0;
  }
  bool needs_positions_at(double) const override { return true; }
};

// A friction observer's configuration for chain c that keeps the mu(t) series.
inline sb::FrictionObserverConfig series_config(const sb::Chain& c) {
  sb::FrictionObserverConfig cfg;
  cfg.F_load = c.F_load;
  cfg.keep_series = true;
  return cfg;
}

// Scene sc on chain c from rest to its end, observed by obs: the final state.
inline sb::State run_from_rest(const sb::Scene& sc, const sb::Chain& c, sb::Observer& obs) {
  sb::State s = sb::State::at_rest(c);
  sb::make_integrator(sc.run)->run(c, s, sc.duration(), sc.run.sample_dt_s, obs);
  return s;
}

}  // namespace sbtest
