// Hierarchical surfaces with unequal pawl and groove sizes (hierarchical:P1/G1,P2/G2,...): masks
// worked out by hand from the layout rule (surface.hpp, Layout), the equal-size form's meaning
// kept exactly, and the refusals of malformed or out-of-range sizes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "springblock/errors.hpp"
#include "springblock/surface.hpp"

namespace {

using sb::Layout;

// The mask as 0/1 characters, the way the expectations below are written; or, for a layout that
// leaves no block in contact, the refusal's message (which two forms of one spec must share too).
std::string mask_of(const std::string& spec, int N, std::vector<Layout> layout = sb::PatternSpec{}.layout) {
  auto p = sb::parse_pattern(spec);
  p.layout = std::move(layout);
  std::string s;
  try {
    for (auto m : sb::build_contact_mask(p, N)) s += m ? '1' : '0';
  } catch (const sb::InputError& e) {
    return e.what();
  }
  return s;
}

// Level 1 with p = 2 pawls, g = 1 groove on 12 blocks: block j is a pawl iff (j + phase) mod 3 < 2.
// pawl_first (phase 0): 110 repeated. groove_first (phase p = 2): 011 repeated. symmetric: of the
// phases 0, 1, 2 only phase 1 (101101101101) reads the same backwards.
TEST(UnequalHierarchy, OneLevelByHand) {
  EXPECT_EQ(mask_of("hierarchical:2/1", 12, {Layout::PawlFirst}), "110110110110");
  EXPECT_EQ(mask_of("hierarchical:2/1", 12, {Layout::GrooveFirst}), "011011011011");
  EXPECT_EQ(mask_of("hierarchical:2/1", 12, {Layout::OneBased}), "101101101101");
  EXPECT_EQ(mask_of("hierarchical:2/1", 12), "101101101101");
  // The same surface as periodic:2,1: a one-level hierarchy is a periodic surface.
  EXPECT_EQ(mask_of("hierarchical:2/1", 12, {Layout::PawlFirst}), mask_of("periodic:2,1", 12, {Layout::PawlFirst}));
}

// Level 1, 4 pawls / 2 grooves, symmetric on 12 blocks: of the period-6 phases, 2 and 5 are mirror
// images of themselves and 2 starts with a pawl: 110011110011 (pawl runs [0,2), [4,8), [10,12)).
// Level 2, pawl_first on each run: 1/1 gives 10 | 1010 | 10, and 2/1 gives 11 | 1101 | 11.
TEST(UnequalHierarchy, TwoLevelsByHand) {
  EXPECT_EQ(mask_of("hierarchical:4/2", 12), "110011110011");
  EXPECT_EQ(mask_of("hierarchical:4/2,1/1", 12), "100010100010");
  EXPECT_EQ(mask_of("hierarchical:4/2,1", 12), "100010100010");
  EXPECT_EQ(mask_of("hierarchical:4/2,2/1", 12), "110011010011");
  // Level 2 groove first on the same runs (phase p = 2 of period 3): 01 | 0110 | 01.
  EXPECT_EQ(mask_of("hierarchical:4/2,2/1", 12, {Layout::Symmetric, Layout::GrooveFirst}), "010001100001");
}

// The equal-size form keeps its meaning: P/G with P = G at every level is the same spec (same
// text, so the same runs are shared) and gives the same mask under every layout.
TEST(UnequalHierarchy, EqualSizesAreTheOldForm) {
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"hierarchical:8,2", "hierarchical:8/8,2/2"},
      {"hierarchical:8,2", "hierarchical:8/8,2"},
      {"hierarchical:30", "hierarchical:30/30"},
      {"hierarchical:24,8,1", "hierarchical:24/24,8/8,1/1"}};
  const std::vector<Layout> rules = {Layout::PawlFirst, Layout::Symmetric, Layout::GrooveFirst, Layout::OneBased};
  std::vector<std::vector<Layout>> layouts = {sb::PatternSpec{}.layout};
  for (auto a : rules) {
    layouts.push_back({a});
    for (auto b : rules) layouts.push_back({a, b});
  }
  for (const auto& [equal, pg] : pairs) {
    const auto p = sb::parse_pattern(pg);
    EXPECT_EQ(p.text(), equal);
    EXPECT_TRUE(p.level_pawls.empty()) << pg;
    EXPECT_EQ(p.levels, sb::parse_pattern(equal).levels);
    for (int N : {30, 37, 100, 360})
      for (const auto& layout : layouts) EXPECT_EQ(mask_of(equal, N, layout), mask_of(pg, N, layout)) << pg << " N=" << N;
  }
}

TEST(UnequalHierarchy, TextRoundTrips) {
  for (const std::string t : {"hierarchical:6/4,2/1", "hierarchical:10,3/1", "hierarchical:1/9,8/2,3"}) {
    EXPECT_EQ(sb::parse_pattern(t).text(), t);
    EXPECT_EQ(sb::parse_pattern(sb::parse_pattern(t).text()).text(), t);
  }
  const auto p = sb::parse_pattern("hierarchical:6/4,2");
  EXPECT_EQ(p.levels, (std::vector<int>{4, 2}));
  EXPECT_EQ(p.level_pawls, (std::vector<int>{6, 2}));
}

TEST(UnequalHierarchy, BadSizesAreRefusedNamingThem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"hierarchical:0/2", "must be a positive number"},
      {"hierarchical:2/0", "must be a positive number"},
      {"hierarchical:-1/2", "must be a positive number"},
      {"hierarchical:2/1000001", "too large (max 1000000)"},
      {"hierarchical:a/2", "not an integer"},
      {"hierarchical:/2", "missing number"},
      {"hierarchical:2/", "missing number"},
      {"hierarchical:2//1", "must be G (pawl = groove) or P/G"},
      {"hierarchical:2/1/1", "must be G (pawl = groove) or P/G"},
      {"hierarchical:20/2", "size 20"},
      {"hierarchical:2/20", "size 20"}};
  for (const auto& [spec, words] : cases) {
    try {
      sb::build_contact_mask(sb::parse_pattern(spec), 10);
      ADD_FAILURE() << spec << " was accepted";
    } catch (const sb::InputError& e) {
      EXPECT_EQ(e.field, "pattern");
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << spec << ": " << e.what();
    }
  }
  sb::PatternSpec hand;  // made by hand: one pawl size for two levels
  hand.kind = sb::SurfaceKind::Hierarchical;
  hand.levels = {4, 2};
  hand.level_pawls = {3};
  EXPECT_THROW(sb::validate_surface(hand, 12), sb::InputError);
}

}  // namespace
