#pragma once
// The paper's method as the benchmarks' yardstick: classical fourth-order Runge-Kutta at a fixed
// step h, every block at every stage of every step (a stuck block's slope is set to zero there,
// as the rules below say, not skipped), written plainly and well, so that a speed-up measured
// against it is the method's and not the price of a careless implementation.
// The state and the stage buffers are contiguous arrays allocated once per run; nothing is
// allocated in the step loop. The rules are sb::Rk4's (integrate/methods/rk4.cpp): the phase of
// every block is frozen over a step; at each step end a sliding block whose velocity reached or
// crossed zero stops, and a stuck block slips when |net non-friction force| > f_static. What
// sb::Rk4 adds and this leaves out, being the project's engineering rather than the paper's
// method: the quiet-phase jump, the compile-time effect specialisations, a branch-free force
// kernel with AVX2 clones, and a screen that skips the switching rules on steps where no block
// can switch.
// tests/unit/test_naive_rk4.cpp holds it to the same doubles as a version with an array of
// structs that allocates at every stage; bench_vs_paper and bench_rk4_kernel check it against
// sb::Rk4 to round-off before timing it.
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::bench {

class NaiveRk4 {
 public:
  explicit NaiveRk4(double h) : h_(h) {}
  // Advances `s` to t_end with every step taken (no observer: the benchmarks need none).
  // Updates s.steps, s.rhs_evals and s.switches like sb::Rk4.
  void run(const Chain& c, State& s, double t_end) const;

 private:
  double h_;
};

}  // namespace sb::bench
