// A scene's surface is checked once, by validate(Scene), with an InputError on field "pattern"
// that names the allowed range; the masks of its repetitions are then built without checks
// (contact_mask), and they are the masks the checked builder gives.
#include <gtest/gtest.h>

#include <string>

#include "springblock/errors.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"

using namespace sb;

namespace {

// The message of the InputError validate() raises for `pattern` on N blocks.
std::string refusal(const std::string& pattern, const std::string& N, const std::string& layout = "") {
  Scene s;
  set_scene_field(s, "N", N);
  set_scene_field(s, "pattern", pattern);
  if (!layout.empty()) set_scene_field(s, "layout", layout);
  try {
    validate(s);
  } catch (const InputError& e) {
    EXPECT_EQ(e.field, "pattern");
    return e.what();
  }
  ADD_FAILURE() << pattern << " on N = " << N << " was accepted";
  return {};
}

TEST(SurfaceValidation, SizeAboveNNamesTheAllowedRange) {
  EXPECT_NE(refusal("periodic:20,5", "10").find("allowed sizes are [1, 10]"), std::string::npos);
  EXPECT_NE(refusal("hierarchical:4,16", "10").find("allowed sizes are [1, 10]"), std::string::npos);
}

TEST(SurfaceValidation, RandomWithoutContactNamesTheAllowedFractions) {
  const auto msg = refusal("random:0.99", "10");
  EXPECT_NE(msg.find("no block in contact"), std::string::npos) << msg;
  EXPECT_NE(msg.find("allowed groove fractions [0, 0.95)"), std::string::npos) << msg;
}

TEST(SurfaceValidation, LayoutLeavingNoContactIsRefused) {
  // periodic:2,3 laid out groove_first on 3 blocks: the first period's grooves cover the chain.
  const auto msg = refusal("periodic:2,3", "3", "groove_first");
  EXPECT_NE(msg.find("no block is left in contact"), std::string::npos) << msg;
}

}  // namespace
