// A worker rank taken for dead (parallel/liveness.hpp, Dealer::reclaim): silence beyond the limit
// and only that marks a rank dead, each once; its units go back to the front of the queue and are
// dealt again; a late record from it is dropped, so every unit is counted exactly once.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "springblock/parallel/dealer.hpp"
#include "springblock/parallel/liveness.hpp"

using namespace sb::parallel;

TEST(Liveness, SilenceBeyondTheLimitAndOnlyThatIsDeath) {
  Liveness live(4, 2.0, 100.0);
  live.heard(1, 101.5);
  live.heard(2, 100.5);
  EXPECT_TRUE(live.newly_dead(102.0).empty());  // nobody silent more than 2 s yet
  EXPECT_EQ(live.newly_dead(102.6), (std::vector<int>{2, 3}));
  EXPECT_TRUE(live.dead(2));
  EXPECT_FALSE(live.dead(1));
  EXPECT_TRUE(live.newly_dead(102.7).empty());  // each death is reported once
  live.forget(1);                               // retired: silence is no longer death
  EXPECT_TRUE(live.newly_dead(200.0).empty());
  EXPECT_FALSE(live.dead(1));
  EXPECT_FALSE(live.dead(0));  // the coordinator is never watched
}

TEST(Liveness, HeartbeatLetsFourBeatsGoMissingBeforeDeath) {
  EXPECT_DOUBLE_EQ(heartbeat_s(2.0), 0.5);
  EXPECT_DOUBLE_EQ(heartbeat_s(60.0), 1.0);  // at most a second
  EXPECT_THROW(Liveness(2, 0.0, 0.0), std::invalid_argument);
}

TEST(Dealer, ADeadRanksUnitsAreDealtAgainAndCountedOnce) {
  std::map<int, int> counted;  // unit -> how many records were taken for it
  Hooks hooks;
  hooks.finished = [&](int id, int, nlohmann::json) { ++counted[id]; };
  Dealer dealer({10, 11, 12, 13, 14}, hooks, nullptr);
  EXPECT_EQ(dealer.next_batch(1, 2), (std::vector<int>{10, 11}));
  EXPECT_EQ(dealer.next_batch(2, 1), (std::vector<int>{12}));
  EXPECT_TRUE(dealer.finished(10, 1, "r10"));
  EXPECT_EQ(dealer.reclaim(1), (std::vector<int>{11}));  // rank 1 dies holding unit 11
  EXPECT_EQ(dealer.queued(), 3);
  EXPECT_EQ(dealer.next_batch(2, 1), (std::vector<int>{11}));  // first in line again
  EXPECT_FALSE(dealer.finished(11, 1, "late r11"));             // rank 1 no longer holds it
  EXPECT_TRUE(dealer.finished(11, 2, "r11"));
  EXPECT_FALSE(dealer.finished(11, 2, "r11 again"));
  EXPECT_TRUE(dealer.finished(12, 2, "r12"));
  EXPECT_EQ(counted, (std::map<int, int>{{10, 1}, {11, 1}, {12, 1}}));
  EXPECT_TRUE(dealer.reclaim(3).empty());
}
