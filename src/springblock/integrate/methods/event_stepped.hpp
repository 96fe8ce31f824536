#pragma once
// The event method's Dormand-Prince evolve step (the runs longer than the exact stepper takes,
// and every run under --stepper dopri5), in the layers of GSL's odeiv2: one trial step of the
// stepped runs (step/dopri5.hpp), its step-size control (step_control.hpp), the search of its
// continuous extension for events (events/event_search.hpp). A trial step is shortened to land
// exactly on the next sample, the next closed-form event or the end of the run. After it is
// accepted its continuous extension is searched for events; if one lies inside, the step is
// redone to exactly the earliest event time, every block whose event lies within the search
// window is switched at that instant, and stage 1 is recomputed (the right-hand side has jumped).
#include <cstdint>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/events/event_search.hpp"
#include "springblock/integrate/methods/event_core.hpp"
#include "springblock/integrate/methods/step_control.hpp"
#include "springblock/integrate/step/dopri5.hpp"

namespace sb::event_detail {

class SteppedEvolve {
 public:
  explicit SteppedEvolve(EventCore& core) : core_(core), control_(core.c, core.opt.tol), dp_(core.c.N), search_(core.c.N) {}
  // One trial step of the stepped runs, to its end or to the first event inside it (Coupled:
  // internal springs; Damped: viscous damping select the kernel).
  template <bool Coupled, bool Damped>
  void step();

 private:
  // One trial of size h from s.t; returns its error (units of the tolerance).
  template <bool Coupled, bool Damped>
  double attempt(const std::vector<BlockRange>& spans, double h);
  // The stepped blocks take the end of the last attempted step.
  void take_step_end(const std::vector<BlockRange>& spans);

  EventCore& core_;
  StepControl control_;
  Dopri5 dp_;
  EventSearch search_;
  std::int64_t stage1_at_ = -1;  // the epoch stage 1 (and the stepped runs' frozen borders) was set in
};

}  // namespace sb::event_detail
