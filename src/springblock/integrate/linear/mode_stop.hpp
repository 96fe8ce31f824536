#pragma once
// When a block sliding alone (no internal springs, methods/uncoupled.cpp) comes to rest: the
// first tau > 0 at which dir (v_s + x'(tau)) <= 0, x the damped mode of its deviation from the
// particular solution (x(0) = x0, x'(0) = p0), to round-off in t_ref + tau.
#include "springblock/integrate/linear/damped_mode.hpp"

namespace sb::event_detail {

// +inf if the block never stops. `evals` counts the mode's evaluations. Throws if the search
// finds no end (a mode that neither stops nor settles: never seen).
double first_stop_tau(const DampedMode& mode, double x0, double p0, int dir, double v_slider, double t_ref,
                      long long& evals);

}  // namespace sb::event_detail
