#pragma once
// The event method's quiet phase (an evolve step): every contact block stuck, the grooves
// propagated exactly (linear/quiet_phase.hpp) to the first threshold crossing, with the samples
// inside served from the closed form. Exact, except that an observer of contact forces only gets
// groove modes below the settle scales dropped (QuietPhase::set_sample_scales); once every
// groove has rung down the observer may take the rest of the phase's samples as one affine
// stretch (sample_affine), and before that blocks of them as closed-form sums (sample_sums).
#include <vector>

#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/linear/quiet_ringing.hpp"
#include "springblock/integrate/methods/event_core.hpp"

namespace sb::event_detail {

class QuietEvolve {
 public:
  explicit QuietEvolve(EventCore& core);
  // At a turn of the driver with nothing sliding: whether a quiet phase pays from here. Its
  // set-up and its threshold search visit the whole chain, while the active set serves the same
  // stretch for what moves; so a phase is begun only when at least kMinSamples samples are due
  // before the active set's earliest real event (which no quiet phase outlasts). Measured among
  // 0, 4, 16 and 64 (paper/choices.md, 'When a quiet phase is begun').
  static constexpr long kMinSamples = 64;
  bool pays() const;
  // The phase from s.t to its first threshold crossing, switched there. False when the observer
  // stopped the run inside it (the state is then exact at its last sample).
  bool phase();

 private:
  bool serve_samples(double t_next);
  void serve_sample(double t);
  void stamp_sample(double t);
  // Quiet-phase samples once every groove has rung down: one affine stretch (the samples taken;
  // 0 when the observer took none, so the caller samples one by one).
  long sample_affine_stretch(double t_next);
  // A block of quiet-phase samples taken as sums over the modes.
  long offer_block(double t_stop, long long& next_offer);
  bool took_samples(long used);

  EventCore& core_;
  QuietPhase quiet_;
  QuietRinging ringing_;  // its contact forces, for an observer of those alone
  State sample_;                 // the state at a sample served from the closed form
  std::vector<double> fa_, fb_;  // affine contact forces a + b t once the phase's modes died
  bool affine_ready_ = false;
};

}  // namespace sb::event_detail
