#pragma once
// Where a run's time goes. The integrators keep work counters (increments only, always on) and,
// when timing is switched on (springblock run --profile), the wall time of each kind of work.
// The kinds are leaves of the event method's layers (event_run.hpp) and never nest, so their
// times add up; what they leave out of the run's wall time is the driver's bookkeeping and the
// step-size control ("other" in the printed table).
//
// A counter costs an increment (all of them ~1% of a run's instructions); a timer two reads of
// the steady clock (~30 ns each on the development machine), several per step; bench_vs_paper's
// event_timed case measures what that costs a run against the untimed one (the README's Cost
// section). Hence timing only when asked. The counters are what the cost model
// (tools/cost_model.py) fits.
#include <chrono>
#include <cstdint>

namespace sb {

// name, meaning. Counts of one run.
#define SB_WORK_COUNTS(X)                                                                                     \
  X(slip_events, "turns with nothing sliding after something slid: one per slip event (avalanche), event method")      \
  X(slip_starts, "block-slip episodes: a contact block starts to slide")                                       \
  X(stepped_attempts, "steps of the moving runs (exact or Dormand-Prince trials: accepted, rejected, redone)")   \
  X(rejected_steps, "trial steps rejected by the error control")                                               \
  X(event_steps, "steps ended at a located event (Dormand-Prince: redone to it)")                                \
  X(block_steps, "blocks integrated, summed over trial steps (the stepping work)")                             \
  X(exact_jumps, "jumps to the next closed-form event or sample with nothing to step")                         \
  X(switch_instants, "instants at which the switching rules were applied")                                      \
  X(samples, "samples of mu(t) served one by one")                                                              \
  X(stretch_samples, "samples taken at once as affine stretches (a quiet phase; uncoupled blocks between events)") \
  X(summed_samples, "samples of a quiet phase taken as closed-form sums over its modes")                     \
  X(peak_samples, "loading samples of a quiet phase taken as a stretch: bounds pass over those below its peak")

// name, meaning. Seconds of one run (0 unless timed).
#define SB_WORK_TIMES(X)                                                                                   \
  X(stepping_s, "steps of the moving runs (exact: projections and modes; Dormand-Prince trials; RK4 steps)")  \
  X(event_location_s, "search of each step for switches (exact: span screen; Dormand-Prince: dense output)") \
  X(switching_s, "switching rules, reclassification of the runs and their exact event times")              \
  X(quiet_s, "quiet phases: projection onto the grooves' modes and the next threshold crossing (RK4: jump)") \
  X(sampling_s, "samples: bringing exact runs to the sample time and the observer")

struct WorkProfile {
#define SB_COUNT(name, doc) std::int64_t name = 0;
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
#define SB_TIME(name, doc) double name = 0;
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
  bool timed = false;  // the times are measured (set before the run)

  void add(const WorkProfile& o) {
#define SB_ADD(name, doc) name += o.name;
    SB_WORK_COUNTS(SB_ADD)
    SB_WORK_TIMES(SB_ADD)
#undef SB_ADD
    timed = timed || o.timed;
  }
};

// Adds the wall time of its scope to one of a WorkProfile's times, when the profile is timed.
class WorkTimer {
 public:
  WorkTimer(const WorkProfile& p, double& slot) : slot_(p.timed ? &slot : nullptr) {
    if (slot_) t0_ = std::chrono::steady_clock::now();
  }
  ~WorkTimer() {
    if (slot_) slot_[0] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  WorkTimer(const WorkTimer&) = delete;
  WorkTimer& operator=(const WorkTimer&) = delete;

 private:
  double* slot_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace sb
