#pragma once
// Reference for the benchmarks: the scheme of integrate/rk4.cpp written the way a first
// implementation would be, so the kernel's speed-up has a baseline to be measured against.
// Same rules (phase frozen over a step; a sliding block whose velocity reaches or crosses zero
// stops; a stuck block slips when |net non-friction force| > f_static), but: blocks as an array
// of structs, a generic right-hand side that returns a freshly allocated derivative of the whole
// state y = (u, v) at each stage, a branch on the phase of every block inside the force loop,
// and no quiet-phase jump. Not for production use.
#include <cstdint>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::bench {

struct NaiveBlock {
  double u = 0, v = 0;
  std::int8_t dir = 0;  // 0 = stuck or free, +1/-1 = sliding direction
  bool contact = true;
  double f_static = 0, f_kinetic = 0;
};

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
