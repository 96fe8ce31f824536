#pragma once
// A range of consecutive blocks [lo, hi) of the chain. The event method's layers pass these
// around (the runs a stepper integrates, a run's blocks); a separate header so that the stepper
// does not depend on the active set that chooses them.
namespace sb::event_detail {

struct BlockRange {
  int lo, hi;  // blocks lo .. hi-1
  int size() const { return hi - lo; }
};

}  // namespace sb::event_detail
