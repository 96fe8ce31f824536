#include "springblock/observe/slip_events.hpp"

#include <cmath>

namespace sb {

void SlipEventObserver::switched(const Chain& c, const State& s, SwitchedBlocks blocks) {
  if (dir_.empty()) {
    dir_.assign(c.N, 0);
    u_start_.assign(c.N, 0.0);
    counted_in_.assign(c.N, -1);
  }
  const auto index = static_cast<std::int64_t>(events_.size());  // the open event's, once recorded
  for (int i : blocks) {
    const bool was = dir_[i] != 0, is = s.dir[i] != 0;
    // A sliding block that switched has stopped here (and may have started again).
    if (was) {
      current_.slip_m += std::fabs(s.u[i] - u_start_[i]);
      --n_sliding_;
    }
    // It started here, unless it only stopped. One stuck before and after started and stopped at
    // once (the rules send back to rest a block whose kinetic friction exceeds its pull).
    if (is || !was) {
      if (!open_) {
        current_ = SlipEvent{};
        current_.t_start_s = s.t;
        open_ = true;
      }
      ++current_.episodes;
      if (counted_in_[i] != index) counted_in_[i] = index, ++current_.blocks;
      u_start_[i] = s.u[i];
      n_sliding_ += is;
    }
    dir_[i] = s.dir[i];
  }
  if (open_ && n_sliding_ == 0) {
    current_.duration_s = s.t - current_.t_start_s;
    events_.push_back(current_);
    open_ = false;
  }
}

}  // namespace sb
