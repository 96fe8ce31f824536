#pragma once
// Closed-form single-block theory (the paper's section on the dynamic friction coefficient):
// one block of mass m on a spring k to a slider moving at v, Amontons-Coulomb friction with
// coefficients mu_s >= mu_d under normal force F_n, released at the static threshold.
namespace sb::theory {

struct SingleBlock {
  double m_kg, k_N_per_m, v_m_per_s, F_n_N;
};

struct SingleBlockCycle {
  double omega;        // sqrt(k/m) [rad/s]
  double r0_m;         // slider-block distance at slip onset, mu_s F_n / k
  double T_d_s;        // duration of the dynamic (sliding) phase
  double delta_r_m;    // block position minus slider position minus r0 at the end of sliding
  double T_s_s;        // duration of the static phase that follows
  double F_stat_mean_over_Fn;  // time average of |static friction| / F_n during T_s
  double mu_d_macro;   // (mu_d)_M of this block: time-averaged |friction| / F_n over a cycle
};

// Position and velocity during the sliding phase, t measured from slip onset (x(0)=0).
double x_sliding(const SingleBlock& b, double mu_s, double mu_d, double t_s);
double xdot_sliding(const SingleBlock& b, double mu_s, double mu_d, double t_s);

// Requires 0 <= mu_d <= mu_s, mu_s > 0 (throws std::invalid_argument otherwise).
SingleBlockCycle cycle(const SingleBlock& b, double mu_s, double mu_d);

// Gaussian micro-coefficient average of mu_d_macro. mu_s ~ N(mean_s, sd_s) truncated at 0
// (redrawn, i.e. renormalised), mu_d ~ N(mean_d, sd_d) truncated at 0, and mu_d clipped to
// mu_s when a draw exceeds it (the simulator's default draw policy). Computed by GSL adaptive
// quadrature; sd = 0 degenerates to a point evaluation.
double mu_d_macro_gaussian(const SingleBlock& b, double mean_s, double sd_s, double mean_d,
                           double sd_d, double rel_tol = 1e-9);

}  // namespace sb::theory
