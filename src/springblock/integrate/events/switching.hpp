#pragma once
// The stick/slip rules applied at one instant by the event-driven integrator.
//
//  * A sliding block whose velocity reached zero (an event located there, or found reversed)
//    stops: v := 0. It stays stuck if |F| <= f_static, else it slides on in the direction of F.
//  * A stuck block whose |F| exceeds f_static, or whose threshold crossing was located at this
//    instant, starts to slide in the direction of F.
//  * A block at rest that has just been set sliding but whose kinetic friction exceeds the
//    force (only possible when mu_d > mu_s is kept) stops again at once.
// The rules are applied to the blocks whose events were located at this instant (flagged), in
// the order they were flagged, and repeated until none of them changes, so the outcome is
// deterministic. Nothing else can switch at the instant: a switch moves no block, so it changes
// no other block's force (only the switched block's own velocity), and every other block's
// event is located by the integrator at its own time. The first apply of a run (full = true)
// visits every contact block in index order. Each switch is counted (CascadeGuard).
#include <cstdint>
#include <vector>

#include "springblock/integrate/block_set.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

// The rules above for contact block i at s.t, one pass; returns the switches made (a stop may
// be followed by a restart in the same pass). Shared with the per-block solver (uncoupled.hpp).
int apply_rules(const Chain& c, State& s, int i, bool event_here);

// The switches made at one instant: more than 100 N there is a cascade that would never end,
// reported as std::runtime_error.
class CascadeGuard {
 public:
  // Counts `made` more switches at time t; throws on a cascade.
  void add(const Chain& c, double t, std::int64_t made);

 private:
  double instant_ = -1;
  std::int64_t at_instant_ = 0;
};

class Switching {
 public:
  explicit Switching(int N) : flagged_(N), touched_(N), mobile_(N), f_kin_(N) {}

  // Mark a block whose event was located at the current instant (cleared by apply()).
  void flag(int i) { flagged_.add(i); }
  // The blocks flagged since the last apply(), in flagging order.
  const std::vector<int>& flagged() const { return flagged_.list(); }
  // Apply the rules at s.t; returns the number of switches made. Throws on a cascade.
  int apply(const Chain& c, State& s, bool full = false);
  // Rebuild mobile / f_kin from s.dir (at the start of a run).
  void sync(const Chain& c, const State& s);

  // Blocks switched since the last clear_touched(), 1 per block (a stop followed by a restart
  // at the same instant leaves dir unchanged, so dir alone does not show it).
  const std::uint8_t* touched() const { return touched_.flags(); }
  const std::vector<int>& touched_list() const { return touched_.list(); }  // the same blocks, in switching order
  void clear_touched() { touched_.clear(); }
  const double* mobile() const { return mobile_.data(); }  // 1 = groove or sliding, 0 = stuck
  const double* f_kin() const { return f_kin_.data(); }    // signed kinetic friction
  int n_sliding() const { return n_sliding_; }

 private:
  // Keep mobile_, f_kin_ and n_sliding_ in step with s.dir for block i.
  void update(const Chain& c, const State& s, int i);

  BlockSet flagged_, touched_;
  std::vector<int> work_;
  std::vector<double> mobile_, f_kin_;
  int n_sliding_ = 0;
  CascadeGuard cascade_;
};

}  // namespace sb::event_detail
