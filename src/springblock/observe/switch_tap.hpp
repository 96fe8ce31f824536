#pragma once
// A second observer on a run that reads only its switches (slip events). Every call goes to the
// first observer exactly as if it were alone, so the integrator makes the same choices and the
// first observer's results are the same to the last bit; Observer::switched goes to both. The run
// is the first observer's: it stops when that one wants it to.
#include "springblock/observe/observer.hpp"

namespace sb {

class SwitchTap final : public Observer {
 public:
  SwitchTap(Observer& main, Observer& switches) : main_(main), switches_(switches) {}

  void switched(const Chain& c, const State& s, SwitchedBlocks blocks) override {
    main_.switched(c, s, blocks);
    switches_.switched(c, s, blocks);
  }
  void sample(const Chain& c, const State& s) override { main_.sample(c, s); }
  void sample_ringing(const Chain& c, const State& s, RingingForces& f) override { main_.sample_ringing(c, s, f); }
  bool takes_active_forces() const override { return main_.takes_active_forces(); }
  void sample_active(const Chain& c, const State& s, const ActiveForces& f) override { main_.sample_active(c, s, f); }
  void follow_forces(const Chain& c, const State& s, const ActiveForces& f) override { main_.follow_forces(c, s, f); }
  bool wants_stop() const override { return main_.wants_stop(); }
  bool reads_groove_interiors() const override { return main_.reads_groove_interiors(); }
  bool reads_only_friction() const override { return main_.reads_only_friction(); }
  bool needs_positions_at(double t) const override { return main_.needs_positions_at(t); }
  long sample_affine(const Chain& c, const State& s, long k0, double dt, long n, const AffineForces& f) override {
    return main_.sample_affine(c, s, k0, dt, n, f);
  }
  long sample_sums(const Chain& c, const State& s, long k0, double dt, long n, SampleStretch& stretch) override {
    return main_.sample_sums(c, s, k0, dt, n, stretch);
  }

 private:
  Observer& main_;
  Observer& switches_;
};

}  // namespace sb
