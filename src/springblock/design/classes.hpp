#pragma once
// Pruning on the contact fraction, for queries that need mu_d (a mu_d or ratio target, or an
// objective on them), whose full runs cost 10 to 30 times a run to the first slip.
//
// Why the contact fraction: the paper (Sec. III, "First level patterning", and table tpat0) finds
// that the dynamic coefficient "displays reduced variation in the presence of patterning, and in
// practice increases only when there is a large reduction of the number of blocks in contact":
// mu_d is, to within about 0.015 on the paper's chain, a function of the contact fraction
// S/S_tot alone (design_map: 0.533 to 0.545 along S = 1/2 for n from 1 to 60), while it spans
// 0.525 to 0.65 over S. So the candidates are grouped into classes of contact fraction (bins of
// width `bin_width`); one representative per class (the member nearest the bin's centre) gets
// `reps` full repetitions; a class whose representative's mu_d lies farther than `margin` from
// the mu_d interval (or whose ratio bound cannot reach the ratio interval) is pruned whole. The
// margin covers the spread within a class and the representative's noise; the design test and
// paper/choices.md compare a pruned query with an unpruned one.
#include <atomic>
#include <string>
#include <vector>

#include "springblock/design/search.hpp"

namespace sb::design {

struct ClassOptions {
  double bin_width = 0.02;  // contact fraction
  double margin = 0.02;     // in mu_d
  int reps = 2;             // full repetitions of each representative
};

struct ContactClass {
  double lo = 0, hi = 0;   // contact fractions [lo, hi)
  int members = 0;
  std::vector<int> member_list;  // indices into the candidates
  int representative = 0;  // index into the candidates
  Statistic mu_d;
  bool kept = true;
};

struct ClassPrune {
  std::vector<int> kept;  // candidates of the kept classes, in candidate order
  std::vector<ContactClass> classes;
  std::uint64_t seed = 0;
  double cpu_s = 0;
  bool interrupted = false;
};

// The seed stage of the representatives' repetitions (beside the rungs' and verification's).
constexpr int kClassStage = 999;

ClassPrune prune_by_contact_class(const Scene& base, const std::vector<Candidate>& candidates, const Target& target,
                                  const ClassOptions& options, const std::atomic<bool>* interrupt,
                                  const StageProgress& progress);

}  // namespace sb::design
