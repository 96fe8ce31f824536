#pragma once
// An observer that reads nothing: for tests that look at the state or the work counters only.
#include "springblock/integrate/integrator.hpp"

namespace sbtest {

class NullObserver final : public sb::Observer {
 public:
  void sample(const sb::Chain&, const sb::State&) override {}
};

}  // namespace sbtest
