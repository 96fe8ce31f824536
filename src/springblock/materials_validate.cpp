// validate_materials: the ranges of every per-block value where it was written (a file's line, a
// Python array's index, a segment), then what only the resolved fields show: whether any block
// touches, mu_d against mu_s block by block, and which integrators take per-block mechanics.
#include <cmath>

#include "springblock/errors.hpp"
#include "springblock/materials.hpp"
#include "springblock/scene.hpp"

namespace sb {
namespace {

struct Range {
  double lo, hi;
  const char* text;
};

// Means and spreads as the scene's own; an internal spring's scale may be 0 (the chain is cut
// there: RK4 integrates the two pieces as they are). A block's slider spring and mass stay within
// eight decades of the scene's either way, as the springs' upper bound: a mass scale of 1e-300
// gives a mode no solver can follow (paper/choices.md, materials).
Range range_of(BlockField f) {
  switch (f) {
    case BlockField::Contact: return {0, 1, "0 or 1"};
    case BlockField::KIntScale: return {0, 1e8, "[0, 1e8]"};
    case BlockField::KsScale:
    case BlockField::MassScale: return {1e-8, 1e8, "[1e-8, 1e8]"};
    default: return {0, 100, "[0, 100]"};
  }
}

bool in_range(BlockField f, double x) {
  const Range r = range_of(f);
  if (!std::isfinite(x) || x > r.hi || x < r.lo) return false;
  return f != BlockField::Contact || x == 0.0 || x == 1.0;
}

const char* name_of(BlockField f) { return block_field_names()[index_of(f)]; }

// Where block i's row was written, for messages.
std::string row_where(const BlockMaterials& m, std::size_t i) {
  if (!m.lines.empty() && i < m.lines.size())
    return "'" + m.source + "' line " + std::to_string(m.lines[i]) + " (row " + std::to_string(i + 1) + ", block " +
           std::to_string(i) + ")";
  return m.source + ", block " + std::to_string(i);
}

void check_columns(const BlockMaterials& m, int N) {
  if (m.source.empty()) return;
  if (m.file)
    require(m.lines.size() == static_cast<std::size_t>(N), "materials",
            "'" + m.source + "' has " + std::to_string(m.lines.size()) + " rows; the scene has N = " +
                std::to_string(N) + " blocks (one row per block)");
  for (int f = 0; f < kBlockFields; ++f) {
    const auto& c = m.columns[f];
    const auto field = static_cast<BlockField>(f);
    if (c.empty()) continue;
    require(c.size() == static_cast<std::size_t>(N), "materials",
            m.source + ": " + name_of(field) + " has " + std::to_string(c.size()) + " values; the scene has N = " +
                std::to_string(N) + " blocks (one value per block)");
    for (std::size_t i = 0; i < c.size(); ++i)
      require(in_range(field, c[i]), "materials",
              row_where(m, i) + ", column " + name_of(field) + ": value " + printed(c[i]) +
                  " is outside the allowed range " + range_of(field).text);
  }
}

void check_segments(const Scene& s) {
  const long N = s.geometry.N;
  const auto& segs = s.materials.segments;
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const MaterialSegment& g = segs[k];
    const std::string at = "segments." + std::to_string(k) + " (" + name_of(g.field) + ")";
    const long from = g.from < 0 ? N + g.from : g.from, to = g.to < 0 ? N + g.to : g.to;
    require(from >= 0 && from < N && to >= 0 && to < N && from <= to, "segments",
            at + ": blocks from = " + std::to_string(g.from) + " to = " + std::to_string(g.to) +
                " must satisfy 0 <= from <= to <= N - 1 = " + std::to_string(N - 1) +
                " (inclusive, 0-based; a negative index counts from the end, -1 the last block)");
    for (const auto& [what, x] : g.ramp ? std::vector<std::pair<const char*, double>>{{"start", g.start}, {"end", g.end}}
                                        : std::vector<std::pair<const char*, double>>{{"value", g.value}})
      require(in_range(g.field, x), "segments",
              at + ": " + what + " " + printed(x) + " is outside the allowed range " + range_of(g.field).text);
    require(!(g.field == BlockField::Contact && g.ramp), "segments", at + ": contact takes a value (0 or 1), not a ramp");
    require(!(g.field == BlockField::Contact && s.pattern.kind == SurfaceKind::Random &&
              s.materials.columns[index_of(BlockField::Contact)].empty()),
            "segments",
            at + ": a random pattern draws its contact blocks per repetition, so contact segments need a contact "
                 "column (a materials file or array) to lie on");
  }
}

// Where block i's value came from, for a message about the resolved fields.
std::string block_where(const BlockMaterials& m, const ResolvedMaterials& r, int i) {
  return m.file ? row_where(m, i) : "block " + std::to_string(i) + " (" + r.source + ")";
}

}  // namespace

void validate_materials(const Scene& s) {
  const BlockMaterials& m = s.materials;
  if (!m.given()) return;
  check_columns(m, s.geometry.N);
  check_segments(s);
  const ResolvedMaterials r = resolve_materials(s);
  const int N = s.geometry.N;
  if (r.has(BlockField::Contact)) {
    bool any = false;
    for (double x : r.column[index_of(BlockField::Contact)]) any = any || x == 1.0;
    require(any, "materials", r.source + ": column contact has no block in contact (all 0); at least one must touch");
  }
  if (r.has(BlockField::MuS) || r.has(BlockField::MuD))
    for (int i = 0; i < N; ++i) {
      const double ms = r.at(BlockField::MuS, i, s.friction.mu_s_mean), md = r.at(BlockField::MuD, i, s.friction.mu_d_mean);
      require(md <= ms, "materials",
              block_where(m, r, i) + ": mu_d mean " + printed(md) + " exceeds the mu_s mean " + printed(ms) +
                  "; the allowed range is [0, mu_s] (kinetic friction above static friction has no stick-slip)");
    }
}

}  // namespace sb
