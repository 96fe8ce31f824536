#pragma once
// Cost of the event method against the chain size N, for accuracy_cost: how the price of one
// simulated second grows from 90 to 2,880 blocks at the paper's block size, with the exponent of
// a power law fitted per surface. The two halves of a target (plan, finish) like
// work_precision.hpp, so the driver runs both studies in one pool.
#include <vector>

#include <nlohmann/json.hpp>

#include "common.hpp"

namespace repro {

// One scene per (surface, N): the event method at its default tolerance, L_x = N x 0.2 mm (the
// paper's 7.2 cm for 360 blocks), a fixed simulated time, x.study = "scaling".
std::vector<LabelledScene> cost_scaling_plan(const Context& ctx);

// The document's "scaling" block: per surface, per N the CPU time, simulated seconds, switches,
// steps, rhs evaluations and CPU seconds per simulated second; and the least-squares fit of
// log(cost) against log(N) with the exponent's standard error.
void cost_scaling_finish(const Context& ctx, nlohmann::json& doc);

}  // namespace repro
