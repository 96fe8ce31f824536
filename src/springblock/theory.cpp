// Closed-form single-block stick-slip cycle and its Gaussian average.
//
// Notation used throughout: A = (mu_s - mu_d) F_n / k is the amplitude of the free oscillation
// about the sliding equilibrium, so the spring extension e = v t + r0 - x starts at r0 = mu_s F_n/k
// and the sliding equilibrium sits at mu_d F_n/k, i.e. A below the onset.
#include "springblock/theory.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace sb::theory {
namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("sb::theory: ") + what);
}

void validate_block(const SingleBlock& b) {
  require(std::isfinite(b.m_kg) && b.m_kg > 0.0, "mass must be finite and > 0");
  require(std::isfinite(b.k_N_per_m) && b.k_N_per_m > 0.0, "stiffness must be finite and > 0");
  require(std::isfinite(b.v_m_per_s) && b.v_m_per_s > 0.0, "slider velocity must be finite and > 0");
  require(std::isfinite(b.F_n_N) && b.F_n_N > 0.0, "normal force must be finite and > 0");
}

void validate(const SingleBlock& b, double mu_s, double mu_d) {
  validate_block(b);
  require(std::isfinite(mu_s) && mu_s > 0.0, "mu_s must be finite and > 0");
  require(std::isfinite(mu_d) && mu_d >= 0.0, "mu_d must be finite and >= 0");
  require(mu_d <= mu_s, "mu_d must not exceed mu_s");
}

// omega t - sin(omega t) loses all its digits to cancellation for small arguments, which is
// exactly where the slip starts; the Taylor series keeps x(t) accurate near t = 0.
double theta_minus_sin(double th) {
  if (std::abs(th) < 1e-2) {
    const double t2 = th * th;
    return th * t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0)));
  }
  return th - std::sin(th);
}

// 1 - cos written as 2 sin^2(th/2) for the same reason (no cancellation near 0).
double one_minus_cos(double th) {
  const double s = std::sin(0.5 * th);
  return 2.0 * s * s;
}

// Duration of sliding. The velocity v(1-cos) + A omega sin factors as
// 2 sin(th/2) [v sin(th/2) + A omega cos(th/2)], so the first positive zero has
// tan(th/2) = -A omega / v with th/2 in (pi/2, pi]. atan2 instead of atan(ratio) keeps this finite
// when v is so small that A omega / v overflows.
double sliding_time(double omega, double A, double v) {
  return 2.0 / omega * (std::numbers::pi - std::atan2(A * omega, v));
}

// Fraction of the cycle spent sticking, T_s / (T_d + T_s). Written as 1 / (1 + T_d / T_s) with
// T_d / T_s = T_d v / (2 A) so that a vanishing v (T_s -> inf) gives 1 instead of inf/inf.
double static_fraction(double omega, double A, double v) {
  if (A <= 0.0) return 0.0;
  const double Td = sliding_time(omega, A, v);
  return 1.0 / (1.0 + Td * v / (2.0 * A));
}

// Eq. (9) without validation: the hot path of the Gaussian quadrature.
double mu_d_macro_unchecked(const SingleBlock& b, double mu_s, double mu_d) {
  // With 2 mu_d >= mu_s the spring never goes into compression while sticking, so the mean
  // static force equals mu_d F_n and the sliding and sticking phases carry the same force.
  if (2.0 * mu_d >= mu_s) return mu_d;
  const double omega = std::sqrt(b.k_N_per_m / b.m_kg);
  const double A = (mu_s - mu_d) * b.F_n_N / b.k_N_per_m;
  const double fs = static_fraction(omega, A, b.v_m_per_s);
  const double d = mu_s - 2.0 * mu_d;
  return mu_d + fs * d * d / (2.0 * (mu_s - mu_d));
}

// ---------------------------------------------------------------------------------------------
// Gaussian average.

// Normal law N(mean, sd) restricted to [0, inf) and renormalised (rejection of negative draws).
struct TruncNormal {
  double mean, sd;
  double log_norm = 0.0;  // log(sd sqrt(2 pi) P(X >= 0)), kept as a log for far-negative means
  double lo = 0.0, hi = 0.0;  // integration window: the truncation at 0 or mean - 9 sd, mean + 9 sd

  TruncNormal(double m, double s) : mean(m), sd(s) {
    if (sd == 0.0) return;
    const double mass = gsl_cdf_ugaussian_Q(-mean / sd);
    require(mass > 0.0, "Gaussian truncated at 0 retains no probability (mean far below 0)");
    log_norm = std::log(sd * std::sqrt(2.0 * std::numbers::pi) * mass);
    lo = std::max(0.0, mean - 9.0 * sd);
    // For a negative mean the density decays away from 0; 9 sd past the larger of (mean, 0)
    // still leaves a neglected tail below exp(-40) of the peak.
    hi = std::max(mean, 0.0) + 9.0 * sd;
  }
  double pdf(double x) const {
    const double z = (x - mean) / sd;
    return std::exp(-0.5 * z * z - log_norm);
  }
};

// GSL's default handler aborts the process; a library must report failure instead. The handler
// is process-global, so this guard is not thread-safe, which is acceptable for analysis code.
class GslHandlerOff {
 public:
  GslHandlerOff() : old_(gsl_set_error_handler_off()) {}
  ~GslHandlerOff() { gsl_set_error_handler(old_); }
  GslHandlerOff(const GslHandlerOff&) = delete;
  GslHandlerOff& operator=(const GslHandlerOff&) = delete;

 private:
  gsl_error_handler_t* old_;
};

struct WorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using Workspace = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;
constexpr std::size_t kLimit = 1000;

Workspace make_workspace() {
  Workspace w(gsl_integration_workspace_alloc(kLimit));
  if (!w) throw std::runtime_error("sb::theory: cannot allocate GSL integration workspace");
  return w;
}

// Status of the first failure seen anywhere in the nested quadrature. Exceptions must not cross
// GSL's C frames, so integrands record errors here and return 0; the caller throws afterwards.
struct Failure {
  int status = GSL_SUCCESS;
  std::string where;
  void note(int s, const char* w) {
    if (status == GSL_SUCCESS && s != GSL_SUCCESS) {
      status = s;
      where = w;
    }
  }
};

// Integrates f over [lo, hi] with qagp, splitting at the interior `breaks` where f has a kink or
// a steep feature; on each piece f is then smooth and Gauss-Kronrod converges fast.
template <class F>
double integrate(F& f, double lo, double hi, std::vector<double> breaks, double epsabs,
                 double epsrel, gsl_integration_workspace* w, Failure& fail, const char* where) {
  std::vector<double> pts{lo};
  std::sort(breaks.begin(), breaks.end());
  for (double p : breaks)
    if (p > pts.back() && p < hi) pts.push_back(p);
  pts.push_back(hi);

  gsl_function gf;
  gf.function = [](double x, void* p) -> double { return (*static_cast<F*>(p))(x); };
  gf.params = &f;
  double result = 0.0, abserr = 0.0;
  const int status = gsl_integration_qagp(&gf, pts.data(), pts.size(), epsabs, epsrel, kLimit, w,
                                          &result, &abserr);
  fail.note(status, where);
  return result;
}

}  // namespace

double x_sliding(const SingleBlock& b, double mu_s, double mu_d, double t_s) {
  validate(b, mu_s, mu_d);
  require(std::isfinite(t_s), "time must be finite");
  const double omega = std::sqrt(b.k_N_per_m / b.m_kg);
  const double A = (mu_s - mu_d) * b.F_n_N / b.k_N_per_m;
  const double th = omega * t_s;
  return b.v_m_per_s / omega * theta_minus_sin(th) + A * one_minus_cos(th);
}

double xdot_sliding(const SingleBlock& b, double mu_s, double mu_d, double t_s) {
  validate(b, mu_s, mu_d);
  require(std::isfinite(t_s), "time must be finite");
  const double omega = std::sqrt(b.k_N_per_m / b.m_kg);
  const double A = (mu_s - mu_d) * b.F_n_N / b.k_N_per_m;
  const double th = omega * t_s;
  return b.v_m_per_s * one_minus_cos(th) + A * omega * std::sin(th);
}

SingleBlockCycle cycle(const SingleBlock& b, double mu_s, double mu_d) {
  validate(b, mu_s, mu_d);
  const double Fk = b.F_n_N / b.k_N_per_m;  // force-to-length scale of the spring
  const double v = b.v_m_per_s;
  SingleBlockCycle c{};
  c.omega = std::sqrt(b.k_N_per_m / b.m_kg);
  c.r0_m = mu_s * Fk;
  const double A = (mu_s - mu_d) * Fk;
  c.T_d_s = sliding_time(c.omega, A, v);
  // At the stop the block has advanced exactly 2A more than the slider (see the factorisation in
  // sliding_time), so the extension there is r0 - 2A = (2 mu_d - mu_s) F_n / k.
  c.delta_r_m = (mu_s - 2.0 * mu_d) * Fk;
  // Sticking lasts until the slider has restored the extension from r0 - 2A back to r0.
  c.T_s_s = 2.0 * A / v;
  // Mean of |extension| while it grows linearly from e0 = 2 mu_d - mu_s to e1 = mu_s (units F_n/k):
  // the plain midpoint mu_d if e0 >= 0, else the |.|-weighted (e0^2 + e1^2) / (2 (e1 - e0)).
  if (2.0 * mu_d >= mu_s) {
    c.F_stat_mean_over_Fn = mu_d;
  } else {
    const double e0 = mu_s - 2.0 * mu_d;  // magnitude of the compression at the stop
    c.F_stat_mean_over_Fn = (e0 * e0 + mu_s * mu_s) / (4.0 * (mu_s - mu_d));
  }
  // Eq. (7) reduces to eq. (9) because <F_stat>/F_n - mu_d = (mu_s - 2 mu_d)^2 / (2 (mu_s - mu_d))
  // in the lower regime; the shared helper keeps cycle() bit-identical to the point values
  // used inside the Gaussian average.
  c.mu_d_macro = mu_d_macro_unchecked(b, mu_s, mu_d);
  return c;
}

double mu_d_macro_gaussian(const SingleBlock& b, double mean_s, double sd_s, double mean_d,
                           double sd_d, double rel_tol) {
  validate_block(b);
  require(std::isfinite(mean_s) && std::isfinite(mean_d), "means must be finite");
  require(std::isfinite(sd_s) && sd_s >= 0.0, "sd_s must be finite and >= 0");
  require(std::isfinite(sd_d) && sd_d >= 0.0, "sd_d must be finite and >= 0");
  require(std::isfinite(rel_tol) && rel_tol > 0.0, "rel_tol must be finite and > 0");
  if (sd_s == 0.0) require(mean_s > 0.0, "mean_s must be > 0 when sd_s = 0");
  if (sd_d == 0.0) require(mean_d >= 0.0, "mean_d must be >= 0 when sd_d = 0");

  // The draw policy: kinetic friction is clipped to the static one.
  auto point = [&b](double ms, double md) { return mu_d_macro_unchecked(b, ms, std::min(md, ms)); };
  if (sd_s == 0.0 && sd_d == 0.0) return point(mean_s, mean_d);

  const TruncNormal ps(mean_s, sd_s), pd(mean_d, sd_d);
  // The result is bounded by E[mu_s]; an absolute floor of this size keeps GSL from chasing
  // relative accuracy on pieces that are pure far-tail (value ~1e-20) and hitting round-off.
  const double scale = std::max(std::abs(mean_s), sd_s);
  const double epsabs = 1e-3 * rel_tol * scale;
  // Inner integrals are tightened so their errors do not spoil the outer estimate.
  const double rel_in = 0.1 * rel_tol, abs_in = 0.1 * epsabs;

  GslHandlerOff guard;
  Failure fail;
  Workspace w_out = make_workspace();
  double result = 0.0;

  if (sd_s == 0.0) {
    // Only mu_d spreads: kinks at mu_s/2 (regime change) and mu_s (clip).
    auto f = [&](double md) { return pd.pdf(md) * point(mean_s, md); };
    result = integrate(f, pd.lo, pd.hi, {0.5 * mean_s, mean_s}, epsabs, rel_tol, w_out.get(), fail,
                       "1-D average over mu_d");
  } else if (sd_d == 0.0) {
    // Only mu_s spreads: the same two kinks seen from the other axis, at 2 mu_d and mu_d.
    auto f = [&](double ms) { return ps.pdf(ms) * point(ms, mean_d); };
    result = integrate(f, ps.lo, ps.hi, {mean_d, 2.0 * mean_d}, epsabs, rel_tol, w_out.get(), fail,
                       "1-D average over mu_s");
  } else {
    Workspace w_in = make_workspace();
    // Inner: average over mu_d at fixed mu_s, split at its two kinks.
    auto inner_f = [&](double ms) {
      auto g = [&](double md) { return pd.pdf(md) * point(ms, md); };
      return ps.pdf(ms) * integrate(g, pd.lo, pd.hi, {0.5 * ms, ms}, abs_in, rel_in, w_in.get(),
                                    fail, "inner average over mu_d");
    };
    // Outer: the inner result varies on the scale sd_d where the kinks sweep through the bulk
    // of the mu_d law, i.e. near mu_s = mean_d and mu_s = 2 mean_d; split there too.
    result = integrate(inner_f, ps.lo, ps.hi, {mean_d, 2.0 * mean_d}, epsabs, rel_tol, w_out.get(),
                       fail, "outer average over mu_s");
  }

  if (fail.status != GSL_SUCCESS)
    throw std::runtime_error("sb::theory::mu_d_macro_gaussian: GSL quadrature failed in " +
                             fail.where + ": " + gsl_strerror(fail.status));
  if (!std::isfinite(result))
    throw std::runtime_error("sb::theory::mu_d_macro_gaussian: non-finite quadrature result");
  return result;
}

}  // namespace sb::theory
