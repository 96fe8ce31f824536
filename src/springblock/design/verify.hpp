#pragma once
// The honest answer: the search's best candidates re-run on fresh repetitions. Their screening
// estimates are biased in their favour (they were chosen because their screening repetitions
// happened to land near the target: the winner's curse), so every number reported for a
// candidate comes from a new, independent set of repetitions with the seed of stage
// kVerifyStage, full runs (mu_s and mu_d).
#include <atomic>
#include <vector>

#include "springblock/design/search.hpp"

namespace sb::design {

struct Verified {
  int candidate = 0;      // index into the candidates
  int screening_rank = 0; // its place in the search's ranking (0 = best)
  Statistic mu_s, mu_d, ratio;
  bool meets_target = false;  // every interval met by the rule of target.hpp (meets)
  double score = 0;           // target.hpp's score of the fresh means
  double wall_s = 0;
};

// Re-runs the first `count` of `ranking` with `reps` fresh full repetitions each, in one pool.
// The result keeps the screening order, except that candidates meeting the target come first
// (stable): the choice among them uses the fresh data only through that yes/no.
std::vector<Verified> verify(const Scene& base, const std::vector<Candidate>& candidates, const std::vector<int>& ranking,
                             const Target& target, int count, int reps, const std::atomic<bool>* interrupt,
                             const StageProgress& progress, bool& interrupted);

bool meets_target(const Target& t, const Statistic& mu_s, const Statistic& mu_d, const Statistic& ratio);

}  // namespace sb::design
