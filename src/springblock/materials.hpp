#pragma once
// Materials given block by block: per-block micro friction (mean and spread of mu_s and mu_d),
// which blocks touch, and the scales of each block's slider spring, each block's mass and each
// internal spring. Given as columns (a TSV file, Python arrays) and/or segments and linear ramps
// laid over them; a field given nowhere keeps the scene's uniform value. A scene that gives none
// holds only empty vectors, and every consumer tests that first, so uniform scenes pay nothing.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sb {

struct Scene;
struct Chain;
struct BlockMechanics;

// The per-block fields, in the order they are hashed and written.
enum class BlockField { Contact, MuS, MuSSd, MuD, MuDSd, KIntScale, KsScale, MassScale };
constexpr int kBlockFields = 8;
const std::array<const char*, kBlockFields>& block_field_names();
// The field called `name`, or throws InputError(what) listing the allowed names.
BlockField block_field(const std::string& name, const std::string& what);
inline int index_of(BlockField f) { return static_cast<int>(f); }

// One stretch of blocks from..to (0-based, both included; a negative index counts from the end,
// -1 being the last block) set to `value`, or, for a ramp, to values rising linearly from `start`
// on block `from` to `end` on block `to`.
struct MaterialSegment {
  BlockField field = BlockField::MuS;
  long from = 0, to = -1;
  bool ramp = false;
  double value = 0, start = 0, end = 0;
};

struct BlockMaterials {
  // Where the columns came from: a file's path, "python arrays", or empty when none were given.
  std::string source;
  std::array<std::vector<double>, kBlockFields> columns;  // one value per block; empty = not given
  bool file = false;       // the columns are a file's (source is its path)
  std::vector<int> lines;  // the file's line of each row, for messages
  std::vector<MaterialSegment> segments;  // laid over the columns in order, later ones on top
  bool given() const;
};

// The fields a scene gives, each as one value per block with the segments applied (an empty
// column: the scene's uniform value). Built from a scene whose N and pattern are set.
struct ResolvedMaterials {
  std::array<std::vector<double>, kBlockFields> column;
  std::string source = "uniform";  // the path, "python arrays", "segments", "PATH + segments" or "uniform"
  bool has(BlockField f) const { return !column[index_of(f)].empty(); }
  double at(BlockField f, int i, double uniform) const { return has(f) ? column[index_of(f)][i] : uniform; }
  // Whether any block's slider spring, mass or internal spring differs from the scene's: only
  // then does the chain carry per-block stiffnesses and masses (all 1 counts as uniform).
  bool mechanical() const;
};

ResolvedMaterials resolve_materials(const Scene& s);

// The per-block slider springs, masses and internal springs of chain c (its uniform K_s, K_int
// and m already set) scaled by the resolved fields.
BlockMechanics block_mechanics(const ResolvedMaterials& m, const Chain& c);

// FNV-1a 64 over each given field's name and its values' IEEE-754 bytes (little-endian), in
// field order, as 16 hex digits: what identifies a scene's per-block fields in its JSON and its
// trajectory specification. "cbf29ce484222325" (FNV's offset basis) for a uniform scene.
std::string materials_hash(const ResolvedMaterials& m);

// Ranges and consistency of a scene's per-block fields; InputError("materials", ...) naming the
// row (and the file's line) or the segment, the column and the allowed range.
void validate_materials(const Scene& s);

// The columns of a TSV file: a header naming its columns, then one row per block. Blank lines and
// lines starting with '#' are skipped. InputError("materials", ...) naming the path, line and
// column for a file that cannot be read, an unknown or repeated column, a row with the wrong
// number of cells or a cell that is not a number. Ranges are validate_materials' business.
BlockMaterials read_materials_tsv(const std::string& path);
BlockMaterials parse_materials_tsv(const std::string& text, const std::string& path);

}  // namespace sb
