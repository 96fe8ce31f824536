#include "springblock/surface.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <system_error>

#include "springblock/errors.hpp"  // InputError, printed
#include "springblock/surface_mask.hpp"

namespace sb {
namespace {

constexpr const char* kGrammar =
    "expected smooth | periodic:NP,NG | hierarchical:G1,G2,... | random:FRACTION | mask:0110... | mask:@FILE "
    "(a hierarchical level may give pawl/groove sizes P/G: hierarchical:P1/G1,P2/G2,...)";
// Sizes are block counts; anything beyond this is certainly a typo and would only produce a
// confusing "exceeds N" later, or overflow in period arithmetic.
constexpr int kMaxSize = 1'000'000;
// Deeper hierarchies than this have no counterpart in the paper (which stops at 3) and would
// need blocks far smaller than any sensible discretisation.
constexpr std::size_t kMaxLevels = 8;

[[noreturn]] void fail(const std::string& what) {
  throw InputError("pattern", what + "; " + kGrammar);
}

// For errors where the spec is well formed but unusable with this chain; repeating the
// grammar there would suggest a syntax problem that does not exist.
[[noreturn]] void fail_plain(const std::string& what) { throw InputError("pattern", what); }

constexpr const char* kNoContact = "no block is left in contact; the surface cannot carry the load";

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto pos = s.find(sep, start);
    if (pos == std::string_view::npos) {
      out.push_back(s.substr(start));
      return out;
    }
    out.push_back(s.substr(start, pos - start));
    start = pos + 1;
  }
}

int parse_size(std::string_view tok, const std::string& spec) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...).
  const std::string quoted = std::string("'").append(tok).append("' in '").append(spec).append("'");
  if (tok.empty()) fail("missing number in '" + spec + "'");
  // from_chars on an int stops at '.', so "2.5" is caught as trailing text below, giving a
  // clear "not an integer" instead of silently truncating to 2.
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec == std::errc::result_out_of_range) fail("size " + quoted + " is too large (max 1000000)");
  if (ec != std::errc() || ptr != tok.data() + tok.size())
    fail("size " + quoted + " is not an integer");
  if (v <= 0) fail("size " + quoted + " must be a positive number of blocks");
  if (v > kMaxSize) fail("size " + quoted + " is too large (max 1000000)");
  return static_cast<int>(v);
}

// Portable uniform integer in [0, bound). std::uniform_int_distribution is allowed to differ
// between standard libraries, which would make a random surface depend on the toolchain; the
// mt19937_64 bit stream itself is fully specified, so we only need a specified reduction.
// Rejection of the lowest (2^64 mod bound) values removes the modulo bias exactly.
std::uint64_t bounded_draw(std::mt19937_64& rng, std::uint64_t bound) {
  const std::uint64_t threshold = (0 - bound) % bound;  // == 2^64 mod bound
  while (true) {
    const std::uint64_t x = rng();
    if (x >= threshold) return x % bound;
  }
}

// The phase of an alternation of `pawl` / `groove` blocks on a run of L blocks (see Layout).
int layout_phase(Layout rule, int pawl, int groove, int L) {
  const int period = pawl + groove;
  switch (rule) {
    case Layout::PawlFirst: return 0;
    case Layout::GrooveFirst: return pawl % period;
    case Layout::OneBased: return 1 % period;
    case Layout::Symmetric: break;
  }
  // The phase whose run is closest to its own mirror image; on a tie one that starts with a
  // pawl, then the smallest phase. The mismatch of block j with its mirror L-1-j repeats with
  // period `period` in j (both ends move one block per step), so the sum over the L/2 pairs is
  // (whole periods) x (one period's sum) + (the first `rest` terms): O(period^2) per level, not
  // O(period L), the same integers. `springblock pattern --N 1000000 --pattern hierarchical:8,4`
  // takes 20 ms of CPU this way (a smooth one 15 ms), 85 ms (22 ms) with the O(period L) sum.
  const int half = L / 2, whole = half / period, rest = half % period;
  int best = 0;
  long best_asym = -1;
  bool best_pawl = false;
  for (int ph = 0; ph < period; ++ph) {
    auto pawl_at = [&](int j) { return ((j + ph) % period) < pawl; };
    long one_period = 0, first_rest = 0;
    for (int j = 0; j < std::min(period, half); ++j) {
      const bool mismatch = pawl_at(j) != pawl_at(L - 1 - j);
      one_period += mismatch;
      if (j < rest) first_rest += mismatch;
    }
    const long asym = static_cast<long>(whole) * one_period + first_rest;
    const bool starts_pawl = pawl_at(0);
    if (best_asym < 0 || asym < best_asym || (asym == best_asym && starts_pawl && !best_pawl)) {
      best = ph, best_asym = asym, best_pawl = starts_pawl;
    }
  }
  return best;
}

// Marks blocks [begin, end) as alternating runs of `pawl` / `groove` blocks placed by `rule`.
// Used both for level 1 (over the whole surface) and for every later level (over each
// surviving pawl run), which is what makes the pattern self-similar.
void alternate(std::vector<std::uint8_t>& mask, int begin, int end, int pawl, int groove, Layout rule) {
  const int period = pawl + groove;
  const int phase = layout_phase(rule, pawl, groove, end - begin);
  for (int i = begin; i < end; ++i) mask[i] = ((i - begin + phase) % period) < pawl ? 1 : 0;
}

Layout layout_at(const PatternSpec& spec, std::size_t level) {
  return spec.layout.empty() ? Layout::PawlFirst : spec.layout[std::min(level, spec.layout.size() - 1)];
}

void check_spec(const PatternSpec& spec) {
  // A scene's spec may be hand-made, not parsed, so re-check what parse_pattern guarantees: a
  // zero size would make the period arithmetic divide by zero.
  switch (spec.kind) {
    case SurfaceKind::Smooth: return;
    case SurfaceKind::Periodic:
      if (spec.n_p < 1 || spec.n_g < 1 || spec.n_p > kMaxSize || spec.n_g > kMaxSize)
        fail("periodic sizes must be positive integers up to 1000000, got '" + spec.text() + "'");
      return;
    case SurfaceKind::Hierarchical:
      if (spec.levels.empty() || spec.levels.size() > kMaxLevels)
        fail("hierarchical needs 1 to 8 levels, got '" + spec.text() + "'");
      if (!spec.level_pawls.empty() && spec.level_pawls.size() != spec.levels.size())
        fail("hierarchical needs one pawl size per level or none, got " + std::to_string(spec.level_pawls.size()) +
             " pawl sizes for " + std::to_string(spec.levels.size()) + " levels");
      for (std::size_t k = 0; k < spec.levels.size(); ++k)
        if (spec.levels[k] < 1 || spec.levels[k] > kMaxSize || spec.pawl_size(k) < 1 || spec.pawl_size(k) > kMaxSize)
          fail("hierarchical sizes must be positive integers up to 1000000, got '" + spec.text() +
               "'");
      return;
    case SurfaceKind::Random:
      if (!(spec.groove_fraction >= 0.0 && spec.groove_fraction < 1.0))
        fail("random groove fraction must be in [0,1), got '" + spec.text() + "'");
      return;
    case SurfaceKind::Mask: check_mask_blocks(spec.mask); return;
  }
  fail("unknown surface kind");
}

// Every size of the pattern must fit on the chain; a larger one is a typo or a wrong N.
void check_sizes_fit(const PatternSpec& spec, int N) {
  std::vector<int> sizes;
  if (spec.kind == SurfaceKind::Periodic) sizes = {spec.n_p, spec.n_g};
  if (spec.kind == SurfaceKind::Hierarchical) {
    sizes = spec.levels;
    sizes.insert(sizes.end(), spec.level_pawls.begin(), spec.level_pawls.end());
  }
  for (int size : sizes)
    if (size > N)
      fail_plain("size " + std::to_string(size) + " in '" + spec.text() + "' exceeds the number of blocks N=" +
                 std::to_string(N) + "; allowed sizes are [1, " + std::to_string(N) + "]");
}

// Level 1 alternates over the whole chain; each finer level subdivides every maximal pawl run
// the levels above left. Grooves are never touched again: a finer level only removes contact.
// Unequal pawl and groove sizes change only the period and the pawl's share of it: the layout
// rules place them as they place a periodic surface's n_p and n_g.
void lay_hierarchy(std::vector<std::uint8_t>& mask, const PatternSpec& spec) {
  const int N = static_cast<int>(mask.size());
  alternate(mask, 0, N, spec.pawl_size(0), spec.levels[0], layout_at(spec, 0));
  for (std::size_t k = 1; k < spec.levels.size(); ++k) {
    const int p = spec.pawl_size(k), g = spec.levels[k];
    int i = 0;
    while (i < N) {
      if (!mask[i]) {
        ++i;
        continue;
      }
      int j = i;
      while (j < N && mask[j]) ++j;
      alternate(mask, i, j, p, g, layout_at(spec, k));
      i = j;
    }
  }
}

long long random_groove_count(const PatternSpec& spec, int N) {
  // std::llround rounds halves away from zero, independent of the FP rounding mode.
  return std::llround(spec.groove_fraction * static_cast<double>(N));
}

// `grooves` blocks drawn without replacement from `seed`. Partial Fisher-Yates: after step i the
// prefix idx[0..i] is a uniform sample without replacement, so only `grooves` draws are needed.
void draw_grooves(std::vector<std::uint8_t>& mask, long long grooves, std::uint64_t seed) {
  const int N = static_cast<int>(mask.size());
  std::vector<int> idx(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) idx[i] = i;
  std::mt19937_64 rng(seed);
  for (long long i = 0; i < grooves && i < N; ++i) {
    const auto j = i + static_cast<long long>(bounded_draw(rng, static_cast<std::uint64_t>(N - i)));
    std::swap(idx[i], idx[j]);
    mask[idx[i]] = 0;
  }
}

}  // namespace

std::string PatternSpec::text() const {
  switch (kind) {
    case SurfaceKind::Smooth: return "smooth";
    case SurfaceKind::Periodic:
      return "periodic:" + std::to_string(n_p) + "," + std::to_string(n_g);
    case SurfaceKind::Hierarchical: {
      // A level whose pawl equals its groove is written G alone, so the P/G form of an
      // equal-size hierarchy has the G1,G2,... form's text (and shares its runs).
      std::string s = "hierarchical:";
      for (std::size_t i = 0; i < levels.size(); ++i) {
        if (i) s += ',';
        if (pawl_size(i) != levels[i]) s += std::to_string(pawl_size(i)) + "/";
        s += std::to_string(levels[i]);
      }
      return s;
    }
    case SurfaceKind::Mask: return mask_path.empty() ? "mask:" + mask_digits(mask) : "mask:@" + mask_path;
    case SurfaceKind::Random: {
      // Shortest round-trip form, so parse_pattern(spec.text()) reproduces the same double and
      // therefore the same groove count; std::to_string would round to 6 decimals.
      std::array<char, 64> buf{};
      const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), groove_fraction);
      return "random:" + std::string(buf.data(), res.ptr);
    }
  }
  return "?";
}

int PatternSpec::pawl_size(std::size_t level) const {
  return level < level_pawls.size() ? level_pawls[level] : levels.at(level);
}

std::string layout_name(Layout l) {
  switch (l) {
    case Layout::PawlFirst: return "pawl_first";
    case Layout::Symmetric: return "symmetric";
    case Layout::GrooveFirst: return "groove_first";
    case Layout::OneBased: return "one_based";
  }
  return "?";
}

std::string PatternSpec::layout_text() const {
  std::string s;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    if (i) s += ',';
    s += layout_name(layout[i]);
  }
  return s;
}

std::vector<Layout> parse_layout(const std::string& text) {
  std::vector<Layout> out;
  for (auto tok : split(text, ',')) {
    bool found = false;
    for (Layout l : {Layout::PawlFirst, Layout::Symmetric, Layout::GrooveFirst, Layout::OneBased})
      if (tok == layout_name(l)) out.push_back(l), found = true;
    if (!found) {
      std::string what = "'";
      what.append(tok).append("' in '").append(text).append(
          "' is not one of: pawl_first, symmetric, groove_first, one_based (one per level, comma separated; "
          "the last holds for deeper levels)");
      throw InputError("layout", what);
    }
  }
  if (out.size() > kMaxLevels)
    throw InputError("layout", "at most " + std::to_string(kMaxLevels) + " levels, got '" + text + "'");
  return out;
}

namespace {

// The levels of hierarchical:G1,G2,... or hierarchical:P1/G1,P2/G2,... (forms may be mixed).
PatternSpec parse_hierarchical(std::string_view args, const std::string& spec) {
  const auto toks = split(args, ',');
  if (toks.size() > kMaxLevels)
    fail("'hierarchical' allows at most 8 levels, got " + std::to_string(toks.size()) + " in '" + spec + "'");
  PatternSpec out;
  out.kind = SurfaceKind::Hierarchical;
  // Non-decreasing levels are deliberately accepted: they are well defined (a level larger
  // than the pawl runs it subdivides leaves them untouched) and rejecting them would forbid
  // legitimate parameter sweeps that cross over.
  std::vector<int> pawls;
  for (auto t : toks) {
    const auto parts = split(t, '/');
    if (parts.size() > 2)
      fail("level '" + std::string(t) + "' in '" + spec + "' must be G (pawl = groove) or P/G (pawl/groove sizes)");
    out.levels.push_back(parse_size(parts.back(), spec));
    pawls.push_back(parts.size() == 2 ? parse_size(parts[0], spec) : out.levels.back());
  }
  // Kept only when some level differs: the equal-size spec is one spec whichever form gave it.
  if (pawls != out.levels) out.level_pawls = pawls;
  return out;
}

}  // namespace

PatternSpec parse_pattern(const std::string& spec) {
  const std::string_view s = spec;
  const auto colon = s.find(':');
  const std::string_view kind = s.substr(0, colon);
  const std::string_view args =
      colon == std::string_view::npos ? std::string_view{} : s.substr(colon + 1);
  const bool has_args = colon != std::string_view::npos;

  PatternSpec out;
  if (kind == "smooth") {
    if (has_args) fail("'smooth' takes no numbers, got '" + spec + "'");
    out.kind = SurfaceKind::Smooth;
    return out;
  }
  if (kind == "periodic") {
    if (!has_args) fail("'periodic' needs two numbers NP,NG, got '" + spec + "'");
    const auto toks = split(args, ',');
    if (toks.size() != 2)
      fail("'periodic' needs exactly two numbers NP,NG, got " + std::to_string(toks.size()) +
           " in '" + spec + "'");
    out.kind = SurfaceKind::Periodic;
    out.n_p = parse_size(toks[0], spec);
    out.n_g = parse_size(toks[1], spec);
    return out;
  }
  if (kind == "hierarchical") {
    if (!has_args) fail("'hierarchical' needs at least one groove size, got '" + spec + "'");
    return parse_hierarchical(args, spec);
  }
  if (kind == "mask") return parse_mask_pattern(args, spec);
  if (kind == "random") {
    if (!has_args || args.empty()) fail("'random' needs a groove fraction, got '" + spec + "'");
    if (args.find(',') != std::string_view::npos)
      fail("'random' takes exactly one number, got '" + spec + "'");
    double f = 0.0;
    const auto [ptr, ec] = std::from_chars(args.data(), args.data() + args.size(), f);
    if (ec != std::errc() || ptr != args.data() + args.size())
      fail("groove fraction '" + std::string(args) + "' in '" + spec + "' is not a number");
    // Written as a negated range test so NaN (which from_chars accepts) is rejected too.
    if (!(f >= 0.0 && f < 1.0))
      fail("groove fraction '" + std::string(args) + "' in '" + spec + "' must be in [0,1)");
    out.kind = SurfaceKind::Random;
    out.groove_fraction = f;
    return out;
  }
  fail("unknown pattern kind '" + std::string(kind) + "' in '" + spec + "'");
}

void validate_surface(const PatternSpec& spec, int N) {
  if (N < 1) fail_plain("the chain needs at least one block, got N=" + std::to_string(N) + " (allowed N >= 1)");
  check_spec(spec);
  if (spec.kind == SurfaceKind::Mask) return check_mask_length(spec, N);
  check_sizes_fit(spec, N);
  if (spec.kind == SurfaceKind::Random) {
    // The groove count is fixed by the fraction (only which blocks is drawn), so one check holds
    // for every repetition's draw.
    if (random_groove_count(spec, N) >= N)
      fail_plain(std::string(kNoContact) + ": " + spec.text() + " on N = " + std::to_string(N) +
                 " leaves no block in contact (allowed groove fractions [0, " +
                 printed((N - 0.5) / N) + "))");
    return;
  }
  // Pattern and layout alone decide a deterministic mask: building it once shows whether a layout
  // that starts with a groove leaves a short chain without contact.
  const auto mask = contact_mask(spec, N, 0);
  if (std::find(mask.begin(), mask.end(), std::uint8_t{1}) == mask.end())
    fail_plain(std::string(kNoContact) + " ('" + spec.text() + "' laid out " + spec.layout_text() +
               " on N = " + std::to_string(N) + ")");
}

std::vector<std::uint8_t> build_contact_mask(const PatternSpec& spec, int N, std::uint64_t seed) {
  validate_surface(spec, N);
  return contact_mask(spec, N, seed);
}

std::vector<std::uint8_t> contact_mask(const PatternSpec& spec, int N, std::uint64_t seed) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(N), 1);
  switch (spec.kind) {
    case SurfaceKind::Smooth: break;
    case SurfaceKind::Periodic: alternate(mask, 0, N, spec.n_p, spec.n_g, layout_at(spec, 0)); break;
    case SurfaceKind::Hierarchical: lay_hierarchy(mask, spec); break;
    case SurfaceKind::Random: draw_grooves(mask, random_groove_count(spec, N), seed); break;
    case SurfaceKind::Mask: mask = spec.mask; break;
  }
  return mask;
}

double contact_fraction(const std::vector<std::uint8_t>& mask) {
  if (mask.empty()) return 0.0;
  std::size_t c = 0;
  for (auto m : mask) c += m ? 1 : 0;
  return static_cast<double>(c) / static_cast<double>(mask.size());
}

}  // namespace sb
