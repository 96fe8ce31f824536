#pragma once
// Exact event-driven solution of a chain without internal springs (K_int = 0).
//
// Every block is then its own one-degree-of-freedom system, solved in closed form and advanced
// on its own: no shared step size, and a block that creeps or rests costs nothing between its
// own events. In each phase of block i
//   stuck:   u = const, v = 0; its force K_s (v_s t - u) reaches f_static at a closed-form time;
//   moving:  m u'' + m gamma u' + K_s u = K_s v_s t - phi, with phi = dir f_kin (sliding) or 0
//            (groove). Around the particular solution u_p = v_s t - phi / K_s - gamma v_s / omega^2
//            the deviation x = u - u_p is one damped mode (damped_mode.hpp), so u and v are
//            closed form at any time.
// A sliding block stops where first_stop_tau (linear/mode_stop.hpp) finds it, to round-off in t
// with no grid and no grazing bound; a creeping block (mu_d clipped to mu_s) never stops there,
// so it has no further event at all, also without damping.
// At an event the stick/slip rules of switching.hpp (apply_rules) apply to the one block, with
// the same cascade guard.
// Samples: stuck blocks hold their u; moving blocks are evaluated at the sample time unless the
// observer reads only friction forces (Observer::reads_only_friction()), which for K_int = 0
// depend on the stuck blocks' u and on dir alone.
#include <vector>

#include "springblock/model.hpp"
#include "springblock/observe/observer.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

// Runs the chain (c.K_int must be 0) from s to t_end. Switch instants are appended to log if
// given. s.steps counts events, s.rhs_evals the closed-form block evaluations divided by N
// (whole-chain equivalents, comparable with the steppers' counts).
void run_uncoupled(const Chain& c, State& s, double t_end, double sample_dt, Observer& obs,
                   std::vector<double>* log);

}  // namespace sb::event_detail
