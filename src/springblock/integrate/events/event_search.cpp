#include "springblock/integrate/events/event_search.hpp"

#include <cmath>

#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {

double EventSearch::locate(const Chain& c, const State& s, const Dopri5& dp, double h, const ActiveSet& active,
                           double window) {
  const int N = c.N;
  const double t = s.t;
  // At theta = 1 the continuous extension is the step's end point: read it, do not evaluate it.
  const double* u1 = dp.u1();
  const double* v1 = dp.v1();
  auto nb_u = [&](int j, double th) {
    switch (active.kind(j)) {
      case ActiveSet::kStepped: return th == 1.0 ? u1[j] : dp.dense_u(j, th);
      case ActiveSet::kSettled: return active.path_u(j, t + th * h);
      case ActiveSet::kModal: return active.modal_u(j, t + th * h);
      default: return s.u[j];  // a stuck neighbour does not move
    }
  };
  // Every watched sliding block is stepped and is tested at theta = 1/2 first.
  dp.dense_v_spans(active.stepped(), 0.5, v_half_.data());
  auto g = [&](int i, double th) {
    if (s.dir[i] != 0) return s.dir[i] * (th == 1.0 ? v1[i] : th == 0.5 ? v_half_[i] : dp.dense_v(i, th));
    // Stuck: v_i = 0 (no damping force) and u_i does not move.
    double F = c.k_s(i) * (c.v_slider * (t + th * h) - s.u[i]);
    if (i > 0) F += c.spring(i - 1) * (nb_u(i - 1, th) - s.u[i]);
    if (i + 1 < N) F += c.spring(i) * (nb_u(i + 1, th) - s.u[i]);
    return c.f_static[i] - std::fabs(F);
  };
  // A stuck block beside a modal run: if |F| stays below f_static with that run's end anywhere
  // within its modal envelope, g > 0 whatever the modes do, so the screen below would find no
  // event and the modes (an exp and a sincos each) need not be evaluated. The margin covers the
  // round-off of the direct evaluation, so the outcome is the screen's to the last bit.
  auto surely_no_event = [&](int i, double th) {
    double F = c.k_s(i) * (c.v_slider * (t + th * h) - s.u[i]), spread = 0, scale = std::fabs(F);
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= N) continue;
      const bool modal = active.kind(j) == ActiveSet::kModal;
      const double k_ij = c.spring_between(i, j);
      const double d = k_ij * ((modal ? active.path_u(j, t + th * h) : nb_u(j, th)) - s.u[i]);
      F += d, scale += std::fabs(d);
      if (modal) spread += k_ij * active.modal_amplitude(j);
    }
    return std::fabs(F) + spread + 1e-12 * (scale + spread) < c.f_static[i] * (1.0 - 1e-9);
  };
  // Done when the bracket spans round-off in t (round_off.hpp), in units of the step (theta).
  auto width = [t, h](double hi) { return time_round_off(t + hi * h) / h; };
  const std::vector<int>& watched = active.watched();
  double best = 2.0;
  for (std::size_t k = 0; k < watched.size(); ++k) {
    const int i = watched[k];
    theta_[k] = 2.0;
    if (s.dir[i] == 0 && active.beside(i, ActiveSet::kModal) && surely_no_event(i, 0.5) && surely_no_event(i, 1.0))
      continue;
    const double g_half = g(i, 0.5);
    double lo, g_lo, hi, g_hi;
    if (g_half <= 0) {
      lo = 0, g_lo = g(i, 0.0), hi = 0.5, g_hi = g_half;
    } else {
      lo = 0.5, g_lo = g_half, hi = 1.0, g_hi = g(i, 1.0);
      if (!(g_hi <= 0)) continue;
    }
    theta_[k] = first_root([&](double th) { return g(i, th); }, lo, g_lo, hi, g_hi, width);
    if (theta_[k] < best) best = theta_[k];
  }
  hits_.clear();
  if (best <= 1.0)
    for (std::size_t k = 0; k < watched.size(); ++k)
      if (theta_[k] <= best + window) hits_.push_back(watched[k]);
  return best;
}

}  // namespace sb::event_detail
