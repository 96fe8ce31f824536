#pragma once
// Locates stick/slip events inside a trial Dormand-Prince step from its continuous extension.
//
// Event functions, positive while nothing happens:
//   sliding block:  g = dir * v           (stops when the velocity reaches zero)
//   stuck block:    g = f_static - |F|    (starts to slide when the force reaches the threshold)
// Only the watched blocks of the active set are searched: sliding blocks and stuck blocks next
// to a stepped run (every other stuck block has an affine force and a closed-form crossing, see
// active_set.hpp). Each g is sampled at the middle and the end of the step and the first sign
// change is refined to round-off in t (first_root.hpp).
#include <vector>

#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/step/dopri5.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class EventSearch {
 public:
  explicit EventSearch(int N) : theta_(N), v_half_(N) { hits_.reserve(N); }

  // Earliest event fraction theta in [0, 1] of the step [s.t, s.t + h], or a value > 1 if none.
  // hits() then lists the blocks whose events lie within `window` (fraction) of it, in order.
  double locate(const Chain& c, const State& s, const Dopri5& dp, double h, const ActiveSet& active,
                double window = 1e-12);
  const std::vector<int>& hits() const { return hits_; }

 private:
  std::vector<double> theta_;
  std::vector<double> v_half_;  // the stepped blocks' v at the step's middle (every sliding block's first test)
  std::vector<int> hits_;
};

}  // namespace sb::event_detail
