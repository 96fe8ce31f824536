#include "springblock/observe/friction_observer.hpp"

#include <cmath>
#include <cstdint>

namespace sb {

void FrictionObserver::sample(const Chain& c, const State& s) {
  // The contact blocks, listed once: grooves carry no friction and are skipped without a test.
  if (contacts_.empty() && c.n_contact > 0)
    for (int i = 0; i < c.N; ++i)
      if (c.contact[i]) contacts_.push_back(i);
  double sum_abs = 0, sum_signed = 0;
  int n_sliding = 0;
  const double* u = s.u.data();
  const double slider = c.v_slider * s.t;
  for (int i : contacts_) {
    double f;
    if (s.dir[i] != 0) {
      f = s.dir[i] * c.f_kinetic[i];
      ++n_sliding;
    } else if (i > 0 && i + 1 < c.N) {
      // A stuck block has v = 0: no damping term.
      f = c.K_s * (slider - u[i]) + c.K_int * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
    } else {
      f = c.driving_force(i, u, s.v.data(), s.t);
    }
    sum_abs += std::fabs(f);
    sum_signed += f;
  }
  const double mu = sum_abs / cfg_.F_load;
  const double mu_signed = sum_signed / cfg_.F_load;
  last_t_ = s.t;

  if (!slipped_) {
    if (mu > running_max_) {
      running_max_ = mu;
      t_max_ = s.t;
    }
    // End of the loading phase: mu_s is the peak reached before it.
    const bool ended = cfg_.peak_rule == ExtractionRules::PeakRule::AllSlipped
                           ? !s.slipped_once.empty() && s.n_slipped_once >= c.n_contact
                           : mu < running_max_ - cfg_.peak_drop;
    if (ended) {
      slipped_ = true;
      t_slip_ = s.t;
    }
  } else if (s.t >= t_slip_ + cfg_.mu_d_skip_s) {
    sum_mu_ += mu;
    sum_mu_signed_ += mu_signed;
    ++n_window_;
  }

  if (cfg_.keep_series) series_.push_back({s.t, mu, mu_signed, n_sliding});
  while (next_stress_ < cfg_.stress_times_s.size() && s.t >= cfg_.stress_times_s[next_stress_]) {
    StressSnapshot snap{s.t, std::vector<double>(c.N), std::vector<double>(c.N)};
    for (int i = 0; i < c.N; ++i) {
      const double f = friction_force(c, s, i);
      snap.f_over_Fn[i] = c.contact[i] ? f / c.F_n : 0.0;
      snap.sigma_over_P[i] = f / cfg_.block_area_P;
    }
    stress_.push_back(std::move(snap));
    ++next_stress_;
  }
  if (cfg_.progress_ns) cfg_.progress_ns->store(static_cast<std::int64_t>(s.t * 1e9), std::memory_order_relaxed);
}

bool FrictionObserver::wants_stop() const {
  if (cfg_.interrupt && cfg_.interrupt->load(std::memory_order_relaxed)) return true;
  return cfg_.stop_after_mu_s && slipped_ && next_stress_ >= cfg_.stress_times_s.size();
}

}  // namespace sb
