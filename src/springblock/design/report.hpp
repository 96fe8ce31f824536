#pragma once
// A design query's results as JSON (the `design --json` object and the --out file) and the
// explanation of an infeasible target: what was reachable and why the target was not.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "springblock/design/query.hpp"

namespace sb::design {

// One object: feasible, best (the verified candidates: pattern, layout, contact fraction, mu_s,
// mu_d and ratio as {mean, std, sem, n} from the fresh repetitions, meets_target, and the
// screening estimate), nearest and why (when infeasible), the rule, the target, the search
// (rungs, pruning counts), every evaluated candidate (for the figure), the scene, seed, method,
// provenance and wall time. No NaN: undefined numbers are null.
nlohmann::json design_json(const Query& q, const Outcome& o, const std::string& command_line);

// Why no verified candidate met the target, in one or two sentences: which interval lies outside
// the range the screened candidates reached (with the candidate nearest to it), and which
// constraints of the space excluded candidates. "" when feasible.
std::string infeasible_reason(const Query& q, const Outcome& o);

// The text of the meets-target rule, as recorded in the JSON.
// How the answers are ordered and when their repetitions stop (verify.hpp), in words.
std::string order_rule();
std::string meets_rule();

}  // namespace sb::design
