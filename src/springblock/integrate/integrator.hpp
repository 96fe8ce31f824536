#pragma once
// Time steppers. An integrator advances a Chain's State to t_end, calling the observer at
// t = 0 and every sample_dt; it owns the stick/slip switching rules it implements.
#include <memory>
#include <string>

#include "springblock/model.hpp"
#include "springblock/observe/observer.hpp"
#include "springblock/run_control.hpp"
#include "springblock/state.hpp"

namespace sb {

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual void run(const Chain& chain, State& state, double t_end, double sample_dt, Observer& obs) = 0;
  virtual std::string name() const = 0;
  // Whether a run ending at t_end takes a sample at time t (a sample time of a longer run).
  // Lets several scenes that differ only in run length share one trajectory (FanOut).
  virtual bool samples_within(double t, double t_end) const { return t <= t_end; }
};

// The exact stepper's longest step, in radians of the chain's fastest rate (omega_max, or the
// damping where larger): the run shapes step by it (run_shape.cpp says why 0.75), and scene
// validation bounds a run's count of such steps.
inline constexpr double kExactStepRadians = 0.75;

std::unique_ptr<Integrator> make_integrator(const RunControl& rc);

}  // namespace sb
