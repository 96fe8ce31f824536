#pragma once
// A design query from start to end: generate and prune the candidates (space.hpp), search them
// by successive halving (search.hpp), verify the best on fresh repetitions (verify.hpp). The
// `design` command and the tests call run_design; the JSON and the infeasibility explanation
// are report.hpp's.
#include <atomic>

#include "springblock/design/classes.hpp"
#include "springblock/design/search.hpp"
#include "springblock/design/space.hpp"
#include "springblock/design/target.hpp"
#include "springblock/design/verify.hpp"

namespace sb::design {

struct Query {
  Scene base;  // validated: chain, material, run control, seed, threads (its pattern is ignored)
  DesignSpace space;
  Target target;
  SearchOptions search;
  bool class_prune = true;  // with a mu_d target: prune contact-fraction classes first (classes.hpp)
  ClassOptions classes;
  int top = 5;            // candidates verified and reported
  VerifyOptions verify;   // fresh full repetitions of each, added until resolved
};

// Throws InputError naming the field for bad bounds, an empty target, or counts out of range.
void validate(const Query& q);

struct Outcome {
  CandidateSet candidates;
  bool classes_used = false;
  ClassPrune classes;
  SearchResult search;
  std::vector<Verified> verified;
  bool feasible = false;  // some verified candidate meets the target
  bool interrupted = false;
  double wall_s = 0;
};

Outcome run_design(const Query& q, const std::atomic<bool>* interrupt = nullptr, const StageProgress& progress = {});

}  // namespace sb::design
