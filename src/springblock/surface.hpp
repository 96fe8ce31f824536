#pragma once
// Contact masks: which blocks touch the sliding plane (pawls) and which sit in grooves.
// A groove block keeps all elastic and damping forces but has no friction.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace sb {

enum class SurfaceKind { Smooth, Periodic, Hierarchical, Random, Mask };

// Where a level's alternation of pawls and grooves sits on the run of blocks it divides (the
// whole chain at level 1, each pawl left by the level above deeper down). The paper does not say;
// paper/choices.md ("Pattern layout") has the study that chose the default. With p pawl and g
// groove blocks (p = g at every level of hierarchical:G1,G2,...; p and g as given per level in
// hierarchical:P1/G1,P2/G2,..., placed by the same rules: paper/choices.md, "Unequal pawls and
// grooves"), block j of a run of L is a pawl iff (j + phase) mod (p + g) < p, where the phase is
//   PawlFirst:   0, the run starts with a whole pawl;
//   GrooveFirst: p, it starts with a whole groove;
//   OneBased:    1, the pawl test on blocks numbered from 1 (a pawl of p shifted one block left);
//   Symmetric:   the run is its own mirror image; of two such placements the one with pawl
//                pieces at both ends (else the least asymmetric placement, a pawl first).
enum class Layout { PawlFirst, Symmetric, GrooveFirst, OneBased };
std::string layout_name(Layout l);

// Parsed pattern specification (the --pattern option):
//   smooth | periodic:NP,NG | hierarchical:G1,G2,... | hierarchical:P1/G1,P2/G2,...
//   | random:FRACTION | mask:0110... | mask:@FILE
// and its layout (the --layout option): one rule per level, level 1 first; the last one holds
// for every deeper level. A mask gives every block itself, so no layout applies to it.
struct PatternSpec {
  SurfaceKind kind = SurfaceKind::Smooth;
  int n_p = 0, n_g = 0;            // periodic
  std::vector<int> levels;         // hierarchical groove sizes, level 1 first
  // Hierarchical pawl sizes, level 1 first. Empty when every level's pawl equals its groove (the
  // form G1,G2,...), which parse_pattern also gives for P/G levels that are all equal.
  std::vector<int> level_pawls;
  double groove_fraction = 0.0;    // random: fraction of blocks in grooves
  std::vector<std::uint8_t> mask;  // mask: one entry per block, 1 = pawl
  std::string mask_path;           // mask: the file it was read from; empty for an inline mask
  // The default is the layout study's choice (paper/choices.md, "Pattern layout"): level 1
  // symmetric on the chain, every deeper level pawl first on the pawls above it.
  std::vector<Layout> layout = {Layout::Symmetric, Layout::PawlFirst};
  // Canonical spec string, e.g. "periodic:2,1" (without the layout); parse_pattern(text()) gives
  // this spec back. An inline mask is its digits ("mask:0110"), a file mask "mask:@PATH" (which
  // names the file, not its content: see mask_hash in surface_mask.hpp).
  std::string text() const;
  int pawl_size(std::size_t level) const;  // hierarchical: level's pawl size (level 0 is level 1)
  std::string layout_text() const; // e.g. "symmetric" or "symmetric,pawl_first"
};

// Throws InputError(field="pattern") with the accepted grammar on any malformed spec,
// non-positive sizes, fraction outside [0,1), or a mask that is empty, holds a character other
// than 0/1, has no pawl or cannot be read (surface_mask.hpp).
PatternSpec parse_pattern(const std::string& spec);
// "pawl_first", "symmetric", "groove_first", "one_based", or a comma list of them per level.
// Throws InputError(field="layout").
std::vector<Layout> parse_layout(const std::string& text);

// Whether `spec` can be laid on a chain of N blocks. Throws InputError(field="pattern") naming the
// allowed range: N >= 1, sizes in [1, N] (and at most 1000000), 1 to 8 hierarchical levels, a
// groove fraction in [0, 1) that leaves a block in contact, a layout that leaves one too, and a
// mask of exactly N blocks with at least one pawl.
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
