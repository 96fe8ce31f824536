#pragma once
// Energy bookkeeping of the chain, used to check integrators against the first law.
//
// System: the blocks, their slider springs and the internal springs. Its mechanical energy is
//   E = sum_i m v_i^2 / 2 + sum_i K_s (v t - u_i)^2 / 2 + sum_i K_int (u_{i+1} - u_i)^2 / 2,
// and differentiating along the equations of motion gives
//   dE/dt = sum_i K_s (v t - u_i) v  -  sum_i f_i v_i  -  sum_i m gamma v_i^2,
// i.e. the power the slider puts in through the spring ends it drags at speed v, minus the
// power of friction (f_i v_i = mu_d,i F_n |v_i| for a sliding block, 0 for a stuck one because
// v_i = 0 and 0 in a groove) minus viscous damping. The internal springs only move energy around.
//
// EnergyObserver integrates the three rates with the trapezoid rule over the sample times it is
// shown. For rates that are continuous in time (they are: friction power vanishes with v_i at
// every stick/slip switch) the bookkeeping error is O(sample_dt^2): per interval
// -dt^3/12 * P'' with P'' ~ omega_max^2 |P|, so relative to the work done it is about
// (omega_max sample_dt)^2 / 12. Choose sample_dt so that this is below the tolerance tested.
#include "springblock/observe/observer.hpp"

namespace sb {

double kinetic_energy(const Chain& c, const State& s);
// Slider springs plus internal springs.
double elastic_energy(const Chain& c, const State& s);

// Instantaneous power flows at the state's time, all >= 0 in normal operation except `input`.
struct EnergyRates {
  double input = 0;     // sum_i K_s (v t - u_i) v
  double friction = 0;  // sum_i f_i v_i (dissipated by friction)
  double damping = 0;   // sum_i m gamma v_i^2
};
EnergyRates energy_rates(const Chain& c, const State& s);

struct EnergyBudget {
  double work_in = 0;             // integral of the slider's input power
  double friction = 0, damping = 0;  // integrated dissipation
  double kinetic0 = 0, elastic0 = 0; // energies at the first sample
  double kinetic = 0, elastic = 0;   // energies at the last sample
  long samples = 0;

  double stored_change() const { return (kinetic + elastic) - (kinetic0 + elastic0); }
  // Work in minus (stored change + dissipation); zero for an exact integrator and bookkeeping.
  double imbalance() const { return work_in - stored_change() - friction - damping; }
  // Size of the terms the balance is made of, the denominator of the relative error.
  double scale() const;
  double relative_error() const;
};

class EnergyObserver final : public Observer {
 public:
  void sample(const Chain& c, const State& s) override;
  const EnergyBudget& budget() const { return b_; }

 private:
  EnergyBudget b_;
  EnergyRates last_{};
  double last_t_ = 0;
};

}  // namespace sb
