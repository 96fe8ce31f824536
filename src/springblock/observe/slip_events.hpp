#pragma once
// Slip events (avalanches) and their sizes. A slip event is a maximal interval during which some
// contact block slides; for each one this records when it started, how long it lasted, how many
// distinct contact blocks slid in it, how many block-slip episodes it held (a block may slide more
// than once in one event) and its total slip: the sum over those episodes of the distance each
// block travelled from where it started to slide to where it stopped.
//
// Read off the integrator's switches alone (Observer::switched): an episode starts and ends at a
// switch, where the switched block's position is exact, and nothing between switches is needed. A
// sliding block keeps its direction until its velocity reaches zero, where it stops, so the
// distance of an episode is |u_stop - u_start|.
//
// Counting rule. An event is recorded when it ends, at the switch that leaves no contact block
// sliding; a block that starts and stops at one instant while nothing else slides makes an event
// of zero duration and zero slip. An event still under way when the run ends is not recorded (its
// slip is not known yet): unfinished() says there was one, and under_way() what it held so far. The
// event method's work profile counts the same events at the first turn of its driver with nothing
// sliding after each (WorkProfile::slip_events), so the two agree unless the run ends at the very
// instant an event ended (no such turn follows it, at the end of the run or where an observer
// stops it): then this records one more.
//
// The run must start with every contact block stuck (State::at_rest, the ensemble's start).
#include <cstdint>
#include <vector>

#include "springblock/observe/observer.hpp"

namespace sb {

struct SlipEvent {
  double t_start_s = 0;   // the first of its blocks starts to slide
  double duration_s = 0;  // until the last one stops
  int blocks = 0;         // distinct contact blocks that slid in it
  int episodes = 0;       // block-slip episodes it held
  double slip_m = 0;      // sum over its episodes of the distance slid
};

// What one repetition records: its events in time order, and whether one was under way at the end
// and, if so, its start, blocks and episodes so far and the slip of its finished episodes (its
// duration is 0: not known).
struct SlipEventRecord {
  std::vector<SlipEvent> events;
  bool unfinished = false;
  SlipEvent under_way;
};

class SlipEventObserver final : public Observer {
 public:
  void switched(const Chain& chain, const State& state, SwitchedBlocks blocks) override;
  // Nothing is read at samples: every stretch is taken whole, and no position is needed there.
  void sample(const Chain&, const State&) override {}
  long sample_affine(const Chain&, const State&, long, double, long n, const AffineForces&) override { return n; }
  long sample_sums(const Chain&, const State&, long, double, long n, SampleStretch&) override { return n; }
  bool reads_groove_interiors() const override { return false; }
  bool reads_only_friction() const override { return true; }
  bool needs_positions_at(double) const override { return false; }

  const std::vector<SlipEvent>& events() const { return events_; }
  bool unfinished() const { return open_; }
  SlipEvent under_way() const { return open_ ? current_ : SlipEvent{}; }
  SlipEventRecord record() const { return {events_, open_, under_way()}; }

 private:
  std::vector<SlipEvent> events_;
  SlipEvent current_;
  bool open_ = false;
  int n_sliding_ = 0;
  // Per block: its direction as last switched, where its current episode started, and the index
  // of the last event it was counted in (-1: none).
  std::vector<std::int8_t> dir_;
  std::vector<double> u_start_;
  std::vector<std::int64_t> counted_in_;
};

}  // namespace sb
