#pragma once
// An ensemble's complete state, for a copy of a result in another process (Python's pickle):
// every repetition as the results JSON holds it plus what that leaves out (its contact fraction,
// mu(t) and stress snapshots, values that are not finite), and the statistics as they were
// computed, so the copy reads back equal number for number.
#include <nlohmann/json_fwd.hpp>

#include "springblock/ensemble.hpp"

namespace sb {

nlohmann::json ensemble_state(const EnsembleResult& e);
// Throws InputError("state") when `j` is not a state ensemble_state wrote.
EnsembleResult ensemble_from_state(const nlohmann::json& j);

// One repetition's part of that state, its mu(t) series and stress snapshots included: what a
// repetition run on another MPI rank sends back, to be read back bit for bit.
nlohmann::json repetition_state(const RunResult& r);
RunResult repetition_from_state(const nlohmann::json& j);

}  // namespace sb
