#pragma once
// A check for the tests (EventDriven::set_clock_audit): each group of the exact stepper that keeps
// its clock and screen across a switch has its screen compared with the one the classification
// would build now (SpanScreen::current; a mismatch throws std::logic_error), and the groups kept,
// and those whose runs were kept but whose surroundings the classification renewed, are counted.
namespace sb {

struct ClockAudit {
  long kept = 0;
  long renewed = 0;
  void take(bool kept_group, bool stale) {
    if (kept_group) ++kept;
    else if (stale) ++renewed;
  }
};

}  // namespace sb
