#pragma once
// Contact masks: which blocks touch the sliding plane (pawls) and which sit in grooves.
// A groove block keeps all elastic and damping forces but has no friction.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace sb {

enum class SurfaceKind { Smooth, Periodic, Hierarchical, Random };

// Parsed pattern specification (the --pattern option):
//   smooth | periodic:NP,NG | hierarchical:G1,G2,... | random:FRACTION
struct PatternSpec {
  SurfaceKind kind = SurfaceKind::Smooth;
  int n_p = 0, n_g = 0;            // periodic
  std::vector<int> levels;         // hierarchical groove sizes, largest first
  double groove_fraction = 0.0;    // random: fraction of blocks in grooves
  std::string text() const;        // canonical spec string, e.g. "periodic:2,1"
};

// Throws InputError(field="pattern") with the accepted grammar on any malformed spec,
// non-positive sizes, or fraction outside [0,1).
PatternSpec parse_pattern(const std::string& spec);

// 1 = in contact, 0 = groove. Deterministic for all kinds except Random, which draws
// round(fraction*N) groove blocks without replacement from `seed`.
// Throws InputError(field="pattern") if a size exceeds N or no block is left in contact.
std::vector<std::uint8_t> build_contact_mask(const PatternSpec& spec, int N, std::uint64_t seed = 0);

// Fraction of blocks in contact, S/S_tot.
double contact_fraction(const std::vector<std::uint8_t>& mask);

}  // namespace sb
