#pragma once
// The design space: which surfaces a query may choose from (a pattern family and its bounds)
// and the constraints every candidate must satisfy. The candidates are generated here, and the
// exact, simulation-free pruning happens here too:
//  - constraints (contact fraction, smallest feature) are computed from the contact mask itself,
//    so a candidate that violates them is never simulated;
//  - candidates whose contact masks are identical are one surface (same chain, same draws, same
//    result): only the first (smallest sizes) is kept, and the others are counted.
#include <cstdint>
#include <string>
#include <vector>

#include "springblock/scene.hpp"
#include "springblock/surface.hpp"

namespace sb::design {

// Given: the surfaces the user lists (masks or any pattern), chosen among as a family's are.
enum class Family { Periodic, Hierarchical, Random, Given };
std::string family_name(Family f);
Family parse_family(const std::string& text);  // throws InputError("family")

// The paper's largest feature, 60 blocks: the default upper bound of n_p and n_g (G1).
inline constexpr int kDefaultMaxSize = 60;

struct DesignSpace {
  Family family = Family::Periodic;
  // periodic: pawl and groove sizes in blocks, both ranges inclusive
  // (complete_query makes the upper ones N on a chain shorter than kDefaultMaxSize, unless given.)
  int min_np = 1, max_np = kDefaultMaxSize, min_ng = 1, max_ng = kDefaultMaxSize;
  // hierarchical: `levels` levels; level 1's groove (= pawl) size G1 in [min_ng, max_ng], each
  // deeper level's G_{k+1} = G_k / f for a factor f of `factors` that divides G_k
  int levels = 2;
  std::vector<int> factors = {2, 3, 4, 5, 6, 8, 10};
  // random: groove fractions from min_fraction to max_fraction in steps of fraction_step
  double min_fraction = 0.1, max_fraction = 0.9, fraction_step = 0.05;
  // given: the candidates as listed (each is laid out with the query's layout)
  std::vector<PatternSpec> given;
  // constraints on every candidate
  double min_contact = 0.0, max_contact = 1.0;  // contact fraction S/S_tot
  int min_feature = 1;  // the shortest run of pawl or groove blocks in the mask (random: none)
};

// Throws InputError naming the field (min_np, max_ng, levels, factors, min_contact, candidates,
// ...) and its allowed range when the bounds are empty or impossible on a chain of N blocks.
void validate(const DesignSpace& space, int N);

// Each given candidate must lie on the chain of `base` (its N and layout): one the user named is
// refused, not dropped as a family's misfit would be. Throws InputError("candidates").
void validate_given(const DesignSpace& space, const Scene& base);

// The candidates of --candidates: each text parsed as a --pattern. Throws InputError("candidates").
std::vector<PatternSpec> parse_candidates(const std::vector<std::string>& texts);

struct Candidate {
  PatternSpec spec;             // with the query's layout
  double contact_fraction = 0;  // of the mask (random: round(fraction N) grooves, exact)
  int min_feature = 0;          // shortest run of equal mask values
  int duplicates = 0;           // other specs of the space with this same mask
};

struct CandidateSet {
  std::vector<Candidate> kept;
  int generated = 0;               // specs in the bounds
  int dropped_contact = 0;         // contact fraction outside [min_contact, max_contact]
  int dropped_feature = 0;         // a run shorter than min_feature
  int dropped_duplicate = 0;       // same mask as a kept candidate
  double contact_lo = 1, contact_hi = 0;  // contact fractions over all generated specs
};

// The candidates of `space` on the chain of `base` (its N and layout), in generation order
// (periodic: n_p, then n_g ascending). `space` must be validated.
CandidateSet generate(const DesignSpace& space, const Scene& base);

// Shortest run of equal values in a mask (the smallest feature, pawl or groove, in blocks).
int shortest_run(const std::vector<std::uint8_t>& mask);

}  // namespace sb::design
