// validate(Scene): every range a scene must lie in, checked once where the scene is made.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <string>

#include "springblock/errors.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/scene.hpp"

namespace sb {
namespace {

void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (!ok) throw InputError(field, "value " + printed(value) + " is outside the allowed range " + range);
}

bool finite(double x) { return std::isfinite(x); }

// The most steps or samples a run may take: past it consecutive times lie within ~450 round-offs
// of t (validate_resolution).
constexpr double kMaxTimes = 1e13;

// RK4 is stable for a mode when |R(h lambda)| <= 1, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24. With
// damping a mode of frequency w has lambda = -gamma/2 +- sqrt(gamma^2/4 - w^2); every w^2 lies in
// the Gershgorin band [K_s, K_s + 4 K_int] / m. Overdamped modes reach lambda ~ -gamma, where the
// real-axis limit h gamma <= 2.785 binds, and between the axes the region is narrower still
// (|z| ~ 2.62 at 123 degrees), so the undamped limit alone does not suffice. Checked on a grid.
bool rk4_damped_stable(double h, double gamma, double w2_lo, double w2_hi) {
  constexpr int kGrid = 1024;
  for (int k = 0; k <= kGrid; ++k) {
    const double w2 = w2_lo + (w2_hi - w2_lo) * k / kGrid;
    const std::complex<double> root = std::sqrt(std::complex<double>(0.25 * gamma * gamma - w2, 0.0));
    for (const auto lambda : {-0.5 * gamma + root, -0.5 * gamma - root}) {
      const std::complex<double> z = h * lambda;
      const auto R = 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
      if (std::abs(R) > 1.0 + 1e-12) return false;
    }
  }
  return true;
}

// The band [lo, hi] holding every mode's squared frequency, and the largest undamped RK4 step:
// uniform chains by the closed forms of derive(); chains whose blocks differ by Gershgorin on
// M^-1 K, row i in [K_s,i / m_i, (K_s,i + 2 K_int,i-1 + 2 K_int,i) / m_i].
struct ModeBand {
  double w2_lo, w2_hi, h_undamped;
};

ModeBand mode_band(const Scene& s) {
  const auto d = s.derived();
  ModeBand b{d.K_s_N_per_m / d.m_kg, d.omega_max * d.omega_max, rk4_stable_dt(d)};
  if (!s.materials.given()) return b;
  const auto r = resolve_materials(s);
  if (!r.mechanical()) return b;
  const int N = s.geometry.N;
  b.w2_lo = std::numeric_limits<double>::infinity();
  b.w2_hi = 0;
  for (int i = 0; i < N; ++i) {
    const double ks = d.K_s_N_per_m * r.at(BlockField::KsScale, i, 1.0), m = d.m_kg * r.at(BlockField::MassScale, i, 1.0);
    const double left = i > 0 ? d.K_int_N_per_m * r.at(BlockField::KIntScale, i - 1, 1.0) : 0.0;
    const double right = i + 1 < N ? d.K_int_N_per_m * r.at(BlockField::KIntScale, i, 1.0) : 0.0;
    b.w2_lo = std::min(b.w2_lo, ks / m);
    b.w2_hi = std::max(b.w2_hi, (ks + 2.0 * left + 2.0 * right) / m);
  }
  b.h_undamped = 2.0 * std::sqrt(2.0) / std::sqrt(b.w2_hi);
  return b;
}

// Largest stable RK4 step with damping, by bisection below the undamped limit.
double rk4_damped_stable_dt(const ModeBand& b, double gamma) {
  double lo = 0, hi = b.h_undamped;
  if (rk4_damped_stable(hi, gamma, b.w2_lo, b.w2_hi)) return hi;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (rk4_damped_stable(mid, gamma, b.w2_lo, b.w2_hi) ? lo : hi) = mid;
  }
  return lo;
}

// The material and load: each quantity positive (damping may be 0) and below any physical scale.
void validate_material(const MaterialParameters& m, const ChainGeometry& g) {
  require(g.N >= 1 && g.N <= 1000000, "N", g.N, "[1, 1000000]");
  require(finite(g.L_x_m) && g.L_x_m > 0 && g.L_x_m <= 100, "length", g.L_x_m, "(0, 100 m]");
  require(finite(m.G_Pa) && m.G_Pa > 0 && m.G_Pa < 1e13, "shear_modulus", m.G_Pa, "(0, 1e13 Pa)");
  require(finite(m.E_Pa) && m.E_Pa > 0 && m.E_Pa < 1e13, "young_modulus", m.E_Pa, "(0, 1e13 Pa)");
  require(finite(m.rho_kg_per_m3) && m.rho_kg_per_m3 > 0 && m.rho_kg_per_m3 < 1e6, "density",
          m.rho_kg_per_m3, "(0, 1e6 kg/m3)");
  require(finite(m.P_Pa) && m.P_Pa > 0 && m.P_Pa < 1e12, "pressure", m.P_Pa, "(0, 1e12 Pa)");
  require(finite(m.gamma_per_s) && m.gamma_per_s >= 0 && m.gamma_per_s < 1e12, "damping",
          m.gamma_per_s, "[0, 1e12 /s)");
  require(finite(m.v_m_per_s) && m.v_m_per_s > 0 && m.v_m_per_s < 1e3, "velocity", m.v_m_per_s,
          "(0, 1000 m/s)");
  require(finite(m.l_y_m) && m.l_y_m > 0 && m.l_y_m <= 100, "l_y", m.l_y_m, "(0, 100 m]");
  require(finite(m.l_z_m) && m.l_z_m > 0 && m.l_z_m <= 100, "l_z", m.l_z_m, "(0, 100 m]");
}

void validate_friction(const FrictionDistribution& f) {
  require(finite(f.mu_s_mean) && f.mu_s_mean > 0 && f.mu_s_mean <= 100, "mu_s", f.mu_s_mean,
          "(0, 100] for the mean");
  require(finite(f.mu_s_sd) && f.mu_s_sd >= 0 && f.mu_s_sd <= 100, "mu_s", f.mu_s_sd, "[0, 100] for the SD");
  require(finite(f.mu_d_mean) && f.mu_d_mean >= 0 && f.mu_d_mean <= 100, "mu_d", f.mu_d_mean,
          "[0, 100] for the mean");
  require(finite(f.mu_d_sd) && f.mu_d_sd >= 0 && f.mu_d_sd <= 100, "mu_d", f.mu_d_sd, "[0, 100] for the SD");
  // A single draw with mu_d > mu_s is the pair policy's business. A mean above mu_s's makes it
  // the rule, and either policy then discards one of the two inputs on most blocks: clip sets
  // mu_d = mu_s, keep raises the static threshold to mu_d (build_chain). Both leave a chain that
  // creeps at its thresholds with mu_d = mu_s, not the scene that was asked for, so it is refused.
  require(f.mu_d_mean <= f.mu_s_mean, "mu_d", f.mu_d_mean,
          "[0, mu_s mean = " + printed(f.mu_s_mean) +
              "] for the mean (kinetic friction above static friction has no stick-slip; "
              "mu_d = mu_s gives blocks that creep at their threshold)");
}

void validate_run_control(const RunControl& r) {
  require(finite(r.sample_dt_s) && r.sample_dt_s > 0 && r.sample_dt_s <= 10, "sample_dt",
          r.sample_dt_s, "(0, 10 s]");
  if (r.duration_s > 0)
    require(finite(r.duration_s) && r.duration_s <= 1e6, "duration", r.duration_s, "(0, 1e6 s]");
  else
    require(finite(r.duration_t0) && r.duration_t0 > 0 && r.duration_t0 <= 1e4, "duration",
            r.duration_t0, "(0, 1e4] t0");
  require(finite(r.tol) && r.tol >= 1e-14 && r.tol <= 1e-2, "tol", r.tol, "[1e-14, 1e-2]");
  require(finite(r.dt_s) && r.dt_s > 0 && r.dt_s <= 1, "dt", r.dt_s, "(0, 1 s]");
  require(r.modal_max_run >= 0 && r.modal_max_run <= 64, "modal_max_run", r.modal_max_run, "[0, 64]");
  require(r.modal_max_groove >= 0 && r.modal_max_groove <= kLongestModalGroove, "modal_max_groove",
          r.modal_max_groove, "[0, " + std::to_string(kLongestModalGroove) + "]");
  require(r.exact_max_run >= 1 && r.exact_max_run <= 512, "exact_max_run", r.exact_max_run, "[1, 512]");
}

// RK4's step against the chain's stability limit, with and without damping, and the run's length.
void validate_rk4_step(const Scene& s) {
  const auto& r = s.run;
  const ModeBand band = mode_band(s);
  const double h_max = band.h_undamped;
  if (r.dt_s > h_max)
    throw InputError("dt", "step " + printed(r.dt_s) + " s exceeds the RK4 stability limit of this chain; "
                           "the largest stable step is " + printed(h_max) +
                           " s (h * omega_max <= 2 sqrt 2, omega_max = sqrt((K_s + 4 K_int)/m), per block "
                           "the largest sqrt((K_s,i + 2 K_int,i-1 + 2 K_int,i)/m_i))");
  if (s.material.gamma_per_s > 0) {
    const double h_damped = rk4_damped_stable_dt(band, s.material.gamma_per_s);
    if (r.dt_s > h_damped)
      throw InputError("dt", "step " + printed(r.dt_s) + " s exceeds the RK4 stability limit with damping " +
                                 printed(s.material.gamma_per_s) + " /s; the largest stable step is " +
                                 printed(h_damped) + " s (overdamped modes need h * gamma <= 2.785)");
  }
  const double steps = s.duration() / r.dt_s;
  require(steps <= kMaxTimes, "dt", r.dt_s,
          "[duration / 1e13 = " + printed(s.duration() / kMaxTimes) + " s, ...) (at most 1e13 RK4 steps over the run; "
          "duration = " + printed(s.duration()) + " s): raise --dt or shorten --duration");
}

// Whether the run's times stay apart in double arithmetic. Samples come every sample_dt, RK4
// steps by dt (validate_rk4_step), and the exact methods by at most kExactStepRadians of the chain's
// fastest rate (omega_max, or the damping where it is larger: an overdamped mode's decay) where
// blocks move. More than 1e13 samples or such steps over the run would put consecutive times
// within ~450 round-offs of t (2^-52 duration), and below one they stop advancing: the run would
// never end. So both counts are bounded as RK4's steps are; a rate that overflowed (omega^2 = inf
// from a vanishing mass) fails the same test.
void validate_resolution(const Scene& s) {
  const double T = s.duration();
  // The duration is often a multiple of t0, which the velocity, the load or the stiffnesses set:
  // the message names both, since the field the user changed may be one of those.
  require(T / s.run.sample_dt_s <= kMaxTimes, "sample_dt", s.run.sample_dt_s,
          "[duration / 1e13 = " + printed(T / kMaxTimes) + " s, ...) (at most 1e13 samples over the run; duration = " +
              printed(T) + " s, t0 = " + printed(s.t0_s()) +
              " s from the velocity, load and stiffnesses): raise --sample-dt or shorten --duration");
  if (s.run.method == Method::RK4) return;
  const double rate = std::max(std::sqrt(mode_band(s).w2_hi), s.material.gamma_per_s);
  if (!(rate * T <= kExactStepRadians * kMaxTimes))
    throw InputError("duration", "the chain's fastest rate " + printed(rate) + " /s (omega_max, or the damping where larger) turns " +
                                     printed(rate * T) + " rad over the run's " + printed(T) +
                                     " s, and the exact methods step at most 0.75 rad at a time; the allowed range is at "
                                     "most 7.5e12 rad (1e13 steps, each above ~450 round-offs of t): shorten the "
                                     "duration, or give a chain with slower modes");
}

// The extraction rules, and whether the run can measure anything: runs that cannot are refused
// here rather than averaged over no samples. The loading phase ends at a sample after t = 0, and
// mu_d averages the samples after that one, from (first slip + mu_d_skip) on: a run needs at
// least two sampling intervals, and a window that opens before the end of the run. Whether the
// first slip itself comes before the end is known only after the run (springblock run exits 3 if
// it never does).
void validate_measurable(const Scene& s) {
  const auto& r = s.run;
  require(finite(s.rules.peak_drop) && s.rules.peak_drop > 0 && s.rules.peak_drop <= 1, "peak_drop",
          s.rules.peak_drop, "(0, 1]");
  require(finite(s.rules.peak_drop_fraction) && s.rules.peak_drop_fraction > 0 && s.rules.peak_drop_fraction < 1,
          "peak_drop_fraction", s.rules.peak_drop_fraction, "(0, 1)");
  require(finite(s.rules.peak_event_fraction) && s.rules.peak_event_fraction > 0 && s.rules.peak_event_fraction <= 1,
          "peak_event_fraction", s.rules.peak_event_fraction, "(0, 1]");
  require(finite(s.rules.mu_d_skip_t0) && s.rules.mu_d_skip_t0 >= 0 && s.rules.mu_d_skip_t0 <= 1e3,
          "mu_d_skip", s.rules.mu_d_skip_t0, "[0, 1000]");
  const double T = s.duration(), t0 = s.t0_s();
  if (r.stop_after_mu_s) {  // no mu_d window: one interval suffices
    require(r.sample_dt_s <= T, "sample_dt", r.sample_dt_s, "(0, duration = " + printed(T) + " s]");
  } else {
    require(2 * r.sample_dt_s <= T, "sample_dt", r.sample_dt_s,
            "(0, duration / 2 = " + printed(T / 2) + " s] (a sample at the first slip and one after it)");
    require(s.rules.mu_d_skip_t0 * t0 < T - r.sample_dt_s, "mu_d_skip", s.rules.mu_d_skip_t0,
            "[0, (duration - sample_dt) / t0 = " + printed((T - r.sample_dt_s) / t0) +
                ") in t0: the mu_d window must open before the end of the run (lower --mu-d-skip or "
                "lengthen --duration)");
  }
  for (double t : s.observe.stress_times_s)
    require(finite(t) && t >= 0 && t <= s.duration(), "stress_times", t,
            "[0, duration = " + printed(s.duration()) + " s]");
}

}  // namespace

// In dependency order: t0 and the duration need the material, friction, surface and per-block
// fields checked.
void validate(const Scene& s) {
  validate_material(s.material, s.geometry);
  validate_friction(s.friction);
  require(finite(s.k_int_scale) && s.k_int_scale >= 0 && s.k_int_scale <= 1e8, "k_int_scale",
          s.k_int_scale, "[0, 1e8]");
  require(s.reps >= 1, "reps", s.reps, "[1, 1000000]");
  // The surface is checked here once; each repetition then builds its mask without checks.
  validate_surface(s.pattern, s.geometry.N);
  validate_materials(s);
  validate_run_control(s.run);
  if (s.run.method == Method::RK4) validate_rk4_step(s);
  validate_resolution(s);
  validate_measurable(s);
}

}  // namespace sb
