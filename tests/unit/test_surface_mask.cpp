// Surfaces given block by block (mask:0110..., mask:@FILE): the parsers, their refusals and what
// they say, the checks against N, the hash that ties a result to its blocks, and the key scenes
// share runs on (the blocks, never the file's name).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "springblock/errors.hpp"
#include "springblock/fnv1a.hpp"
#include "springblock/scene.hpp"
#include "springblock/surface.hpp"
#include "springblock/surface_mask.hpp"
#include "springblock/trajectory_spec.hpp"

namespace {

using sb::parse_pattern;
using Mask = std::vector<std::uint8_t>;

// A file under the test's temporary directory holding `text`; its path.
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + "springblock_mask_" + name;
  std::ofstream(path) << text;
  return path;
}

// The message of the InputError `spec` raises (on a chain of N), or "" when it is accepted.
std::string refusal(const std::string& spec, int N = 4) {
  try {
    sb::build_contact_mask(parse_pattern(spec), N);
  } catch (const sb::InputError& e) {
    EXPECT_EQ(e.field, "pattern") << spec;
    return e.what();
  }
  return "";
}

void expect_refused(const std::string& spec, int N, const std::vector<std::string>& words) {
  const auto msg = refusal(spec, N);
  ASSERT_FALSE(msg.empty()) << spec << " was accepted";
  for (const auto& w : words) EXPECT_NE(msg.find(w), std::string::npos) << spec << ": '" << w << "' not in: " << msg;
}

TEST(MaskParse, InlineMaskIsItsBlocks) {
  const auto p = parse_pattern("mask:0110");
  EXPECT_EQ(p.kind, sb::SurfaceKind::Mask);
  EXPECT_EQ(p.mask, (Mask{0, 1, 1, 0}));
  EXPECT_TRUE(p.mask_path.empty());
  EXPECT_EQ(p.text(), "mask:0110");
  EXPECT_EQ(parse_pattern(p.text()).mask, p.mask);
  EXPECT_EQ(sb::build_contact_mask(p, 4), p.mask);
  // No layout applies to a mask: every rule gives its blocks.
  for (auto rule : {sb::Layout::PawlFirst, sb::Layout::Symmetric, sb::Layout::GrooveFirst, sb::Layout::OneBased}) {
    auto q = p;
    q.layout = {rule};
    EXPECT_EQ(sb::build_contact_mask(q, 4), p.mask);
  }
}

TEST(MaskParse, FileSkipsWhitespaceAndCommentLines) {
  const auto path = write_file("comments.txt",
                               "# a surface of 10 blocks\n"
                               "  01 10\n"
                               "\n"
                               "\t # an indented comment: 1111 is not read\n"
                               "0\t1\r\n"
                               "1 0 0 1");
  const auto p = parse_pattern("mask:@" + path);
  EXPECT_EQ(p.mask, (Mask{0, 1, 1, 0, 0, 1, 1, 0, 0, 1}));
  EXPECT_EQ(p.mask_path, path);
  EXPECT_EQ(p.text(), "mask:@" + path);
  EXPECT_EQ(parse_pattern(p.text()).mask, p.mask);  // the round trip reads the file again
}

TEST(MaskParse, InlineRefusalsNameTheFieldAndThePosition) {
  expect_refused("mask:01x0", 4, {"character 3 of 4 is 'x'", "only 0 (groove) and 1 (pawl)"});
  expect_refused("mask:01 0", 4, {"character 3 of 4 is ' '"});
  expect_refused("mask:012", 3, {"character 3 of 3 is '2'"});
  expect_refused("mask:", 4, {"empty mask", "mask:0110"});
  expect_refused("mask:0000", 4, {"no block in contact", "at least one 1"});
  expect_refused("mask:" + std::string(1000001, '1'), 4, {"more than 1000000 blocks"});
}

TEST(MaskParse, FileRefusalsNameThePathLineAndColumn) {
  const auto bad = write_file("bad.txt", "# header\n0110\n01a1\n");
  expect_refused("mask:@" + bad, 8, {"mask file '" + bad + "' line 3, column 3", "'a' is not 0 or 1"});
  const auto hash_inside = write_file("hash.txt", "0110 # not a comment here\n");
  expect_refused("mask:@" + hash_inside, 4, {"line 1, column 6", "'#'"});
  const auto empty = write_file("empty.txt", "# nothing but a comment\n\n  \n");
  expect_refused("mask:@" + empty, 4, {"'" + empty + "' holds no 0 or 1"});
  const auto grooves = write_file("grooves.txt", "000\n0\n");
  expect_refused("mask:@" + grooves, 4, {"no block in contact"});
  const std::string missing = testing::TempDir() + "springblock_mask_no_such_file.txt";
  expect_refused("mask:@" + missing, 4, {"cannot read mask file '" + missing + "'"});
  expect_refused("mask:@", 4, {"names no file"});
}

TEST(MaskParse, LengthMustEqualN) {
  expect_refused("mask:0110", 5, {"the mask has 4 blocks", "N = 5", "must equal N"});
  const auto path = write_file("six.txt", "011110\n");
  expect_refused("mask:@" + path, 4, {"'" + path + "' has 6 blocks", "N = 4"});
  EXPECT_EQ(refusal("mask:0110", 4), "");
}

TEST(MaskParse, HandMadeSpecsAreCheckedToo) {
  sb::PatternSpec p;
  p.kind = sb::SurfaceKind::Mask;
  EXPECT_THROW(sb::validate_surface(p, 1), sb::InputError);  // no blocks
  p.mask = {1, 2};
  EXPECT_THROW(sb::validate_surface(p, 2), sb::InputError);  // an entry that is not 0/1
  p.mask = {1, 0};
  EXPECT_NO_THROW(sb::validate_surface(p, 2));
}

TEST(MaskRecord, HashIsFnv1aOfTheDigits) {
  // 64-bit FNV-1a (offset basis 14695981039346656037) of the four bytes "0110", worked out apart
  // from this code; and the published test vector FNV-1a 64("a") = af63dc4c8601ec8c.
  EXPECT_EQ(sb::mask_hash({0, 1, 1, 0}), "b999a0f9e6825b73");
  sb::Fnv1a64 a;
  a.add("a");
  EXPECT_EQ(a.hex(), "af63dc4c8601ec8c");
  EXPECT_EQ(sb::mask_digits({0, 1, 1, 0}), "0110");
  EXPECT_NE(sb::mask_hash({0, 1, 1, 0}), sb::mask_hash({0, 1, 1, 1}));
}

TEST(MaskRecord, LongMasksAreLabelledByTheirNumbers) {
  const auto p = parse_pattern("mask:" + std::string(50, '1'));
  const auto label = sb::pattern_label(p);
  EXPECT_NE(label.find("50 blocks, 50 in contact, fnv1a64 " + sb::mask_hash(p.mask)), std::string::npos) << label;
  EXPECT_EQ(sb::pattern_label(parse_pattern("mask:0110")), "mask:0110");
  EXPECT_EQ(sb::pattern_label(parse_pattern("periodic:2,1")), "periodic:2,1");
}

// Scenes share runs by their trajectory spec: a file and an inline mask of the same blocks are
// one surface; the same file name with other blocks is another.
TEST(MaskRecord, RunsAreSharedOnTheBlocksNotTheFileName) {
  const auto path = write_file("shared.txt", "0110\n");
  sb::Scene inline_scene, file_scene;
  inline_scene.geometry.N = file_scene.geometry.N = 4;
  inline_scene.pattern = parse_pattern("mask:0110");
  file_scene.pattern = parse_pattern("mask:@" + path);
  EXPECT_EQ(*sb::trajectory_spec(inline_scene), *sb::trajectory_spec(file_scene));
  write_file("shared.txt", "1110\n");
  sb::Scene edited = file_scene;
  edited.pattern = parse_pattern("mask:@" + path);
  EXPECT_EQ(edited.pattern.text(), file_scene.pattern.text());
  EXPECT_NE(*sb::trajectory_spec(edited), *sb::trajectory_spec(file_scene));
}

}  // namespace
