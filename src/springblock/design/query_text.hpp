#pragma once
// The parts of a design query a user gives as words: the family, the candidates, the target
// intervals and the goal. The command line's options and Python's keywords are turned into a
// Query here, so both check them the same way and refuse them with the same messages.
#include <optional>
#include <string>
#include <vector>

#include "springblock/design/query.hpp"

namespace sb::design {

struct QueryText {
  std::string family = "periodic";
  std::vector<std::string> candidates;  // family given: each as a pattern is written
  std::string target_mu_s, target_mu_d, target_ratio;  // "X", "LO:HI", ">=X", "<=X"; "" = unconstrained
  std::string minimise, maximise;                      // "mu_s", "mu_d", "ratio" or ""
  // The largest pawl and groove sizes when given; else kDefaultMaxSize, or N on a shorter chain.
  std::optional<int> max_np, max_ng;
};

// Completes `q`, whose base scene fields, space bounds and search options are set, with `text`,
// and validates it. Throws InputError naming the field and what it allows.
void complete_query(Query& q, const QueryText& text);

// The refusal of a fixed pattern (design chooses the surface): InputError("pattern").
[[noreturn]] void refuse_pattern(const std::string& pattern);

// The scene fields a design query shares with a run: not the pattern, the repetitions or the stop
// at the first slip, which the search chooses.
bool shared_scene_field(const std::string& key);

}  // namespace sb::design
