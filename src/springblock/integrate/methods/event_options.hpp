#pragma once
// What the event method is told by its caller (EventDriven's setters) and by its observer, asked
// once per run; and the exact stepper's check for the tests.
#include <vector>

#include "springblock/run_control.hpp"

namespace sb {

// A check for the tests (EventDriven::set_clock_audit): each group of the exact stepper that keeps
// its clock and screen across a switch has its screen compared with the one the classification
// would build now (SpanScreen::current; a mismatch throws std::logic_error), and the groups kept,
// and those whose runs were kept but whose surroundings the classification renewed, are counted.
struct ClockAudit {
  long kept = 0;
  long renewed = 0;
};

}  // namespace sb

namespace sb::event_detail {

struct EventOptions {
  double tol;         // the integration tolerance (step_control.hpp)
  bool fast_forward;  // exact quiet phases, settled and modal runs (off: the tests' reference)
  int modal_max_run = kDefaultModalMaxRun;        // see EventDriven::set_modal_max_run
  int modal_max_groove = kDefaultModalMaxGroove;  // see EventDriven::set_modal_max_groove
  // The stepped runs move by their modes (span_modes.hpp), not Dormand-Prince, while no stepped
  // run is longer than exact_max_run.
  bool exact_stepper = true;
  int exact_max_run = kDefaultExactMaxRun;
  // Diagnostics: the times of the instants with a switch, and the exact stepper's audit
  // (nullptr: none).
  struct Diagnostics {
    std::vector<double>* switch_log = nullptr;
    ClockAudit* audit = nullptr;  // EventDriven::set_clock_audit
  } diag{};
  // What the observer reads (Observer::reads_groove_interiors, reads_only_friction), asked once:
  // an observer of contact blocks' forces only needs the groove segments' end rows at
  // quiet-phase samples (O(N) per sample instead of O(sum n^2) for long grooves), one of
  // friction forces only the exact stepper's end rows.
  bool ends_only = false;
  bool friction_only = false;
  // The observer sums the contact forces from what the active set knows of them at the samples of
  // an active phase (Observer::takes_active_forces): only the live blocks' neighbours are written.
  bool active_forces = false;
};

}  // namespace sb::event_detail
