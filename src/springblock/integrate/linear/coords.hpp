#pragma once
// Modal coordinates q and their rates p, one per slot (run_store.hpp): a run's state at one time as its users keep it.
#include <vector>

namespace sb::event_detail {

struct Coords {
  std::vector<double> q, p;
  explicit Coords(int N = 0) : q(N), p(N) {}
};

}  // namespace sb::event_detail
