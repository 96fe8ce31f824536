// Inverse design (src/springblock/design): the target grammar and the meets-target rule, and
// the exact pruning of the candidate space (constraints from the mask, one candidate per mask).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "springblock/design/space.hpp"
#include "springblock/design/target.hpp"
#include "springblock/errors.hpp"
#include "springblock/scene.hpp"

namespace {

using namespace sb::design;

TEST(DesignTarget, IntervalForms) {
  const auto point = parse_interval("target_mu_s", "0.65");
  EXPECT_EQ(point.lo, 0.65);
  EXPECT_EQ(point.hi, 0.65);
  const auto range = parse_interval("target_mu_s", "0.6:0.7");
  EXPECT_EQ(range.lo, 0.6);
  EXPECT_EQ(range.hi, 0.7);
  EXPECT_TRUE(std::isinf(parse_interval("target_mu_d", ">=0.52").hi));
  EXPECT_TRUE(std::isinf(parse_interval("target_mu_d", "<=0.5").lo));
  for (const char* bad : {"abc", "0.7:0.6", "-0.1", "11", ">=x", ""}) {
    try {
      parse_interval("target_ratio", bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const sb::InputError& e) {
      EXPECT_EQ(e.field, "target_ratio");
    }
  }
}

TEST(DesignTarget, MeetsRuleIsTwoStandardErrors) {
  const auto t = parse_interval("target_mu_s", "0.65");
  sb::Statistic s;
  s.mean = 0.66, s.sem = 0.005, s.n = 10;  // exactly 2 SEM away: met
  EXPECT_TRUE(meets(t, s));
  s.sem = 0.0049;  // just beyond 2 SEM: not met
  EXPECT_FALSE(meets(t, s));
  s.n = 0;  // nothing measured never meets
  EXPECT_FALSE(meets(t, s));
  EXPECT_TRUE(meets(Interval{}, s));  // no interval: nothing to meet
}

TEST(DesignTarget, ScoreRanksInsideBeforeOutsideWithAGoal) {
  Target t;
  t.mu_d = parse_interval("target_mu_d", ">=0.52");
  t.goal = Goal::Minimise;
  t.objective = Quantity::MuS;
  // Inside the mu_d interval with a high mu_s beats outside it with a low one.
  EXPECT_LT(score(t, 0.9, 0.53), score(t, 0.5, 0.519));
  EXPECT_LT(score(t, 0.6, 0.53), score(t, 0.7, 0.53));
  EXPECT_TRUE(std::isinf(score(t, std::nan(""), 0.53)));
}

TEST(DesignSpace, ShortestRun) {
  EXPECT_EQ(shortest_run({1, 1, 0, 0, 0, 1, 1}), 2);
  EXPECT_EQ(shortest_run({1, 1, 1}), 3);
  EXPECT_EQ(shortest_run({0, 1, 1, 0, 0}), 1);
}

TEST(DesignSpace, OneCandidatePerMaskAndConstraintsFromTheMask) {
  sb::Scene base;
  base.geometry.N = 12;
  DesignSpace s;
  s.max_np = 12, s.max_ng = 12;  // pawls or grooves of up to the whole chain: many equal masks
  const auto all = generate(s, base);
  EXPECT_EQ(all.generated, 144);
  EXPECT_GT(all.dropped_duplicate, 0);
  std::set<std::string> masks;  // as text: GCC 12 warns falsely on sets of byte vectors
  int specs = 0;
  for (const auto& c : all.kept) {
    const auto m = sb::build_contact_mask(c.spec, 12, 0);
    EXPECT_TRUE(masks.insert(std::string(m.begin(), m.end())).second) << c.spec.text();
    specs += 1 + c.duplicates;
  }
  EXPECT_EQ(specs + all.dropped_contact + all.dropped_feature, all.generated);
  s.min_contact = 0.5, s.min_feature = 2;
  const auto constrained = generate(s, base);
  EXPECT_GT(constrained.dropped_contact, 0);
  EXPECT_GT(constrained.dropped_feature, 0);
  for (const auto& c : constrained.kept) {
    EXPECT_GE(c.contact_fraction, 0.5);
    EXPECT_GE(c.min_feature, 2);
  }
}

TEST(DesignSpace, BadBoundsNameTheField) {
  DesignSpace s;
  s.min_np = 5, s.max_np = 3;
  try {
    validate(s, 60);
    ADD_FAILURE() << "an empty n_p range was accepted";
  } catch (const sb::InputError& e) {
    EXPECT_EQ(e.field, "max_np");
  }
  s = DesignSpace{};
  s.max_ng = 61;
  EXPECT_THROW(validate(s, 60), sb::InputError);
}

}  // namespace
