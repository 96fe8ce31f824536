#pragma once
// How finely every event refinement resolves a time: a bracket ending near time t is done once it
// is no wider than 4e-16 |t|, about two ulp of t, below which the integrators' times cannot tell
// two instants apart. One rule for the Dormand-Prince event search (first_root.hpp), the modal
// searches (EdgeMarch) and the per-block solver of uncoupled chains, so they stop alike.
#include <cmath>

namespace sb {

inline double time_round_off(double t) { return 4e-16 * std::fabs(t); }

// The one round-off rule for stops in exactly propagated runs (the modal runs, the exact
// stepper): a sliding block stops when dir v falls below -kStopMargin times the slider velocity,
// so that a creeping block whose velocity only touches zero is not stopped and restarted at
// every touch (paper/choices.md, Integration). The per-block solver of uncoupled chains uses the
// same margin.
inline constexpr double kStopMargin = 1e-12;

}  // namespace sb
