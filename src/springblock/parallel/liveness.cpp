#include "springblock/parallel/liveness.hpp"

#include <algorithm>
#include <stdexcept>

namespace sb::parallel {

Liveness::Liveness(int ranks, double silence_s, double now)
    : silence_s_(silence_s), last_(ranks, now), watched_(ranks, true), dead_(ranks, false) {
  if (!(silence_s > 0)) throw std::invalid_argument("Liveness: the silence allowed must be positive");
  if (ranks > 0) watched_[0] = false;  // the coordinator does not watch itself
}

double heartbeat_s(double silence_s) { return std::min(1.0, silence_s / 4); }

void Liveness::heard(int rank, double now) { last_[rank] = std::max(last_[rank], now); }

void Liveness::forget(int rank) { watched_[rank] = false; }

void Liveness::mark_dead(int rank) {
  watched_[rank] = false;
  dead_[rank] = true;
}

std::vector<int> Liveness::newly_dead(double now) {
  std::vector<int> out;
  for (int r = 0; r < static_cast<int>(last_.size()); ++r)
    if (watched_[r] && now - last_[r] > silence_s_) {
      watched_[r] = false;
      dead_[r] = true;
      out.push_back(r);
    }
  return out;
}

}  // namespace sb::parallel
