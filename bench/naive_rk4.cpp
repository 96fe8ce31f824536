#include "naive_rk4.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace sb::bench {
namespace {

// The chain's constants, read once into locals: the force loops write doubles through pointers,
// which the compiler cannot prove leave a Chain's members alone.
struct Coefficients {
  int N;
  double K_s, K_int, m, m_gamma;
};

// Net non-friction force on block i (slider spring, internal springs, damping), the slider at
// x_slider. Free chain ends: the end blocks have one neighbour.
inline double net_force(const Coefficients& k, const double* u, const double* v, int i, double x_slider) {
  double f = k.K_s * (x_slider - u[i]) - k.m_gamma * v[i];
  if (i > 0) f += k.K_int * (u[i - 1] - u[i]);
  if (i + 1 < k.N) f += k.K_int * (u[i + 1] - u[i]);
  return f;
}

// The right-hand side at (u, v, t) with the phases `dir` frozen, into (du, dv): a stuck contact
// block has neither velocity nor acceleration, a sliding one feels its kinetic friction against
// its direction, a groove block no friction.
void derivative(const Coefficients& k, const std::uint8_t* contact, const double* f_kinetic,
                const std::int8_t* dir, const double* u, const double* v, double t, double v_slider, double* du,
                double* dv) {
  const double x_slider = v_slider * t;
  for (int i = 0; i < k.N; ++i) {
    if (contact[i] && dir[i] == 0) {
      du[i] = 0.0;
      dv[i] = 0.0;
      continue;
    }
    double f = net_force(k, u, v, i, x_slider);
    if (contact[i]) f -= dir[i] * f_kinetic[i];
    du[i] = v[i];
    dv[i] = f / k.m;  // a division, as the scheme is written: multiplying by 1/m rounds differently
  }
}

// The switching decisions at a step end, in block order, on the state in place.
void switches(const Coefficients& k, const Chain& c, const double* u, double* v, std::int8_t* dir, double t,
              State& s) {
  const double x_slider = c.v_slider * t;
  for (int i = 0; i < k.N; ++i) {
    if (!c.contact[i]) continue;
    if (dir[i] != 0 && v[i] * dir[i] <= 0.0) {
      v[i] = 0.0;
      dir[i] = 0;
      ++s.switches;
    }
    if (dir[i] == 0) {
      const double F = net_force(k, u, v, i, x_slider);
      if (std::fabs(F) > c.f_static[i]) {
        dir[i] = F > 0 ? 1 : -1;
        ++s.switches;
      }
    }
  }
}

}  // namespace

void NaiveRk4::run(const Chain& c, State& s, double t_end) const {
  const Coefficients k{c.N, c.K_s, c.K_int, c.m, c.m * c.gamma};
  const std::size_t N = static_cast<std::size_t>(c.N);
  // The state is stepped in place in s; the stage state (us, vs), the current stage's
  // derivative (ku, kv) and the weighted sum k1 + 2 k2 + 2 k3 + k4 (su, sv) are allocated here,
  // once per run.
  std::vector<double> us(N), vs(N), ku(N), kv(N), su(N), sv(N);
  double* u = s.u.data();
  double* v = s.v.data();
  std::int8_t* dir = s.dir.data();
  const std::uint8_t* contact = c.contact.data();
  const double* f_kinetic = c.f_kinetic.data();
  const double h = h_, h2 = h / 2, h6 = h / 6, vs_slider = c.v_slider;

  const std::int64_t n_end = std::llround(t_end / h);
  std::int64_t n = std::llround(s.t / h);
  switches(k, c, u, v, dir, n * h, s);
  while (n < n_end) {
    const double t = n * h;
    derivative(k, contact, f_kinetic, dir, u, v, t, vs_slider, ku.data(), kv.data());
    for (std::size_t i = 0; i < N; ++i) {
      su[i] = ku[i];
      sv[i] = kv[i];
      us[i] = u[i] + h2 * ku[i];
      vs[i] = v[i] + h2 * kv[i];
    }
    for (const double step : {h2, h}) {  // stages 2 and 3: slopes at t + h/2, weight 2
      derivative(k, contact, f_kinetic, dir, us.data(), vs.data(), t + h2, vs_slider, ku.data(), kv.data());
      for (std::size_t i = 0; i < N; ++i) {
        su[i] += 2 * ku[i];
        sv[i] += 2 * kv[i];
        us[i] = u[i] + step * ku[i];
        vs[i] = v[i] + step * kv[i];
      }
    }
    derivative(k, contact, f_kinetic, dir, us.data(), vs.data(), t + h, vs_slider, ku.data(), kv.data());
    for (std::size_t i = 0; i < N; ++i) {
      u[i] += h6 * (su[i] + ku[i]);
      v[i] += h6 * (sv[i] + kv[i]);
    }
    ++n;
    ++s.steps;
    s.rhs_evals += 4;
    switches(k, c, u, v, dir, n * h, s);
  }
  s.t = n * h;
}

}  // namespace sb::bench
