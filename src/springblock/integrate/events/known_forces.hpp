#pragma once
// Each contact block's friction force as the active set knows it between two classifications
// (ActiveForces, observer.hpp): what an observer that sums the forces needs at a sample without
// the positions of the blocks that have not changed since.
//
// The active set classifies each contact block when it finds its next event, and a stuck
// block's closed-form crossing is found from exactly the affine force recorded here (the
// crossing is stale the moment that force is, so the record is renewed wherever the crossing
// is). The blocks whose entry changed are listed until the next sample takes them.
#include <cstdint>
#include <vector>

#include "springblock/observe/observer.hpp"

namespace sb::event_detail {

class KnownForces {
 public:
  explicit KnownForces(int N) : a_(N, 0.0), b_(N, 0.0), kind_(N, ActiveForces::kNone), live_at_(N), listed_(N, 0) {}

  // Stuck block i feels a + b t from now on (t absolute).
  void affine(int i, double a, double b) { set(i, ActiveForces::kAffine, a, b); }
  void sliding(int i, double f) { set(i, ActiveForces::kSliding, f, 0.0); }
  // Stuck beside a run that moves otherwise: its force is read from the state at samples.
  void live(int i) { set(i, ActiveForces::kLive, 0.0, 0.0); }

  // The stuck blocks whose force is read from the state (in no particular order).
  const std::vector<int>& live_blocks() const { return live_; }
  ActiveForces view() const { return {a_.data(), b_.data(), kind_.data(), changed_, all_, live_}; }
  // A sample took the changes (every observer's sample_active or follow_forces was called).
  void delivered() {
    for (int i : changed_) listed_[i] = 0;
    changed_.clear();
    all_ = false;
  }

 private:
  void set(int i, std::uint8_t kind, double a, double b) {
    a_[i] = a, b_[i] = b;
    if ((kind == ActiveForces::kLive) != (kind_[i] == ActiveForces::kLive)) {
      if (kind == ActiveForces::kLive) {
        live_at_[i] = static_cast<int>(live_.size());
        live_.push_back(i);
      } else {  // the last live block takes its place
        live_at_[live_.back()] = live_at_[i];
        live_[static_cast<std::size_t>(live_at_[i])] = live_.back();
        live_.pop_back();
      }
    }
    kind_[i] = kind;
    if (!all_ && !listed_[i]) listed_[i] = 1, changed_.push_back(i);
  }

  std::vector<double> a_, b_;
  std::vector<std::uint8_t> kind_;
  std::vector<int> live_, live_at_;  // the live blocks, and each live block's index in live_
  std::vector<int> changed_;
  std::vector<std::uint8_t> listed_;  // per block: in changed_
  bool all_ = true;                   // nothing delivered yet: every block counts as changed
};

}  // namespace sb::event_detail
