#pragma once
// Contact masks: which blocks touch the sliding plane (pawls) and which sit in grooves.
// A groove block keeps all elastic and damping forces but has no friction.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace sb {

enum class SurfaceKind { Smooth, Periodic, Hierarchical, Random };

// Where a level's alternation of pawls and grooves sits on the run of blocks it divides (the
// whole chain at level 1, each pawl left by the level above deeper down). The paper does not say;
// paper/choices.md ("Pattern layout") has the study that chose the default. With p pawl and g
// groove blocks, block j of a run of L is a pawl iff (j + phase) mod (p + g) < p, where the phase is
//   PawlFirst:   0, the run starts with a whole pawl;
//   GrooveFirst: p, it starts with a whole groove;
//   OneBased:    1, the pawl test on blocks numbered from 1 (a pawl of p shifted one block left);
//   Symmetric:   the run is its own mirror image; of two such placements the one with pawl
//                pieces at both ends (else the least asymmetric placement, a pawl first).
enum class Layout { PawlFirst, Symmetric, GrooveFirst, OneBased };
std::string layout_name(Layout l);

// Parsed pattern specification (the --pattern option):
//   smooth | periodic:NP,NG | hierarchical:G1,G2,... | random:FRACTION
// and its layout (the --layout option): one rule per level, level 1 first; the last one holds
// for every deeper level.
struct PatternSpec {
  SurfaceKind kind = SurfaceKind::Smooth;
  int n_p = 0, n_g = 0;            // periodic
  std::vector<int> levels;         // hierarchical groove sizes, largest first
  double groove_fraction = 0.0;    // random: fraction of blocks in grooves
  // The default is the layout study's choice (paper/choices.md, "Pattern layout"): level 1
  // symmetric on the chain, every deeper level pawl first on the pawls above it.
  std::vector<Layout> layout = {Layout::Symmetric, Layout::PawlFirst};
  std::string text() const;        // canonical spec string, e.g. "periodic:2,1" (without the layout)
  std::string layout_text() const; // e.g. "symmetric" or "symmetric,pawl_first"
};

// Throws InputError(field="pattern") with the accepted grammar on any malformed spec,
// non-positive sizes, or fraction outside [0,1).
PatternSpec parse_pattern(const std::string& spec);
// "pawl_first", "symmetric", "groove_first", "one_based", or a comma list of them per level.
// Throws InputError(field="layout").
std::vector<Layout> parse_layout(const std::string& text);

// Whether `spec` can be laid on a chain of N blocks. Throws InputError(field="pattern") naming the
// allowed range: N >= 1, sizes in [1, N] (and at most 1000000), 1 to 8 hierarchical levels, a
// groove fraction in [0, 1) that leaves a block in contact, and a layout that leaves one too.
// A scene's surface is checked here once, when the scene is validated (validate(Scene)).
void validate_surface(const PatternSpec& spec, int N);

// 1 = in contact, 0 = groove. Deterministic for all kinds except Random, which draws
// round(fraction*N) groove blocks without replacement from `seed`. Checks `spec` first
// (validate_surface): for callers that hold a pattern but no validated scene.
std::vector<std::uint8_t> build_contact_mask(const PatternSpec& spec, int N, std::uint64_t seed = 0);

// The same mask without the checks, for a spec validate_surface accepted on this N: what every
// repetition of a validated scene builds its chain with.
std::vector<std::uint8_t> contact_mask(const PatternSpec& spec, int N, std::uint64_t seed);

// Fraction of blocks in contact, S/S_tot.
double contact_fraction(const std::vector<std::uint8_t>& mask);

}  // namespace sb
