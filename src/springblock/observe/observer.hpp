#pragma once
// Observers see the chain at sample times; integrators call them and never compute
// observables themselves (odeint's observer concept).
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb {

class Observer {
 public:
  virtual ~Observer() = default;
  // Called at t = 0 and then at every sample time with the state at exactly that time.
  virtual void sample(const Chain& chain, const State& state) = 0;
  // An observer may end the run early (mu_s-only scenes, interruption).
  virtual bool wants_stop() const { return false; }
  // Whether samples must carry exact positions of groove blocks that have no contact
  // neighbour. An observer that reads only contact blocks' forces says no, and an integrator
  // with an exact groove solution may then skip evaluating those interiors at samples.
  virtual bool reads_groove_interiors() const { return true; }
  // Whether the observer reads nothing but s.t, s.dir, the slip counters and the contact blocks'
  // friction forces (friction_force()). In a chain without internal springs those depend on
  // the stuck blocks' positions only, so an exact per-block integrator may leave the positions
  // of moving blocks unevaluated at samples.
  virtual bool reads_only_friction() const { return false; }
};

}  // namespace sb
