#include "springblock/energy.hpp"

#include <algorithm>
#include <cmath>

namespace sb {

double kinetic_energy(const Chain& c, const State& s) {
  double e = 0;
  for (int i = 0; i < c.N; ++i) e += s.v[i] * s.v[i];
  return 0.5 * c.m * e;
}

double elastic_energy(const Chain& c, const State& s) {
  const double slider = c.v_slider * s.t;
  double es = 0, ei = 0;
  for (int i = 0; i < c.N; ++i) {
    const double e = slider - s.u[i];
    es += e * e;
  }
  for (int i = 0; i + 1 < c.N; ++i) {
    const double d = s.u[i + 1] - s.u[i];
    ei += d * d;
  }
  return 0.5 * c.K_s * es + 0.5 * c.K_int * ei;
}

EnergyRates energy_rates(const Chain& c, const State& s) {
  EnergyRates r;
  const double slider = c.v_slider * s.t;
  double stretch = 0, vv = 0;
  for (int i = 0; i < c.N; ++i) {
    stretch += slider - s.u[i];
    vv += s.v[i] * s.v[i];
    // The friction force actually applied by the model; its power is the dissipation. Using
    // the force rather than mu_d F_n |v| keeps the bookkeeping honest if a velocity ever
    // pointed against the sliding direction.
    r.friction += friction_force(c, s, i) * s.v[i];
  }
  r.input = c.K_s * c.v_slider * stretch;
  r.damping = c.m * c.gamma * vv;
  return r;
}

double EnergyBudget::scale() const {
  return std::max({std::fabs(work_in), std::fabs(stored_change()), friction + damping, 1e-300});
}

double EnergyBudget::relative_error() const { return std::fabs(imbalance()) / scale(); }

void EnergyObserver::sample(const Chain& c, const State& s) {
  const EnergyRates r = energy_rates(c, s);
  b_.kinetic = kinetic_energy(c, s);
  b_.elastic = elastic_energy(c, s);
  if (b_.samples == 0) {
    b_.kinetic0 = b_.kinetic;
    b_.elastic0 = b_.elastic;
  } else {
    const double dt = s.t - last_t_;
    b_.work_in += 0.5 * dt * (last_.input + r.input);
    b_.friction += 0.5 * dt * (last_.friction + r.friction);
    b_.damping += 0.5 * dt * (last_.damping + r.damping);
  }
  last_ = r;
  last_t_ = s.t;
  ++b_.samples;
}

}  // namespace sb
