#include "springblock/design/space.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "springblock/errors.hpp"
#include "springblock/surface_mask.hpp"

namespace sb::design {
namespace {

void check_range(const std::string& lo_field, int lo, const std::string& hi_field, int hi, int N) {
  require(lo >= 1 && lo <= N, lo_field, std::to_string(lo) + " is outside [1, N = " + std::to_string(N) + "]");
  require(hi >= 1 && hi <= N, hi_field, std::to_string(hi) + " is outside [1, N = " + std::to_string(N) + "]");
  require(lo <= hi, hi_field, std::to_string(hi) + " is below " + lo_field + " = " + std::to_string(lo) +
                                  "; the range is empty");
}

// The hierarchical specs: G1 in [lo, hi], then each level divided by one of the factors.
void hierarchies(const DesignSpace& s, std::vector<int>& prefix, std::vector<PatternSpec>& out) {
  if (static_cast<int>(prefix.size()) == s.levels) {
    PatternSpec p;
    p.kind = SurfaceKind::Hierarchical;
    p.levels = prefix;
    out.push_back(p);
    return;
  }
  if (prefix.empty()) {
    for (int g = s.min_ng; g <= s.max_ng; ++g) {
      prefix = {g};
      hierarchies(s, prefix, out);
    }
    prefix.clear();
    return;
  }
  for (int f : s.factors) {
    const int g = prefix.back();
    if (g % f != 0) continue;
    prefix.push_back(g / f);
    hierarchies(s, prefix, out);
    prefix.pop_back();
  }
}

std::vector<PatternSpec> specs(const DesignSpace& s) {
  std::vector<PatternSpec> out;
  if (s.family == Family::Periodic) {
    for (int p = s.min_np; p <= s.max_np; ++p)
      for (int g = s.min_ng; g <= s.max_ng; ++g) {
        PatternSpec spec;
        spec.kind = SurfaceKind::Periodic;
        spec.n_p = p;
        spec.n_g = g;
        out.push_back(spec);
      }
  } else if (s.family == Family::Hierarchical) {
    std::vector<int> prefix;
    hierarchies(s, prefix, out);
  } else if (s.family == Family::Given) {
    out = s.given;
  } else {
    const int steps = static_cast<int>(std::floor((s.max_fraction - s.min_fraction) / s.fraction_step + 1e-9));
    for (int k = 0; k <= steps; ++k) {
      PatternSpec spec;
      spec.kind = SurfaceKind::Random;
      // Rounded to 1e-9 so the pattern text is the fraction meant (0.85, not 0.8500000000000001).
      spec.groove_fraction = std::round((s.min_fraction + k * s.fraction_step) * 1e9) / 1e9;
      out.push_back(spec);
    }
  }
  return out;
}

// Equal keys are one surface. A random surface's mask differs per repetition: two fractions are
// one surface when they round to the same groove count, which is its key.
std::string mask_key(const PatternSpec& spec, const std::vector<std::uint8_t>& mask) {
  if (spec.kind != SurfaceKind::Random) return std::string(mask.begin(), mask.end());
  std::size_t grooves = 0;
  for (auto m : mask) grooves += m ? 0 : 1;
  return "random grooves " + std::to_string(grooves);
}

}  // namespace

std::string family_name(Family f) {
  switch (f) {
    case Family::Periodic: return "periodic";
    case Family::Hierarchical: return "hierarchical";
    case Family::Random: return "random";
    case Family::Given: return "given";
  }
  return "?";
}

Family parse_family(const std::string& text) {
  if (text == "periodic") return Family::Periodic;
  if (text == "hierarchical") return Family::Hierarchical;
  if (text == "random") return Family::Random;
  if (text == "given") return Family::Given;
  throw InputError("family", "'" + text + "' is not a family; expected periodic, hierarchical, random or given");
}

std::vector<PatternSpec> parse_candidates(const std::vector<std::string>& texts) {
  std::vector<PatternSpec> out;
  for (const auto& t : texts) {
    try {
      out.push_back(parse_pattern(t));
    } catch (const InputError& e) {
      throw InputError("candidates", "'" + t + "' is not a surface: " + e.what());
    }
  }
  return out;
}

void validate_given(const DesignSpace& s, const Scene& base) {
  for (PatternSpec spec : s.given) {
    spec.layout = base.pattern.layout;
    try {
      validate_surface(spec, base.geometry.N);
    } catch (const InputError& e) {
      throw InputError("candidates", pattern_label(spec) + " does not fit the chain: " + e.what());
    }
  }
}

void validate(const DesignSpace& s, int N) {
  const bool given = s.family == Family::Given;
  require(given == !s.given.empty(), "candidates",
          given ? "--family given needs the surfaces to choose among: --candidates PATTERN... (e.g. mask:@a.txt "
                  "periodic:3,1)"
                : "candidates are chosen among with --family given; the " + family_name(s.family) +
                      " family generates its own");
  require(s.given.size() <= 100000, "candidates", std::to_string(s.given.size()) + " given; at most 100000");
  if (s.family == Family::Periodic) check_range("min_np", s.min_np, "max_np", s.max_np, N);
  if (s.family == Family::Periodic || s.family == Family::Hierarchical)
    check_range("min_ng", s.min_ng, "max_ng", s.max_ng, N);
  if (s.family == Family::Hierarchical) {
    require(s.levels >= 1 && s.levels <= 8, "levels", std::to_string(s.levels) + " is outside [1, 8]");
    require(!s.factors.empty(), "factors", "no factor given; expected integers >= 2, e.g. 2,3,4");
    for (int f : s.factors) require(f >= 2 && f <= 1000, "factors", std::to_string(f) + " is outside [2, 1000]");
  }
  if (s.family == Family::Random) {
    require(s.min_fraction >= 0 && s.min_fraction < 1, "min_fraction", printed(s.min_fraction) + " is outside [0, 1)");
    require(s.max_fraction >= s.min_fraction && s.max_fraction < 1, "max_fraction",
            printed(s.max_fraction) + " is outside [min_fraction = " + printed(s.min_fraction) + ", 1)");
    require(s.fraction_step > 0 && s.fraction_step <= 1, "fraction_step", printed(s.fraction_step) + " is outside (0, 1]");
  }
  require(s.min_contact >= 0 && s.min_contact <= 1, "min_contact", printed(s.min_contact) + " is outside [0, 1]");
  require(s.max_contact >= s.min_contact && s.max_contact <= 1, "max_contact",
          printed(s.max_contact) + " is outside [min_contact = " + printed(s.min_contact) + ", 1]");
  require(s.min_feature >= 1 && s.min_feature <= N, "min_feature",
          std::to_string(s.min_feature) + " is outside [1, N = " + std::to_string(N) + "]");
}

int shortest_run(const std::vector<std::uint8_t>& mask) {
  int best = static_cast<int>(mask.size()), run = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    ++run;
    if (i + 1 == mask.size() || mask[i + 1] != mask[i]) {
      best = std::min(best, run);
      run = 0;
    }
  }
  return best;
}

CandidateSet generate(const DesignSpace& s, const Scene& base) {
  CandidateSet out;
  std::map<std::string, std::size_t> seen;  // mask key -> index into kept
  const int N = base.geometry.N;
  for (PatternSpec spec : specs(s)) {
    spec.layout = base.pattern.layout;
    ++out.generated;
    std::vector<std::uint8_t> mask;
    try {
      mask = build_contact_mask(spec, N, 0);  // random: one draw; its groove count is exact
    } catch (const InputError&) {
      ++out.dropped_contact;  // laid out on this chain, it leaves no block in contact
      continue;
    }
    Candidate c{spec, contact_fraction(mask), spec.kind == SurfaceKind::Random ? 1 : shortest_run(mask), 0};
    out.contact_lo = std::min(out.contact_lo, c.contact_fraction);
    out.contact_hi = std::max(out.contact_hi, c.contact_fraction);
    if (c.contact_fraction < s.min_contact || c.contact_fraction > s.max_contact) {
      ++out.dropped_contact;
      continue;
    }
    if (spec.kind != SurfaceKind::Random && c.min_feature < s.min_feature) {
      ++out.dropped_feature;
      continue;
    }
    const auto [it, fresh] = seen.emplace(mask_key(spec, mask), out.kept.size());
    if (!fresh) {
      ++out.dropped_duplicate;
      ++out.kept[it->second].duplicates;
      continue;
    }
    out.kept.push_back(c);
  }
  return out;
}

}  // namespace sb::design
