// ModalRuns' event searches (modal_runs.hpp): a sliding block's stop and a stuck neighbour's
// threshold crossing on the sum of a run's modes (EdgeMarch).
#include <cmath>

#include "springblock/infinity.hpp"
#include "springblock/integrate/linear/modal_runs.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {

ModalRuns::Found ModalRuns::stop_time(const Chain& c, const State& s, int i, bool fresh, double t_limit) {
  // The velocity v = B + sum Q q_k' and each q_k' is a damped mode started from (q', q'') at
  // s.t. Event: -dir (v - B) >= dir B + eps_v, i.e. dir v <= -eps_v (eps_v = kStopMargin v_s).
  const Run& r = scratch_at(i, s.t);
  const RunShape& sh = *record(r).shape;
  const int n = r.hi - r.lo;
  const double* row = sh.row(i - r.lo);
  const double dir = s.dir[i];
  march_.reset();
  for (int k = 0; k < n; ++k) {
    const int slot = r.lo + k;
    const DampedMode& m = sh.modes[k];
    velocity_.q[slot] = scratch_.p[slot];
    velocity_.p[slot] = -c.gamma * scratch_.p[slot] - m.omega2 * scratch_.q[slot];
    march_.add_mode(-dir * row[k], m, slot, sh.steps.march[k].data());
  }
  march_.finish(store_.shapes().march_step());
  march_.set_affine(0.0, 0.0);
  // A block that has just started to slide sits at v = 0 exactly (see EdgeMarch's open origin).
  march_.set_sense(EdgeMarch::Sense::Upper, dir * (fresh ? s.v[i] : store_.row_v(i, scratch_.p.data())) <= 0.0);
  const double tau = march_.first_crossing(velocity_.q.data(), velocity_.p.data(),
                                           dir * store_.B(i) + kStopMargin * c.v_slider, t_limit - s.t, s.t);
  return {s.t + tau, march_.hit_limit, t_limit};
}

ModalRuns::Found ModalRuns::crossing_time(const Chain& c, const State& s, int j, const double base[2],
                                          const double nb_B[2], double t_limit) {
  // The envelope first. Each modal side's end row stays within its bound (amplitude()) of its path at every time
  // after its projection, so no crossing can come before the affine part of F is within their
  // sum of the threshold. Most searches after a switch end at t_limit (the next event, soon
  // while something slides) without a crossing; when the envelope already says so, the search
  // waits until then with no march set up and no mode evaluated, and goes on from where the
  // envelope allows.
  double a = c.k_s(j) * (c.v_slider * s.t - s.u[j]), b = c.k_s(j) * c.v_slider, spread = 0;
  for (int side = 0; side < 2; ++side) {
    const int nb = side == 0 ? j - 1 : j + 1;
    if (nb < 0 || nb >= static_cast<int>(run_of_.size())) continue;
    const double k = c.spring_between(j, nb);
    if (run_of_[nb] < 0) {
      a += k * (base[side] - s.u[j]), b += k * nb_B[side];
      continue;
    }
    a += k * (store_.path_u(nb, s.t) - s.u[j]), b += k * store_.B(nb), spread += k * amplitude(nb);
  }
  const double room = c.f_static[j] - spread;
  if (std::fabs(a) < room) {
    const double reach = b > 0 ? (room - a) / b : b < 0 ? (room + a) / -b : kInf;
    if (!(s.t + reach < t_limit)) return {kInf, std::isfinite(reach), s.t + reach};
  }
  // Then the march on F = a + b tau plus the modal sides' modes.
  march_.reset();
  for (int side = 0; side < 2; ++side) {
    const int nb = side == 0 ? j - 1 : j + 1;
    if (nb < 0 || nb >= static_cast<int>(run_of_.size()) || run_of_[nb] < 0) continue;
    const double k_nb = c.spring_between(j, nb);
    // The run's coordinates at s.t (its own origin may be older: it was kept across switches).
    const Run& r = scratch_at(nb, s.t);
    const RunShape& sh = *record(r).shape;
    const double* row = sh.row(nb - r.lo);
    for (int k = 0; k < r.hi - r.lo; ++k)
      march_.add_mode(k_nb * row[k], sh.modes[k], r.lo + k, sh.steps.march[k].data());
  }
  march_.finish(store_.shapes().march_step());
  march_.set_affine(a, b);
  march_.set_sense(EdgeMarch::Sense::Abs, false);
  const double tau = march_.first_crossing(scratch_.q.data(), scratch_.p.data(), c.f_static[j], t_limit - s.t, s.t);
  return {s.t + tau, march_.hit_limit, t_limit};
}

}  // namespace sb::event_detail
