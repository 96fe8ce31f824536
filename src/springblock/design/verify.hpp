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
  int reps = 0;               // fresh repetitions run
  double half_width = 0;      // the largest 2 SEM over the quantities the target constrains
  bool resolved = false;      // see resolved()
};

// How many fresh repetitions a finalist gets: `reps` first, then twice as many, and so on while
// its distance to the target is not resolved, up to `max_reps`. `resolution`: the 2 SEM at which a
// distance counts as resolved even when the estimate straddles an interval's edge.
struct VerifyOptions {
  int reps = 10;
  int max_reps = 80;
  double resolution = 0.002;
};

// A finalist's distance to the target is resolved when, for every quantity the target
// constrains, its fresh estimate's two-standard-error interval lies wholly inside the target
// interval or wholly outside it (whether it meets is then not in doubt), or is no wider than
// 2 x resolution on each side (the distance is then known to that precision).
bool resolved(const Target& t, const Verified& v, double resolution);

// Re-runs the first `count` of `ranking` on fresh full repetitions (VerifyOptions), in one pool per
// round. The result is ordered by the fresh score (the distance to the target printed beside each
// answer; screening order on ties).
std::vector<Verified> verify(const Scene& base, const std::vector<Candidate>& candidates, const std::vector<int>& ranking,
                             const Target& target, int count, const VerifyOptions& options,
                             const std::atomic<bool>* interrupt, const StageProgress& progress, bool& interrupted);

bool meets_target(const Target& t, const Statistic& mu_s, const Statistic& mu_d, const Statistic& ratio);

}  // namespace sb::design
