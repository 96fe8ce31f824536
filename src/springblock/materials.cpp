#include "springblock/materials.hpp"

#include <cstring>

#include "springblock/errors.hpp"
#include "springblock/fnv1a.hpp"
#include "springblock/model.hpp"
#include "springblock/scene.hpp"

namespace sb {

const std::array<const char*, kBlockFields>& block_field_names() {
  static const std::array<const char*, kBlockFields> names = {
      "contact", "mu_s", "mu_s_sd", "mu_d", "mu_d_sd", "k_int_scale", "k_s_scale", "mass_scale"};
  return names;
}

BlockField block_field(const std::string& name, const std::string& what) {
  const auto& names = block_field_names();
  for (int f = 0; f < kBlockFields; ++f)
    if (name == names[f]) return static_cast<BlockField>(f);
  std::string allowed;
  for (const char* n : names) allowed += (allowed.empty() ? "" : ", ") + std::string(n);
  throw InputError("materials", what + ": unknown field '" + name + "'; the per-block fields are " + allowed);
}

bool BlockMaterials::given() const {
  if (!source.empty() || !segments.empty()) return true;
  for (const auto& c : columns)
    if (!c.empty()) return true;
  return false;
}

bool ResolvedMaterials::mechanical() const {
  for (BlockField f : {BlockField::KIntScale, BlockField::KsScale, BlockField::MassScale}) {
    const auto& c = column[index_of(f)];
    // Row N-1's internal spring does not exist: its k_int_scale is never read.
    const std::size_t n = f == BlockField::KIntScale && !c.empty() ? c.size() - 1 : c.size();
    for (std::size_t i = 0; i < n; ++i)
      if (c[i] != 1.0) return true;
  }
  return false;
}

namespace {

// The value a field has where nothing sets it: the scene's own.
std::vector<double> uniform_column(const Scene& s, BlockField f) {
  const int N = s.geometry.N;
  switch (f) {
    case BlockField::Contact: {
      std::vector<double> out;
      for (auto b : contact_mask(s.pattern, N, 0)) out.push_back(b);
      return out;
    }
    case BlockField::MuS: return std::vector<double>(N, s.friction.mu_s_mean);
    case BlockField::MuSSd: return std::vector<double>(N, s.friction.mu_s_sd);
    case BlockField::MuD: return std::vector<double>(N, s.friction.mu_d_mean);
    case BlockField::MuDSd: return std::vector<double>(N, s.friction.mu_d_sd);
    default: return std::vector<double>(N, 1.0);
  }
}

}  // namespace

ResolvedMaterials resolve_materials(const Scene& s) {
  ResolvedMaterials r;
  const BlockMaterials& m = s.materials;
  if (!m.given()) return r;
  r.column = m.columns;
  const long N = s.geometry.N;
  for (const MaterialSegment& g : m.segments) {
    auto& c = r.column[index_of(g.field)];
    if (c.empty()) c = uniform_column(s, g.field);
    const long from = g.from < 0 ? N + g.from : g.from, to = g.to < 0 ? N + g.to : g.to;
    if (from < 0 || to < from || to >= static_cast<long>(c.size())) continue;  // refused by validate
    for (long i = from; i <= to; ++i) {
      if (!g.ramp) {
        c[i] = g.value;
        continue;
      }
      // (1 - w) start + w end is exactly start on the first block and end on the last.
      const double w = to == from ? 0.0 : static_cast<double>(i - from) / static_cast<double>(to - from);
      c[i] = (1.0 - w) * g.start + w * g.end;
    }
  }
  const bool columns = !m.source.empty();
  r.source = columns ? (m.segments.empty() ? m.source : m.source + " + segments") : "segments";
  return r;
}

BlockMechanics block_mechanics(const ResolvedMaterials& m, const Chain& c) {
  BlockMechanics b;
  for (int i = 0; i < c.N; ++i) {
    b.K_s.push_back(c.K_s * m.at(BlockField::KsScale, i, 1.0));
    b.K_int.push_back(i + 1 < c.N ? c.K_int * m.at(BlockField::KIntScale, i, 1.0) : 0.0);
    b.m.push_back(c.m * m.at(BlockField::MassScale, i, 1.0));
    b.m_gamma.push_back(b.m.back() * c.gamma);
    b.inv_m.push_back(1.0 / b.m.back());
  }
  return b;
}

std::string materials_hash(const ResolvedMaterials& m) {
  Fnv1a64 h;
  for (int f = 0; f < kBlockFields; ++f) {
    if (m.column[f].empty()) continue;
    h.add(block_field_names()[f]);
    h.add(0);
    for (double x : m.column[f]) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      for (int b = 0; b < 8; ++b) h.add(static_cast<unsigned char>(bits >> (8 * b)));
    }
  }
  return h.hex();
}

}  // namespace sb
