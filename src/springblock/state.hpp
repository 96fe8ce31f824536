#pragma once
// Dynamic state of the chain, structure-of-arrays so the kernels vectorise.
#include <cstdint>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/work_profile.hpp"

namespace sb {

// Contact phase of a block. Free: in a groove (no friction, always moving).
// Stuck: held by static friction, velocity exactly zero. Sliding: kinetic friction
// opposes the sliding direction `dir` (+1 forward with the slider, -1 backward).
struct State {
  double t = 0;
  std::vector<double> u;         // displacement from the rest position [m]
  std::vector<double> v;         // velocity [m/s]
  std::vector<std::int8_t> dir;  // 0 = stuck or free, +1/-1 = sliding direction
  std::int64_t steps = 0;        // accepted steps
  std::int64_t rhs_evals = 0;    // force evaluations of the whole chain (work measure)
  std::int64_t switches = 0;     // stick<->slip transitions
  std::vector<std::uint8_t> slipped_once;  // 1 once a contact block has started to slide
  int n_slipped_once = 0;                  // how many contact blocks have slid at least once
  WorkProfile work;                        // where the run's work went (work_profile.hpp)

  // Called by integrators whenever block i starts to slide.
  void mark_slip(int i) {
    ++work.slip_starts;
    if (!slipped_once[i]) {
      slipped_once[i] = 1;
      ++n_slipped_once;
    }
  }

  // Initial condition (a choice the paper leaves open): every block at rest at its rest
  // position, the slider spring unstretched, all contact blocks stuck.
  static State at_rest(const Chain& c) {
    State s;
    s.u.assign(c.N, 0.0);
    s.v.assign(c.N, 0.0);
    s.dir.assign(c.N, 0);
    s.slipped_once.assign(c.N, 0);
    return s;
  }
  bool stuck(const Chain& c, int i) const { return c.contact[i] && dir[i] == 0; }
  bool sliding(int i) const { return dir[i] != 0; }
};

// Friction force on block i (positive opposes the forward pull of the slider): the static
// reaction -(-F) for a stuck block, the kinetic force for a sliding one, 0 in a groove.
inline double friction_force(const Chain& c, const State& s, int i) {
  if (!c.contact[i]) return 0.0;
  if (s.dir[i] == 0) return c.driving_force(i, s.u.data(), s.v.data(), s.t);
  return s.dir[i] * c.f_kinetic[i];
}

}  // namespace sb
