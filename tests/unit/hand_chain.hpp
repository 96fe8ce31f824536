#pragma once
// Chains built by hand for the integrator tests, bypassing build_chain so that thresholds can
// be chosen exactly: blocks of the paper's default size (N = 200, L_x = 4 cm: m = 2.4 mg,
// K_s = 1e4 N/m, F_n = 2 N, v = 0.05 cm/s), a given contact mask, K_int, damping and micro
// coefficients (ignored in grooves, where friction is zero).
#include <cstdint>
#include <vector>

#include "springblock/model.hpp"

namespace sbtest {

inline sb::Chain hand_chain(const std::vector<std::uint8_t>& contact, double K_int, double gamma,
                            const std::vector<double>& mu_s, const std::vector<double>& mu_d) {
  sb::Chain c;
  c.N = static_cast<int>(contact.size());
  c.K_s = 1e4;
  c.K_int = K_int;
  c.m = 2.4e-6;
  c.gamma = gamma;
  c.v_slider = 5e-4;
  c.F_n = 2.0;
  c.contact = contact;
  for (int i = 0; i < c.N; ++i) {
    const double ms = contact[i] ? mu_s[i] : 0.0, md = contact[i] ? mu_d[i] : 0.0;
    c.n_contact += contact[i] ? 1 : 0;
    c.mu_s.push_back(ms);
    c.mu_d.push_back(md);
    c.f_static.push_back(ms * c.F_n);
    c.f_kinetic.push_back(md * c.F_n);
  }
  c.F_load = c.F_n * c.n_contact;
  return c;
}

}  // namespace sbtest
