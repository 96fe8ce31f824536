#pragma once
// The paper's method: classical fourth-order Runge-Kutta with a fixed step h.
//
// Stick/slip rules (the paper states the friction law but not how it meets the stepper):
//  * The contact phase of every block is frozen for the whole step (all four stages).
//  * A stuck block has v = 0 and a = 0; it stays exactly where it is.
//  * After each step, a sliding block whose velocity reached or crossed zero is stopped
//    (v := 0) and becomes stuck; then every stuck block whose net non-friction force exceeds
//    mu_s,i F_n in modulus starts to slide in the direction of that force.
//  So switching times are resolved to one step, and the method is first order in them.
//
// When every block is in contact and stuck nothing moves, and the slider spring loads each
// block linearly in time; the stepper then jumps straight to the step before the next
// threshold crossing. This is exact for the scheme (RK4 of a motionless chain is the identity)
// and is the only shortcut taken.
#include <cmath>

#include "springblock/integrate/integrator.hpp"

namespace sb {

class Rk4 final : public Integrator {
 public:
  explicit Rk4(double h) : h_(h) {}
  // The end-of-step switch screen (rk4.cpp) skips the exact stick/slip rules on steps where no
  // block can switch. Off, the rules run after every step: the tests' reference (same result).
  void set_switch_screen(bool on) { screen_ = on; }
  void run(const Chain& chain, State& state, double t_end, double sample_dt, Observer& obs) override;
  std::string name() const override { return "rk4"; }
  // Steps are counted in integers: a run to t_end takes llround(t_end / h) of them.
  bool samples_within(double t, double t_end) const override {
    return std::llround(t / h_) <= std::llround(t_end / h_);
  }

 private:
  double h_;
  bool screen_ = true;
};

}  // namespace sb
