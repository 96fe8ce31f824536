#include "springblock/integrate/events/switching.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sb::event_detail {

void Switching::sync(const Chain& c, const State& s) {
  n_sliding_ = 0;
  std::fill(mobile_.begin(), mobile_.end(), 0.0);  // update() then counts no block as sliding before
  for (int i = 0; i < c.N; ++i) update(c, s, i);
}

int apply_rules(const Chain& c, State& s, int i, bool event_here) {
  int made = 0;
  // A stuck block whose crossing was located here: the crossing is the switch, even if round-off
  // left |F| a hair below f_static.
  const bool crossing = event_here && s.dir[i] == 0;
  if (s.dir[i] != 0) {
    const double dv = s.dir[i] * s.v[i];
    // At rest and pulled clearly less than kinetic friction: it cannot move in its
    // direction. With mu_d = mu_s a block released at its threshold has net force zero up
    // to round-off; the slider's loading then accelerates it, so a round-off deficit must
    // not send it back to rest at the same instant (that would be an endless cascade).
    const bool cannot_go = dv == 0.0 && s.dir[i] * c.driving_force(i, s.u.data(), s.v.data(), s.t) - c.f_kinetic[i] <
                                            -1e-9 * c.f_kinetic[i];
    if (event_here || dv < 0.0 || cannot_go) {
      s.v[i] = 0.0;
      s.dir[i] = 0;
      ++made;
    }
  }
  if (s.dir[i] == 0) {
    const double F = c.driving_force(i, s.u.data(), s.v.data(), s.t);
    if (crossing || std::fabs(F) > c.f_static[i]) {
      s.dir[i] = (crossing ? F >= 0 : F > 0) ? 1 : -1;
      s.mark_slip(i);
      ++made;
    }
  }
  return made;
}

void CascadeGuard::add(const Chain& c, double t, std::int64_t made) {
  if (t != instant_) {
    instant_ = t;
    at_instant_ = 0;
  }
  at_instant_ += made;
  const std::int64_t limit = 100LL * c.N;
  if (at_instant_ > limit)
    throw std::runtime_error("switching cascade: more than " + std::to_string(limit) +
                             " stick/slip switches at t = " + std::to_string(t) +
                             " s without time advancing (is mu_d > mu_s kept for some block?)");
}

void Switching::update(const Chain& c, const State& s, int i) {
  const bool sliding = s.dir[i] != 0;
  // Until it is rewritten below, mobile_ says whether a contact block was sliding.
  n_sliding_ += static_cast<int>(sliding) - static_cast<int>(c.contact[i] && mobile_[i] != 0.0);
  mobile_[i] = (!c.contact[i] || sliding) ? 1.0 : 0.0;
  f_kin_[i] = s.dir[i] * c.f_kinetic[i];
}

int Switching::apply(const Chain& c, State& s, bool full) {
  if (full) {
    work_.clear();
    for (int i = 0; i < c.N; ++i)
      if (c.contact[i]) work_.push_back(i);
  } else {
    work_ = flagged_.list();
  }
  int made = 0;
  for (bool first_pass = true;; first_pass = false) {
    int pass = 0;
    for (int i : work_) {
      if (!c.contact[i]) continue;
      const int m = apply_rules(c, s, i, first_pass && flagged_.has(i));
      if (m > 0) {
        touched_.add(i);
        update(c, s, i);
      }
      pass += m;
    }
    if (first_pass) flagged_.clear();
    cascade_.add(c, s.t, pass);
    made += pass;
    if (pass == 0) break;
  }
  s.switches += made;
  return made;
}

}  // namespace sb::event_detail
