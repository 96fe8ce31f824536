#pragma once
// The next exact event of the active set: per block, the time of its next closed-form or modal
// event (a stuck block's threshold crossing, a modal block's stop), or where a modal search was
// cut off (a "recheck": not an event, the search continues from there when it comes up).
//
// Two tournament trees over the blocks (earliest entry; earliest real event, rechecks
// excluded) are brought up to date for the blocks whose time changed since the last refresh:
// O(changed log N) per switch, not O(N). Ties go as a full scan in block order would take them:
// earliest t, then a real event before a recheck, then the lower block.
//
// Each node holds its winner's whole sort key, (t, recheck, block) packed into one 128-bit
// integer whose order is that order, both trees' keys side by side: a level of a climb reads two
// adjacent 32-byte nodes and takes two integer minima, with no look-up of the winners' times and
// no data-dependent branch (the winner is one of two children, which a branch predictor guesses
// half the time wrong). offer() compares by the same keys, so the order is written once.
#include <cstdint>
#include <vector>

#include "springblock/integrate/block_set.hpp"

namespace sb::event_detail {

class EventQueue {
 public:
  struct Next {
    double t;      // earliest entry (infinity if none)
    int block;     // its block (lowest index on a tie), -1 if none
    bool recheck;  // not an event: a modal search was cut off here
  };

  explicit EventQueue(int N);

  // Every write of an event time goes through here (marks the block for refresh()).
  void set(int i, double t, bool recheck);
  double time(int i) const { return t_[i]; }
  bool is_recheck(int i) const { return recheck_[i] != 0; }  // block i's entry is a cut-off search

  // Bring the trees up to date with every set() since the last refresh.
  void refresh();
  // Take block i's entry, set after refresh(), into next() and next_real() at once (the trees
  // see it at the next refresh).
  void offer(int i);

  Next next() const { return next_; }
  double next_real() const { return next_real_; }  // earliest real event (rechecks excluded)

 private:
  __extension__ typedef unsigned __int128 Key;  // GCC and Clang on 64-bit targets
  struct alignas(32) Node {
    Key all, real;  // the winners' keys: every entry; real events only
  };
  static constexpr Key kEmpty = ~Key(0);  // a leaf with no block: after every block
  // The key of an entry: time, then (main tree) recheck, then block, most significant first.
  static Key key(double t, std::uint32_t tie);
  Node leaf(int i) const;

  int P_ = 1;                          // leaves of the trees (a power of two >= N)
  std::vector<double> t_;              // per block: its entry (infinity if none)
  std::vector<std::uint8_t> recheck_;  // per block: the entry is a cut-off modal search
  std::vector<Node> tree_;             // node n: children 2n, 2n + 1; leaves P_ + block
  BlockSet dirty_;                     // the blocks whose entry changed since refresh()
  Next next_{0, -1, false};
  double next_real_ = 0;
};

}  // namespace sb::event_detail
