#pragma once
// Surfaces given block by block: a string of 0 (groove) and 1 (pawl) characters, one per block,
// inline after "mask:" or in a file after "mask:@". A file may spread its characters over lines
// and space them freely; a line whose first non-blank character is '#' is a comment. A relative
// path is read from the working directory, as every other path the program is given.
//
// A mask's text() names a file by its path, which says nothing about what the file held when a
// result was made: mask_hash is what ties a result to its surface, and scenes that may share runs
// are compared on the blocks themselves (trajectory_spec.cpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "springblock/surface.hpp"

namespace sb {

// The spec of "mask:ARGS" (`spec` is the whole text, for messages). Throws InputError("pattern")
// for an empty mask, a character other than 0/1 (its position; for a file its line and column),
// a mask longer than 1000000 blocks (N's bound), no pawl, or a file that cannot be read (its path).
PatternSpec parse_mask_pattern(std::string_view args, const std::string& spec);

// The blocks of a mask file. Throws InputError("pattern") as parse_mask_pattern does.
std::vector<std::uint8_t> read_mask_file(const std::string& path);

// What parse_mask_pattern guarantees of a mask, checked again for a spec made by hand: 1 to
// 1000000 entries, each 0 or 1, at least one 1. Throws InputError("pattern"), the message
// starting with `what`.
void check_mask_blocks(const std::vector<std::uint8_t>& mask, const std::string& what = "the mask");

// A mask lays one entry on each block, so its length must be the chain's N; the mask does not
// set N (a scene's N is given or defaulted, never inferred). Throws InputError("pattern") naming
// both numbers.
void check_mask_length(const PatternSpec& spec, int N);

// "0110...": the mask as its digits.
std::string mask_digits(const std::vector<std::uint8_t>& mask);

// 64-bit FNV-1a of mask_digits(mask), as 16 lower-case hex digits.
std::string mask_hash(const std::vector<std::uint8_t>& mask);

// text() for one-line summaries: a mask longer than 40 blocks is shown by its first 24 blocks,
// its length, pawl count and hash; a file mask by its path and the same numbers.
std::string pattern_label(const PatternSpec& spec);

}  // namespace sb
